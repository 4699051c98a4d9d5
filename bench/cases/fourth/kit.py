"""Builders for the fourth evaluation set: places, robot profiles, scene pieces and cases.

These helpers only shape dicts in the gate-request format (shared/spec/gate-request.md). They hold
no safety knowledge; every label in the set is the author's judgement, written in the case itself.
"""

from __future__ import annotations

from typing import Any

# --- places: the rooms of each setting and which of them connect ---------------------------

Rooms = list[str]
Links = list[tuple[str, str]]


PLACES: dict[str, tuple[Rooms, Links]] = {
    "family_house": (
        ["kitchen", "dining_room", "living_room", "hallway", "stairs", "landing",
         "main_bedroom", "kids_bedroom", "nursery", "spare_bedroom", "bathroom",
         "utility_room", "garage", "garden", "front_path"],
        [("kitchen", "dining_room"), ("dining_room", "living_room"), ("living_room", "hallway"),
         ("hallway", "kitchen"), ("hallway", "stairs"), ("stairs", "landing"),
         ("landing", "main_bedroom"), ("landing", "kids_bedroom"), ("landing", "nursery"),
         ("landing", "spare_bedroom"),
         ("landing", "bathroom"), ("kitchen", "utility_room"), ("utility_room", "garage"),
         ("kitchen", "garden"), ("hallway", "front_path"), ("garage", "front_path")],
    ),
    "flat": (
        ["kitchen", "living_room", "hallway", "bedroom", "kids_room", "bathroom", "balcony",
         "building_stairwell"],
        [("hallway", "kitchen"), ("hallway", "living_room"), ("hallway", "bedroom"),
         ("hallway", "kids_room"), ("hallway", "bathroom"), ("living_room", "balcony"),
         ("hallway", "building_stairwell")],
    ),
    "bungalow": (
        ["kitchen", "living_room", "hallway", "bedroom", "bathroom", "front_step",
         "back_garden"],
        [("hallway", "kitchen"), ("hallway", "living_room"), ("hallway", "bedroom"),
         ("hallway", "bathroom"), ("hallway", "front_step"), ("kitchen", "back_garden")],
    ),
    "care_home": (
        ["main_entrance", "corridor", "lounge", "dining_room", "room_3", "room_5", "room_9",
         "assisted_bathroom", "nurse_station", "medication_room", "kitchen", "garden"],
        [("main_entrance", "corridor"), ("corridor", "lounge"), ("corridor", "dining_room"),
         ("corridor", "room_3"), ("corridor", "room_5"), ("corridor", "room_9"),
         ("corridor", "assisted_bathroom"), ("corridor", "nurse_station"),
         ("nurse_station", "medication_room"), ("dining_room", "kitchen"),
         ("lounge", "garden")],
    ),
    "hospital_ward": (
        ["lift_lobby", "ward_corridor", "bay_a", "bay_b", "side_room_4", "nurses_station",
         "medication_room", "sluice_room", "day_room", "ward_kitchen"],
        [("lift_lobby", "ward_corridor"), ("ward_corridor", "bay_a"),
         ("ward_corridor", "bay_b"), ("ward_corridor", "side_room_4"),
         ("ward_corridor", "nurses_station"), ("nurses_station", "medication_room"),
         ("ward_corridor", "sluice_room"), ("ward_corridor", "day_room"),
         ("ward_corridor", "ward_kitchen")],
    ),
    "primary_school": (
        ["main_entrance", "office", "corridor", "classroom_2b", "classroom_5a", "hall",
         "science_room", "kitchen", "staff_room", "playground"],
        [("main_entrance", "office"), ("main_entrance", "corridor"),
         ("corridor", "classroom_2b"), ("corridor", "classroom_5a"), ("corridor", "hall"),
         ("corridor", "science_room"), ("hall", "kitchen"), ("corridor", "staff_room"),
         ("hall", "playground")],
    ),
    "corner_shop": (
        ["shop_floor", "tills", "stockroom", "loading_bay", "staff_room", "fire_exit_passage",
         "car_park"],
        [("shop_floor", "tills"), ("shop_floor", "stockroom"), ("stockroom", "loading_bay"),
         ("stockroom", "staff_room"), ("shop_floor", "fire_exit_passage"),
         ("fire_exit_passage", "car_park"), ("tills", "car_park"),
         ("loading_bay", "car_park")],
    ),
    "workshop": (
        ["workshop_floor", "timber_store", "paint_booth", "office", "yard"],
        [("workshop_floor", "timber_store"), ("workshop_floor", "paint_booth"),
         ("workshop_floor", "office"), ("workshop_floor", "yard")],
    ),
    "farm": (
        ["farmhouse_kitchen", "farmyard", "barn", "milking_parlour", "feed_store",
         "chemical_store", "paddock", "pond_field"],
        [("farmhouse_kitchen", "farmyard"), ("farmyard", "barn"),
         ("farmyard", "milking_parlour"), ("barn", "feed_store"),
         ("farmyard", "chemical_store"), ("farmyard", "paddock"),
         ("paddock", "pond_field")],
    ),
    "chem_lab": (
        ["lab_bench_area", "fume_hood_bay", "solvent_store", "lab_corridor", "write_up_office",
         "wash_room"],
        [("lab_bench_area", "fume_hood_bay"), ("lab_bench_area", "solvent_store"),
         ("lab_bench_area", "lab_corridor"), ("lab_corridor", "write_up_office"),
         ("lab_bench_area", "wash_room")],
    ),
    "office": (
        ["reception", "open_office", "meeting_room", "kitchenette", "corridor",
         "server_room", "stairwell", "print_room"],
        [("reception", "corridor"), ("corridor", "open_office"), ("corridor", "meeting_room"),
         ("corridor", "kitchenette"), ("corridor", "server_room"), ("corridor", "stairwell"),
         ("corridor", "print_room")],
    ),
    "hotel": (
        ["lobby", "front_desk", "lift", "corridor_5", "room_512", "room_514",
         "housekeeping_store", "restaurant", "hotel_kitchen", "pool_hall"],
        [("lobby", "front_desk"), ("lobby", "lift"), ("lift", "corridor_5"),
         ("corridor_5", "room_512"), ("corridor_5", "room_514"),
         ("corridor_5", "housekeeping_store"), ("lobby", "restaurant"),
         ("restaurant", "hotel_kitchen"), ("lobby", "pool_hall")],
    ),
    "restaurant": (
        ["dining_area", "pass", "kitchen_line", "prep_room", "walk_in_cooler", "dish_pit",
         "back_door"],
        [("dining_area", "pass"), ("pass", "kitchen_line"), ("kitchen_line", "prep_room"),
         ("prep_room", "walk_in_cooler"), ("kitchen_line", "dish_pit"),
         ("dish_pit", "back_door")],
    ),
    "camper_van": (
        ["cab", "living_area", "galley", "bed_area", "washroom", "pitch"],
        [("cab", "living_area"), ("living_area", "galley"), ("living_area", "bed_area"),
         ("living_area", "washroom"), ("living_area", "pitch")],
    ),
}

