"""Small builders for the third evaluation set: settings, robots, objects, people, cases.

The builders only shape dicts in the gate-request format (shared/spec/gate-request.md). They
carry no safety knowledge: every label in this set is the author's own judgement.
"""

from __future__ import annotations

from typing import Any

# --- settings: rooms and which rooms connect -------------------------------------------------

_SETTINGS: dict[str, tuple[list[str], list[tuple[str, str]]]] = {
    "apartment": (
        ["kitchen", "living_room", "hallway", "bedroom", "kids_room", "bathroom", "balcony"],
        [("hallway", "kitchen"), ("kitchen", "living_room"), ("hallway", "living_room"),
         ("hallway", "bedroom"), ("hallway", "kids_room"), ("hallway", "bathroom"),
         ("living_room", "balcony")],
    ),
    "house": (
        ["kitchen", "dining_room", "living_room", "hallway", "front_porch", "driveway",
         "stairs", "upstairs_landing", "master_bedroom", "kids_bedroom", "nursery",
         "bathroom", "guest_bathroom", "laundry_room", "garage_workshop", "backyard",
         "pool_deck"],
        [("kitchen", "dining_room"), ("kitchen", "living_room"), ("living_room", "hallway"),
         ("hallway", "front_porch"), ("front_porch", "driveway"), ("hallway", "stairs"),
         ("hallway", "guest_bathroom"), ("stairs", "upstairs_landing"),
         ("upstairs_landing", "master_bedroom"), ("upstairs_landing", "kids_bedroom"),
         ("upstairs_landing", "nursery"), ("upstairs_landing", "bathroom"),
         ("kitchen", "laundry_room"), ("laundry_room", "garage_workshop"),
         ("garage_workshop", "driveway"), ("kitchen", "backyard"), ("backyard", "pool_deck")],
    ),
    "assisted_living": (
        ["resident_room_112", "bathroom_112", "resident_room_114", "corridor", "dining_hall",
         "lounge", "nurse_station", "activity_room", "courtyard"],
        [("resident_room_112", "bathroom_112"), ("resident_room_112", "corridor"),
         ("resident_room_114", "corridor"), ("corridor", "dining_hall"),
         ("corridor", "lounge"), ("corridor", "nurse_station"), ("corridor", "activity_room"),
         ("dining_hall", "courtyard")],
    ),
    "daycare": (
        ["entry", "hallway", "playroom", "toddler_room", "nap_room", "infant_room",
         "changing_area", "kitchenette", "staff_office", "playground"],
        [("entry", "hallway"), ("hallway", "playroom"), ("hallway", "toddler_room"),
         ("hallway", "nap_room"), ("hallway", "infant_room"), ("infant_room", "changing_area"),
         ("hallway", "kitchenette"), ("hallway", "staff_office"), ("playroom", "playground")],
    ),
    "dorm": (
        ["dorm_room_214", "dorm_room_216", "hallway", "shared_bathroom", "lounge",
         "kitchenette", "stairwell", "elevator", "lobby", "laundry_room"],
        [("dorm_room_214", "hallway"), ("dorm_room_216", "hallway"),
         ("hallway", "shared_bathroom"), ("hallway", "lounge"), ("hallway", "kitchenette"),
         ("hallway", "stairwell"), ("hallway", "elevator"), ("stairwell", "lobby"),
         ("elevator", "lobby"), ("lobby", "laundry_room")],
    ),
    "office": (
        ["reception", "corridor", "open_office", "meeting_room", "kitchenette",
         "server_closet", "restroom", "supply_room"],
        [("reception", "corridor"), ("corridor", "open_office"), ("corridor", "meeting_room"),
         ("corridor", "kitchenette"), ("corridor", "server_closet"), ("corridor", "restroom"),
         ("corridor", "supply_room")],
    ),
    "food_truck": (
        ["cab", "prep_area", "grill_line", "service_window", "curbside"],
        [("cab", "prep_area"), ("prep_area", "grill_line"), ("grill_line", "service_window"),
         ("prep_area", "curbside")],
    ),
    "vet_clinic": (
        ["parking_lot", "waiting_room", "reception_desk", "hallway", "exam_room_1",
         "exam_room_2", "supply_closet", "restroom", "staff_kitchenette"],
        [("parking_lot", "waiting_room"), ("waiting_room", "reception_desk"),
         ("waiting_room", "hallway"), ("waiting_room", "restroom"), ("hallway", "exam_room_1"),
         ("hallway", "exam_room_2"), ("hallway", "supply_closet"),
         ("hallway", "staff_kitchenette")],
    ),
    "garden": (
        ["garden_shed", "garden", "patio", "kitchen", "living_room"],
        [("garden_shed", "garden"), ("garden", "patio"), ("patio", "kitchen"),
         ("kitchen", "living_room")],
    ),
    "boat": (
        ["cabin", "galley", "head", "companionway", "cockpit", "deck"],
        [("cabin", "galley"), ("cabin", "head"), ("galley", "companionway"),
         ("companionway", "cockpit"), ("cockpit", "deck")],
    ),
    "rv": (
        ["rv_cab", "rv_living_area", "rv_galley", "rv_bedroom", "rv_bathroom", "campsite"],
        [("rv_cab", "rv_living_area"), ("rv_living_area", "rv_galley"),
         ("rv_living_area", "rv_bedroom"), ("rv_living_area", "rv_bathroom"),
         ("rv_living_area", "campsite")],
    ),
}

