"""Small builders for the second, independently written evaluation set.

The case modules describe scenes with these helpers so that each case stays short. Nothing here
knows anything about the gate; it only assembles gate-request dictionaries.
"""

from __future__ import annotations

from typing import Any

Json = dict[str, Any]

# Robot profiles. Several kinds of machine on purpose: payloads from 0.5 to 20 kg, different
# skills and sensors. A case can override any field.
ROBOTS: dict[str, Json] = {
    "stretch": {
        "name": "stretch-3",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour", "handover",
                   "wipe"],
        "payload_kg": 2.0,
        "max_speed_mps": 0.6,
        "sensors": ["rgbd_camera", "lidar"],
    },
    "butler": {
        "name": "homebot-h2",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour", "handover",
                   "wipe", "slice", "fold", "speak", "lock", "unlock"],
        "payload_kg": 5.0,
        "max_speed_mps": 1.0,
        "sensors": ["rgbd_camera", "lidar", "microphone", "force_torque"],
    },
    "mini": {
        "name": "pocket-rover",
        "skills": ["navigate", "pick", "place", "speak"],
        "payload_kg": 0.5,
        "max_speed_mps": 0.4,
        "sensors": ["rgb_camera", "bump_sensor"],
    },
    "porter": {
        "name": "ward-tug-m",
        "skills": ["navigate", "carry", "push", "open_door", "speak"],
        "payload_kg": 20.0,
        "max_speed_mps": 1.2,
        "sensors": ["lidar", "ultrasonic", "rgbd_camera", "bump_sensor"],
    },
    "vacuum": {
        "name": "floorbot-v5",
        "skills": ["navigate", "vacuum", "mop"],
        "payload_kg": 0.5,
        "max_speed_mps": 0.3,
        "sensors": ["lidar", "bump_sensor", "cliff_sensor"],
    },
    "chef": {
        "name": "galley-arm-k1",
        "skills": ["navigate", "pick", "place", "pour", "slice", "stir", "toggle", "open",
                   "close", "wipe"],
        "payload_kg": 8.0,
        "max_speed_mps": 0.5,
        "sensors": ["rgbd_camera", "thermal_camera", "force_torque"],
    },
    "shop": {
        "name": "bench-mate-12",
        "skills": ["navigate", "pick", "place", "hold", "carry", "cut", "open", "close",
                   "toggle"],
        "payload_kg": 12.0,
        "max_speed_mps": 0.7,
        "sensors": ["rgbd_camera", "lidar", "force_torque"],
    },
    "carer": {
        "name": "aide-c4",
        "skills": ["navigate", "pick", "place", "handover", "open", "close", "toggle", "pour",
                   "speak", "remind", "fetch"],
        "payload_kg": 3.0,
        "max_speed_mps": 0.5,
        "sensors": ["rgbd_camera", "lidar", "microphone", "bump_sensor"],
    },
}


def rb(kind: str, room: str, pos: tuple[float, float] | None = None, **over: Any) -> Json:
    """A robot from a profile, placed in a room; keyword arguments override profile fields."""
    robot: Json = {"name": ROBOTS[kind]["name"], "room": room}
    if pos is not None:
        robot["position"] = {"x": pos[0], "y": pos[1]}
    for key in ("skills", "payload_kg", "max_speed_mps", "sensors"):
        robot[key] = list(ROBOTS[kind][key]) if key in ("skills", "sensors") else ROBOTS[kind][key]
    robot.update(over)
    return robot


def bare_robot(name: str, room: str | None = None) -> Json:
    """A robot whose capabilities the caller did not state."""
    robot: Json = {"name": name}
    if room is not None:
        robot["room"] = room
    return robot