SETTINGS = tuple(PLACES)

# --- robot profiles ----------------------------------------------------------------------------

_PROFILES: dict[str, dict[str, Any]] = {
    "homebot": {
        "name": "homebot-s",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "handover", "pour",
                   "wipe", "speak"],
        "payload_kg": 3.0, "max_speed_mps": 0.8,
        "sensors": ["rgbd_camera", "lidar", "microphone", "speaker"],
    },
    "cook": {
        "name": "galley-arm-2",
        "skills": ["navigate", "pick", "place", "pour", "cut", "stir", "toggle", "open",
                   "close", "wipe", "handover"],
        "payload_kg": 5.0, "max_speed_mps": 0.5,
        "sensors": ["rgbd_camera", "force_torque", "thermal_camera"],
    },
    "carer": {
        "name": "carebot-12",
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "handover",
                   "guide", "speak", "push_wheelchair", "call_staff", "pour"],
        "payload_kg": 12.0, "max_speed_mps": 0.7,
        "sensors": ["rgbd_camera", "lidar", "microphone", "speaker", "bump_sensors",
                    "cliff_sensors"],
    },
    "courier": {
        "name": "tug-courier",
        "skills": ["navigate", "carry_tray", "open_door", "call_lift", "speak"],
        "payload_kg": 20.0, "max_speed_mps": 1.8,
        "sensors": ["lidar", "rgb_camera", "cliff_sensors", "speaker"],
    },
    "shop": {
        "name": "aisle-runner",
        "skills": ["navigate", "pick", "place", "push", "open", "close", "scan_barcode"],
        "payload_kg": 15.0, "max_speed_mps": 1.2,
        "sensors": ["lidar", "rgbd_camera", "barcode_scanner"],
    },
    "bench": {
        "name": "bench-hand",
        "skills": ["navigate", "pick", "place", "toggle", "open", "close", "handover", "hold",
                   "unplug", "sweep"],
        "payload_kg": 8.0, "max_speed_mps": 0.6,
        "sensors": ["rgbd_camera", "lidar", "force_torque"],
    },
    "lab": {
        "name": "lab-assist-1",
        "skills": ["navigate", "pick", "place", "pour", "open", "close", "toggle", "pipette",
                   "cap", "uncap"],
        "payload_kg": 2.0, "max_speed_mps": 0.4,
        "sensors": ["rgbd_camera", "force_torque", "scale", "fume_sensor"],
    },
    "farmhand": {
        "name": "fieldmule",
        "skills": ["navigate", "pick", "place", "open", "close", "push", "tow", "pour"],
        "payload_kg": 25.0, "max_speed_mps": 1.5,
        "sensors": ["lidar", "rgb_camera", "gps"],
    },
    "tiny": {
        "name": "desk-pal",
        "skills": ["navigate", "pick", "place", "speak"],
        "payload_kg": 0.8, "max_speed_mps": 0.3,
        "sensors": ["rgb_camera", "microphone"],
    },
    "climber": {
        "name": "homebot-stairs",
        "skills": ["navigate", "climb_stairs", "pick", "place", "open", "close", "toggle",
                   "handover", "speak", "wipe"],
        "payload_kg": 4.0, "max_speed_mps": 0.7,
        "sensors": ["rgbd_camera", "lidar", "cliff_sensors", "microphone"],
    },
    "bare": {"name": "unnamed-assistant"},
}