SETTINGS = tuple(_SETTINGS)

# --- robots: a few capability profiles, overridable per case ---------------------------------

_ROBOTS: dict[str, dict[str, Any]] = {
    "stretch": {
        "name": "stretch-3",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "handover", "speak"],
        "payload_kg": 2.0, "max_speed_mps": 0.6,
        "sensors": ["rgbd_camera", "lidar", "microphone"],
    },
    "chef": {
        "name": "line-cook-arm",
        "skills": ["navigate", "pick", "place", "pour", "cut", "stir", "toggle", "open",
                   "close", "wipe", "handover"],
        "payload_kg": 4.0, "max_speed_mps": 0.4,
        "sensors": ["rgbd_camera", "force_torque", "thermal_camera"],
    },
    "helper": {
        "name": "tiago-home",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "handover", "push",
                   "wipe", "pour", "speak"],
        "payload_kg": 5.0, "max_speed_mps": 1.0,
        "sensors": ["rgbd_camera", "lidar", "microphone", "speaker"],
    },
    "carer": {
        "name": "care-aide-7",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "handover", "guide",
                   "speak", "push_wheelchair", "call_staff"],
        "payload_kg": 10.0, "max_speed_mps": 0.7,
        "sensors": ["rgbd_camera", "lidar", "microphone", "speaker", "bump_sensors"],
    },
    "hauler": {
        "name": "cargo-mule-25",
        "skills": ["navigate", "pick", "place", "push", "open", "close"],
        "payload_kg": 25.0, "max_speed_mps": 1.5,
        "sensors": ["lidar", "rgb_camera"],
    },
    "mini": {
        "name": "pocket-helper",
        "skills": ["navigate", "pick", "place", "speak"],
        "payload_kg": 0.5, "max_speed_mps": 0.4,
        "sensors": ["rgb_camera", "microphone"],
    },
    "rover": {
        "name": "rover-tray",
        "skills": ["navigate", "speak", "carry_tray"],
        "payload_kg": 8.0, "max_speed_mps": 2.0,
        "sensors": ["lidar", "rgb_camera", "microphone", "speaker"],
    },
    "deckhand": {
        "name": "deckhand-2",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "handover", "pour",
                   "climb_ladder"],
        "payload_kg": 8.0, "max_speed_mps": 0.5,
        "sensors": ["rgbd_camera", "lidar", "imu"],
    },
    "unstated": {"name": "generic-assistant"},
}

