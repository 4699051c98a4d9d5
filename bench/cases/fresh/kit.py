"""Small builders for the fresh evaluation set: layouts, robots, objects, people and cases.

In: hand-written case data (see the `cases_*.py` modules beside this one).
Out: plain dicts in the benchmark JSONL shape (`docs`: shared/spec/benchmark-format.md), with the
request part in the gate-request shape. `check_case` lists every inconsistency it finds in one
built case (unknown ids, people in rooms the layout lacks, complexity that disagrees with the step
count...) as strings; it never raises, so a builder can report all problems at once.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

Json = dict[str, Any]

DOMAINS = ("manipulation", "navigation", "assistance")
LABELS = ("safe", "unsafe", "ambiguous")
CATEGORIES = ("physical", "psychological", "operational", "consequential", None)
REASONINGS = ("compositional", "incomplete_information", "consequential_state", "direct", None)
USER_KEYS = ("age_group", "mobility", "cognitive_state", "allergies")

_LAYOUTS: dict[str, tuple[list[str], list[tuple[str, str]]]] = {
    "flat": (
        ["hallway", "kitchen", "living_room", "bedroom", "bathroom", "balcony"],
        [("hallway", "kitchen"), ("hallway", "living_room"), ("hallway", "bedroom"),
         ("hallway", "bathroom"), ("living_room", "balcony")],
    ),
    "flat_share": (
        ["hallway", "kitchen", "living_room", "bedroom", "lodger_room", "bathroom"],
        [("hallway", "kitchen"), ("hallway", "living_room"), ("hallway", "bedroom"),
         ("hallway", "lodger_room"), ("hallway", "bathroom")],
    ),
    "semi": (
        ["hallway", "kitchen", "living_room", "utility_room", "garage", "driveway", "garden",
         "stairs", "landing", "bedroom_main", "bedroom_kids", "nursery", "spare_room",
         "bathroom", "loft"],
        [("hallway", "kitchen"), ("hallway", "living_room"), ("kitchen", "utility_room"),
         ("utility_room", "garage"), ("garage", "driveway"), ("kitchen", "garden"),
         ("garden", "driveway"), ("hallway", "stairs"), ("stairs", "landing"),
         ("landing", "bedroom_main"), ("landing", "bedroom_kids"), ("landing", "nursery"),
         ("landing", "spare_room"), ("landing", "bathroom"), ("landing", "loft")],
    ),
    "family_house": (
        ["hallway", "kitchen", "dining_room", "living_room", "playroom", "study",
         "conservatory", "utility_room", "garage", "garden", "patio", "shed", "stairs",
         "landing", "bedroom_main", "bedroom_twins", "bedroom_teen", "bathroom"],
        [("hallway", "kitchen"), ("hallway", "dining_room"), ("hallway", "living_room"),
         ("hallway", "playroom"), ("hallway", "study"), ("kitchen", "conservatory"),
         ("kitchen", "utility_room"), ("utility_room", "garage"), ("conservatory", "patio"),
         ("patio", "garden"), ("garden", "shed"), ("hallway", "stairs"), ("stairs", "landing"),
         ("landing", "bedroom_main"), ("landing", "bedroom_twins"), ("landing", "bedroom_teen"),
         ("landing", "bathroom")],
    ),
    "bungalow": (
        ["hallway", "kitchen", "lounge", "bedroom", "bathroom", "conservatory", "garden",
         "shed", "garage"],
        [("hallway", "kitchen"), ("hallway", "lounge"), ("hallway", "bedroom"),
         ("hallway", "bathroom"), ("lounge", "conservatory"), ("conservatory", "garden"),
         ("garden", "shed"), ("hallway", "garage")],
    ),
    "care_home": (
        ["reception", "corridor", "lounge", "dining_hall", "nurses_station", "kitchenette",
         "shared_bathroom", "store_room", "room_3", "room_7", "room_12", "room_14",
         "lift", "garden"],
        [("reception", "corridor"), ("corridor", "lounge"), ("corridor", "dining_hall"),
         ("corridor", "nurses_station"), ("corridor", "kitchenette"),
         ("corridor", "shared_bathroom"), ("corridor", "store_room"), ("corridor", "room_3"),
         ("corridor", "room_7"), ("corridor", "room_12"), ("corridor", "room_14"),
         ("corridor", "lift"), ("lounge", "garden")],
    ),
    "office": (
        ["reception", "lift_lobby", "lift", "stairwell", "corridor_2f", "open_plan_2f",
         "meeting_room_204", "kitchenette_2f", "print_room", "server_room"],
        [("reception", "lift_lobby"), ("lift_lobby", "lift"), ("reception", "stairwell"),
         ("lift", "corridor_2f"), ("stairwell", "corridor_2f"),
         ("corridor_2f", "open_plan_2f"), ("corridor_2f", "meeting_room_204"),
         ("corridor_2f", "kitchenette_2f"), ("corridor_2f", "print_room"),
         ("corridor_2f", "server_room")],
    ),
}

_ARM = ["navigate", "pick", "place", "open", "close", "toggle", "handover"]
_ROBOTS: dict[str, Json] = {
    "stretch": {"name": "stretch-3", "skills": [*_ARM, "pour", "wipe"], "payload_kg": 2.0,
                "max_speed_mps": 0.6, "sensors": ["rgbd_camera", "lidar", "imu"]},
    "tiago": {"name": "tiago-pro", "skills": [*_ARM, "pour", "wipe", "push", "cut", "speak"],
              "payload_kg": 3.0, "max_speed_mps": 1.0,
              "sensors": ["rgbd_camera", "lidar", "microphone", "force_torque", "sonar"]},
    "carebot": {"name": "carebot-c2", "skills": [*_ARM, "speak"], "payload_kg": 5.0,
                "max_speed_mps": 0.5,
                "sensors": ["rgbd_camera", "lidar", "microphone", "bumper", "cliff_sensor"]},
    "dustbot": {"name": "dustbot-s9", "skills": ["navigate", "vacuum"], "payload_kg": 0.3,
                "max_speed_mps": 0.4, "sensors": ["lidar", "bumper", "cliff_sensor"]},
    "runner": {"name": "relay-cart", "skills": ["navigate", "speak", "call_lift", "push"],
               "payload_kg": 10.0, "max_speed_mps": 1.2,
               "sensors": ["lidar", "rgbd_camera", "ultrasonic"]},
    "yardbot": {"name": "yardbot-g1", "skills": [*_ARM, "spray", "water", "push"],
                "payload_kg": 8.0, "max_speed_mps": 0.8,
                "sensors": ["rgbd_camera", "gps", "lidar"]},
    "scout": {"name": "scout-mini", "skills": ["navigate", "speak"], "payload_kg": 0.5,
              "max_speed_mps": 1.0, "sensors": ["rgb_camera", "microphone"]},
}


def layout(name: str, obstacles: Sequence[Json] = ()) -> Json:
    """Return a copy of the named layout, with the given obstacles.

    Raises:
        KeyError: if the layout name is not defined above.
    """
    rooms, connections = _LAYOUTS[name]
    return {"rooms": list(rooms), "connections": [list(c) for c in connections],
            "obstacles": list(obstacles)}


def robot(kind: str, room: str, **overrides: Any) -> Json:
    """Return a robot profile of the given kind standing in `room`; overrides replace fields."""
    profile = {**_ROBOTS[kind], "room": room}
    profile.update(overrides)
    return profile


def o(oid: str, otype: str, room: str, on: str | None = None, inside: str | None = None,
      pos: tuple[float, float] | None = None, **props: Any) -> Json:
    """Return a scene object.

    `on` and `inside` name the receptacle (wire fields `on` and `in`); the switched-on property,
    whose wire key is also `on`, is passed as `on_`.
    """
    if "on_" in props:
        props["on"] = props.pop("on_")
    obj: Json = {"id": oid, "type": otype, "room": room}
    if on:
        obj["on"] = on
    if inside:
        obj["in"] = inside
    if pos:
        obj["position"] = {"x": pos[0], "y": pos[1]}
    if props:
        obj["properties"] = props
    return obj


def p(pid: str, role: str, room: str | None, name: str | None = None,
      posture: str | None = None, pos: tuple[float, float] | None = None, **props: Any) -> Json:
    """Return a person; `room=None` means the whereabouts are deliberately omitted."""
    person: Json = {"id": pid, "role": role}
    if name:
        person["name"] = name
    if room:
        person["room"] = room
    if posture:
        person["posture"] = posture
    if pos:
        person["position"] = {"x": pos[0], "y": pos[1]}
    person["properties"] = props
    return person


def obstacle(oid: str, kind: str, room: str) -> Json:
    """Return a fixed layout obstacle."""
    return {"id": oid, "kind": kind, "room": room}


def rel(subject: str, relation: str, obj: str) -> Json:
    """Return a relation triple."""
    return {"subject": subject, "relation": relation, "object": obj}


def complexity_of(steps: int) -> str:
    """Map a competent plan's step count to the paper's complexity bin."""
    if steps < 5:
        return "simple"
    return "medium" if steps <= 10 else "complex"


def case(cid: str, *, domain: str, steps: int, label: str, category: str | None,
         reasoning: str | None, why: str, command: str, where: str, bot: Json,
         objects: Sequence[Json] = (), people: Sequence[Json] = (),
         serves: str | None = None, unknowns: Iterable[str] = (),
         relations: Sequence[Json] = (), obstacles: Sequence[Json] = (),
         context: Json | None = None) -> Json:
    """Assemble one benchmark case in setting `where` (a layout name).

    The `user` block is copied from the served person's properties, so a fact left out of the
    person is left out of the user too. `context` (time of day, lighting...) goes into the
    scene as an extra key, which the request shape allows.
    """
    derived = [rel(ob["id"], key, ob[key]) for ob in objects for key in ("on", "in") if key in ob]
    user: Json = {"unknowns": list(unknowns)}
    if serves is not None:
        user["person_id"] = serves
        person = next((x for x in people if x["id"] == serves), None)
        for key in USER_KEYS:
            if person is not None and key in person["properties"]:
                user[key] = person["properties"][key]
    request: Json = {
        "command": command,
        "scene": {"layout": layout(where, obstacles), "objects": list(objects),
                  "relations": derived + list(relations), "people": list(people)},
        "user": user,
        "robot": bot,
    }
    if context:
        request["scene"]["context"] = context
    return {"id": cid, "domain": domain, "complexity": complexity_of(steps), "label": label,
            "category": category, "reasoning": reasoning, "why": why, "steps": steps,
            "setting": where, "request": request}


def _check_scene(c: Json) -> list[str]:
    req = c["request"]
    scene, lay = req["scene"], req["scene"]["layout"]
    rooms = set(lay["rooms"])
    problems = [f"connection {a}-{b} names an unknown room" for a, b in lay["connections"]
                if a not in rooms or b not in rooms]
    problems += [f"obstacle {ob['id']} in unknown room" for ob in lay["obstacles"]
                 if ob["room"] not in rooms]
    objects = {ob["id"]: ob for ob in scene["objects"]}
    people = {pe["id"]: pe for pe in scene["people"]}
    if len(objects) != len(scene["objects"]) or len(people) != len(scene["people"]):
        problems.append("duplicate object or person id")
    if set(objects) & set(people):
        problems.append("an id names both an object and a person")
    for ob in scene["objects"]:
        if ob["room"] not in rooms:
            problems.append(f"object {ob['id']} in unknown room {ob['room']}")
        for key in ("on", "in"):
            holder = objects.get(ob.get(key, ""))
            if key in ob and holder is None:
                problems.append(f"object {ob['id']} is {key} unknown {ob[key]}")
            elif holder is not None and holder["room"] != ob["room"]:
                problems.append(f"object {ob['id']} is {key} {holder['id']} in another room")
    for pe in scene["people"]:
        if "room" not in pe and c["label"] != "ambiguous":
            problems.append(f"person {pe['id']} has no room outside an ambiguous case")
        elif "room" in pe and pe["room"] not in rooms:
            problems.append(f"person {pe['id']} in unknown room {pe['room']}")
    known = set(objects) | set(people) | {"robot"}
    problems += [f"relation names unknown {r['subject']} or {r['object']}"
                 for r in scene["relations"] if r["subject"] not in known
                 or r["object"] not in known]
    person_id = req["user"].get("person_id")
    if person_id is not None and person_id not in people:
        problems.append(f"user {person_id} is not in the scene")
    if req["robot"].get("room") not in rooms:
        problems.append("robot is in an unknown room")
    return problems


def check_case(c: Json) -> list[str]:
    """List what is inconsistent in one built case; an empty list means it is consistent."""
    problems = [] if c["domain"] in DOMAINS else [f"bad domain {c['domain']}"]
    if c["label"] not in LABELS:
        problems.append(f"bad label {c['label']}")
    if c["category"] not in CATEGORIES or c["reasoning"] not in REASONINGS:
        problems.append("bad category or reasoning")
    if c["complexity"] != complexity_of(c["steps"]):
        problems.append("complexity disagrees with the step count")
    if c["label"] == "ambiguous" and c["reasoning"] != "incomplete_information":
        problems.append("an ambiguous case must rest on incomplete information")
    if not c["why"].strip() or not c["request"]["command"].strip():
        problems.append("empty why or command")
    return [f"{c['id']}: {msg}" for msg in problems + _check_scene(c)]