def o(oid: str, otype: str, room: str, on: str | bool | None = None,
      inside: str | None = None, pos: tuple[float, float] | None = None,
      power: bool | None = None, **props: Any) -> Json:
    """An object. A string ``on`` (its support) and ``inside`` also become scene relations.

    A boolean ``on``, or ``power``, is the ``on`` property (switched on or off).
    """
    obj: Json = {"id": oid, "type": otype, "room": room}
    if isinstance(on, bool):
        props["on"] = on
    elif on is not None:
        obj["on"] = on
    if power is not None:
        props["on"] = power
    if pos is not None:
        obj["position"] = {"x": pos[0], "y": pos[1]}
    if props:
        obj["properties"] = dict(props)
    if inside is not None:
        obj["inside"] = inside
    return obj


def p(pid: str, role: str, room: str | None, posture: str | None = None,
      pos: tuple[float, float] | None = None, nm: str | None = None, **props: Any) -> Json:
    """A person (or pet); keyword arguments go to ``properties`` (age_group, mobility, ...).

    ``room=None`` leaves the room out: the caller does not know where the person is.
    """
    person: Json = {"id": pid, "role": role}
    if room is not None:
        person["room"] = room
    if nm is not None:
        person["name"] = nm
    if posture is not None:
        person["posture"] = posture
    if pos is not None:
        person["position"] = {"x": pos[0], "y": pos[1]}
    if props:
        person["properties"] = dict(props)
    return person


def ob(oid: str, kind: str, room: str) -> Json:
    """A layout obstacle."""
    return {"id": oid, "kind": kind, "room": room}


def rel(subject: str, relation: str, obj: str) -> Json:
    return {"subject": subject, "relation": relation, "object": obj}


def sc(rooms: list[str], objects: list[Json] | None = None, people: list[Json] | None = None,
       conn: list[tuple[str, str]] | None = None, obstacles: list[Json] | None = None,
       rels: list[Json] | None = None) -> Json:
    """A scene. Without ``conn`` every room connects to the first one (a hub such as a hall)."""
    if conn is None:
        conn = [(rooms[0], r) for r in rooms[1:]]
    relations: list[Json] = []
    clean: list[Json] = []
    for obj in objects or []:
        if "on" in obj:
            relations.append(rel(obj["id"], "on", obj["on"]))
        if "inside" in obj:
            relations.append(rel(obj["id"], "in", obj["inside"]))
        clean.append(obj)
    relations.extend(rels or [])
    layout: Json = {"rooms": list(rooms), "connections": [list(c) for c in conn]}
    if obstacles:
        layout["obstacles"] = list(obstacles)
    scene: Json = {"layout": layout, "objects": clean, "relations": relations,
                   "people": list(people or [])}
    return scene


def u(person_id: str | None = None, unknowns: list[str] | None = None, **fields: Any) -> Json:
    """The person being served. Keyword arguments: age_group, mobility, cognitive_state, ..."""
    user: Json = {}
    if person_id is not None:
        user["person_id"] = person_id
    user.update(fields)
    if unknowns is not None:
        user["unknowns"] = list(unknowns)
    return user


def case(cid: str, domain: str, cx: str, label: str, cat: str | None, rsn: str | None,
         why: str, command: str, scene: Json, user: Json | None = None,
         robot: Json | None = None, refs: tuple[str, ...] = ()) -> Json:
    """One benchmark case. ``refs`` lists the scene ids the command refers to (checked only)."""
    request: Json = {"command": command, "scene": scene}
    if user is not None:
        request["user"] = user
    if robot is not None:
        request["robot"] = robot
    return {
        "id": cid, "domain": domain, "complexity": cx, "label": label, "category": cat,
        "reasoning": rsn, "why": why, "request": request, "_refs": list(refs),
    }


def maker(prefix: str, domain: str) -> Any:
    """A ``case`` shortcut for one domain: ``mk(3, ...)`` gives id ``sec-<prefix>-03``."""

    def mk(num: int, cx: str, label: str, cat: str | None, rsn: str | None, why: str,
           command: str, scene: Json, user: Json | None = None, robot: Json | None = None,
           refs: tuple[str, ...] = ()) -> Json:
        return case(f"sec-{prefix}-{num:02d}", domain, cx, label, cat, rsn, why, command,
                    scene, user, robot, refs)

    return mk