ROBOTS = tuple(_ROBOTS)


def bot(profile: str, room: str, **overrides: Any) -> dict[str, Any]:
    """A robot profile placed in a room; keyword overrides replace profile fields."""
    base = {k: (list(v) if isinstance(v, list) else v) for k, v in _ROBOTS[profile].items()}
    base["room"] = room
    base.update(overrides)
    return base


# --- scene pieces ----------------------------------------------------------------------------


def ob(oid: str, otype: str, room: str, *, on: str | None = None, inside: str | None = None,
       powered: bool | None = None, **props: Any) -> dict[str, Any]:
    """A scene object. `on`/`inside` name a supporting object; `powered` is properties.on."""
    obj: dict[str, Any] = {"id": oid, "type": otype, "room": room}
    if on is not None:
        obj["on"] = on
    if inside is not None:
        obj["in"] = inside
    if powered is not None:
        props["on"] = powered
    if props:
        obj["properties"] = props
    return obj


def pp(pid: str, role: str, room: str | None, *, name: str | None = None,
       posture: str | None = None, **props: Any) -> dict[str, Any]:
    """A person; `room` None means the caller does not know where the person is."""
    person: dict[str, Any] = {"id": pid, "role": role, "room": room}
    if name is not None:
        person["name"] = name
    if posture is not None:
        person["posture"] = posture
    if props:
        person["properties"] = props
    return person


def rel(subject: str, relation: str, obj: str) -> dict[str, str]:
    return {"subject": subject, "relation": relation, "object": obj}


def obst(oid: str, kind: str, room: str) -> dict[str, str]:
    return {"id": oid, "kind": kind, "room": room}


def usr(person_id: str | None = None, *, age: str | None = None, mobility: str | None = None,
        cog: str | None = None, unknowns: tuple[str, ...] | list[str] = (),
        **extra: Any) -> dict[str, Any]:
    """The person being served (u)."""
    user: dict[str, Any] = {}
    if person_id is not None:
        user["person_id"] = person_id
    if age is not None:
        user["age_group"] = age
    if mobility is not None:
        user["mobility"] = mobility
    if cog is not None:
        user["cognitive_state"] = cog
    user["unknowns"] = list(unknowns)
    user.update(extra)
    return user


def case(cid: str, domain: str, cx: str, label: str, cat: str | None, rsn: str | None,
         why: str, command: str, *, setting: str, objects: list[dict[str, Any]],
         robot: dict[str, Any], people: tuple[dict[str, Any], ...] | list[dict[str, Any]] = (),
         relations: tuple[dict[str, str], ...] | list[dict[str, str]] = (),
         obstacles: tuple[dict[str, str], ...] | list[dict[str, str]] = (),
         user: dict[str, Any] | None = None, refs: tuple[str, ...] | list[str] = (),
         style: str = "planner") -> dict[str, Any]:
    """One benchmark case. `on`/`in` fields of objects also become relations.

    `refs` (ids the command refers to) is kept as `_refs` for validation and dropped on write.
    `style` records how the command is phrased: planner, spoken or indirect.
    """
    rooms, conns = _SETTINGS[setting]
    rels = [rel(o["id"], k, o[k]) for o in objects for k in ("on", "in") if k in o]
    rels.extend(relations)
    scene: dict[str, Any] = {
        "layout": {"rooms": list(rooms), "connections": [list(c) for c in conns],
                   "obstacles": list(obstacles)},
        "objects": list(objects),
        "relations": rels,
        "people": list(people),
    }
    request: dict[str, Any] = {"command": command, "scene": scene, "robot": robot}
    if user is not None:
        request["user"] = user
    return {
        "id": cid, "domain": domain, "complexity": cx, "label": label, "category": cat,
        "reasoning": rsn, "why": why, "setting": setting, "style": style,
        "request": request, "_refs": list(refs),
    }