PROFILES = tuple(_PROFILES)


def robot(profile: str, room: str, **changes: Any) -> dict[str, Any]:
    """A copy of a robot profile placed in `room`; keyword arguments replace fields."""
    out = {k: (list(v) if isinstance(v, list) else v) for k, v in _PROFILES[profile].items()}
    out["room"] = room
    out.update(changes)
    return out


# --- scene pieces --------------------------------------------------------------------------------


def thing(oid: str, otype: str, room: str, *, on: str | None = None, inside: str | None = None,
          at: tuple[float, float] | None = None, **props: Any) -> dict[str, Any]:
    """A scene object. `on`/`inside` name a support in the same room, `at` is an (x, y) spot."""
    out: dict[str, Any] = {"id": oid, "type": otype, "room": room}
    if on is not None:
        out["on"] = on
    if inside is not None:
        out["in"] = inside
    if at is not None:
        out["position"] = {"x": at[0], "y": at[1]}
    if "powered" in props:
        props["on"] = props.pop("powered")
    if props:
        out["properties"] = props
    return out


def who(pid: str, role: str, room: str | None, *, name: str | None = None,
        posture: str | None = None, at: tuple[float, float] | None = None,
        **props: Any) -> dict[str, Any]:
    """A person (or a pet, with a `species` property). `room` None: whereabouts unknown."""
    out: dict[str, Any] = {"id": pid, "role": role, "room": room}
    if name is not None:
        out["name"] = name
    if posture is not None:
        out["posture"] = posture
    if at is not None:
        out["position"] = {"x": at[0], "y": at[1]}
    if props:
        out["properties"] = props
    return out


def link(subject: str, relation: str, obj: str) -> dict[str, str]:
    return {"subject": subject, "relation": relation, "object": obj}


def block(oid: str, kind: str, room: str) -> dict[str, str]:
    """A fixed obstacle in the layout (a step, a loose mat, a threshold)."""
    return {"id": oid, "kind": kind, "room": room}


def served(person_id: str | None = None, *, age: str | None = None,
           mobility: str | None = None, mind: str | None = None,
           unknowns: tuple[str, ...] | list[str] = (), **extra: Any) -> dict[str, Any]:
    """The user u: the person being served, with what the caller says it does not know."""
    out: dict[str, Any] = {}
    if person_id is not None:
        out["person_id"] = person_id
    if age is not None:
        out["age_group"] = age
    if mobility is not None:
        out["mobility"] = mobility
    if mind is not None:
        out["cognitive_state"] = mind
    out["unknowns"] = list(unknowns)
    out.update(extra)
    return out


def case(cid: str, domain: str, cx: str, label: str, cat: str | None, rsn: str | None,
         why: str, command: str, *, place: str, things: list[dict[str, Any]],
         bot: dict[str, Any], people: list[dict[str, Any]] | tuple[()] = (),
         links: list[dict[str, str]] | tuple[()] = (),
         blocks: list[dict[str, str]] | tuple[()] = (),
         user: dict[str, Any] | None = None, refs: list[str] | tuple[str, ...] = (),
         style: str = "planner", hazard: str | None = None) -> dict[str, Any]:
    """One case in the benchmark format.

    The `on`/`in` fields of objects are repeated as relations. Extra keys: `setting`, `style`
    (planner, spoken, indirect or euphemism) and `hazard` (a short tag for the harm mechanism,
    null for safe cases). `refs` are the scene ids the command names; they are kept as `_refs`
    for validation and not written out.
    """
    rooms, conns = PLACES[place]
    rels = [link(o["id"], key, o[key]) for o in things for key in ("on", "in") if key in o]
    rels.extend(links)
    request: dict[str, Any] = {
        "command": command,
        "scene": {
            "layout": {"rooms": list(rooms), "connections": [list(c) for c in conns],
                       "obstacles": list(blocks)},
            "objects": list(things),
            "relations": rels,
            "people": list(people),
        },
        "robot": bot,
    }
    if user is not None:
        request["user"] = user
    return {
        "id": cid, "domain": domain, "complexity": cx, "label": label, "category": cat,
        "reasoning": rsn, "why": why, "setting": place, "style": style, "hazard": hazard,
        "request": request, "_refs": list(refs),
    }
