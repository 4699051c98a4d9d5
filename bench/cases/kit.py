"""The benchmark's vocabulary: layouts, fixture sets, robot presets and the `Case` record.

In: keyword descriptions of objects, people, layouts, users and robots, as a case file
(`case_files.py`) names them. Out: plain JSON dicts in the gate-request shape
(`shared/spec/gate-request.md`). A property left out of a description is left out of the JSON:
a missing key means unknown, which is how ambiguous cases omit their critical fact.
Fails: `KeyError` on an unknown layout, fixture set or robot preset name.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

Json = dict[str, Any]


class CaseError(ValueError):
    """A case description that would make a wrong or inconsistent benchmark line."""


LAYOUTS: dict[str, tuple[list[str], list[tuple[str, str]]]] = {
    "flat": (
        ["kitchen", "living_room", "hallway", "bedroom", "bathroom"],
        [("kitchen", "living_room"), ("living_room", "hallway"), ("hallway", "bedroom"),
         ("hallway", "bathroom")],
    ),
    "house": (
        ["entrance", "hallway", "kitchen", "dining_room", "living_room", "laundry_room",
         "garage", "stairs", "upstairs_landing", "bedroom", "kids_room", "bathroom"],
        [("entrance", "hallway"), ("hallway", "kitchen"), ("kitchen", "dining_room"),
         ("hallway", "living_room"), ("kitchen", "laundry_room"), ("laundry_room", "garage"),
         ("hallway", "stairs"), ("stairs", "upstairs_landing"), ("upstairs_landing", "bedroom"),
         ("upstairs_landing", "kids_room"), ("upstairs_landing", "bathroom")],
    ),
    "studio": (
        ["kitchenette", "living_area", "bathroom"],
        [("kitchenette", "living_area"), ("living_area", "bathroom")],
    ),
    "care": (
        ["reception", "resident_room", "corridor", "lounge", "dining_hall", "nurse_station",
         "bathroom"],
        [("reception", "corridor"), ("resident_room", "corridor"), ("corridor", "lounge"),
         ("corridor", "dining_hall"),
         ("corridor", "nurse_station"), ("resident_room", "bathroom")],
    ),
    "office": (
        ["reception", "corridor", "open_office", "office_kitchen", "meeting_room", "server_room"],
        [("reception", "corridor"), ("corridor", "open_office"), ("corridor", "office_kitchen"),
         ("corridor", "meeting_room"), ("corridor", "server_room")],
    ),
}


def o(ident: str, kind: str, room: str | None, *, at: str | None = None,
      inside: str | None = None, name: str | None = None, **props: Any) -> Json:
    """An object resting on `at` or inside `inside`; `props` become its `properties`.

    `on=True` in `props` is the fixed property "switched on"; the support is `at`.
    """
    obj: Json = {"id": ident, "type": kind}
    if name is not None:
        obj["name"] = name
    if room is not None:
        obj["room"] = room
    if at is not None:
        obj["on"] = at
    if inside is not None:
        obj["in"] = inside
    if props:
        obj["properties"] = props
    return obj


def p(ident: str, role: str, room: str | None, *, age: str | None = None,
      mobility: str | None = None, cog: str | None = None, posture: str | None = None,
      name: str | None = None, **props: Any) -> Json:
    """A person; `age`, `mobility`, `cog` and `props` go into `properties` when given."""
    person: Json = {"id": ident, "role": role}
    if name is not None:
        person["name"] = name
    if room is not None:
        person["room"] = room
    if posture is not None:
        person["posture"] = posture
    properties: Json = {}
    if age is not None:
        properties["age_group"] = age
    if mobility is not None:
        properties["mobility"] = mobility
    if cog is not None:
        properties["cognitive_state"] = cog
    properties.update(props)
    if properties:
        person["properties"] = properties
    return person


def rel(subject: str, relation: str, obj: str) -> Json:
    """A relation between two scene ids."""
    return {"subject": subject, "relation": relation, "object": obj}


def scene(layout: str, objects: list[Json], people: list[Json],
          relations: list[Json] | None = None, obstacles: list[Json] | None = None) -> Json:
    """A scene on one of the preset layouts; relations mirror every object's `on`/`in`."""
    rooms, connections = LAYOUTS[layout]
    derived = [rel(x["id"], "on", x["on"]) for x in objects if "on" in x]
    derived += [rel(x["id"], "in", x["in"]) for x in objects if "in" in x]
    return {
        "layout": {"rooms": list(rooms), "connections": [list(c) for c in connections],
                   "obstacles": obstacles or []},
        "objects": objects,
        "relations": derived + (relations or []),
        "people": people,
    }


def user(person_id: str | None = None, *, age: str | None = None, mobility: str | None = None,
         cog: str | None = None, allergies: list[str] | None = None,
         unknowns: list[str] | None = None) -> Json:
    """The person being served; omitted attributes stay unknown."""
    profile: Json = {}
    if person_id is not None:
        profile["person_id"] = person_id
    for key, value in (("age_group", age), ("mobility", mobility), ("cognitive_state", cog),
                       ("allergies", allergies)):
        if value is not None:
            profile[key] = value
    profile["unknowns"] = unknowns or []
    return profile


_FULL = ["navigate", "pick", "place", "open", "close", "toggle", "pour", "handover"]
ROBOTS: dict[str, Json] = {
    "stretch": {"name": "stretch-3", "skills": [*_FULL, "wipe"], "payload_kg": 2.0,
                "max_speed_mps": 0.6, "sensors": ["rgbd_camera", "lidar"]},
    "tiago": {"name": "tiago-pro", "skills": [*_FULL, "slice", "wipe", "push"],
              "payload_kg": 3.0, "max_speed_mps": 1.0,
              "sensors": ["rgbd_camera", "lidar", "force_torque", "microphone"]},
    "fetch": {"name": "fetch-mobile", "skills": ["navigate", "pick", "place", "open", "close",
                                                 "push", "handover"],
              "payload_kg": 6.0, "max_speed_mps": 1.0, "sensors": ["rgbd_camera", "lidar"]},
    "locobot": {"name": "locobot-wx250", "skills": ["navigate", "pick", "place"],
                "payload_kg": 0.25, "max_speed_mps": 0.5, "sensors": ["rgbd_camera"]},
    "tray": {"name": "turtlebot-4-tray", "skills": ["navigate", "carry_tray"],
             "payload_kg": 9.0, "max_speed_mps": 0.3,
             "sensors": ["lidar", "rgbd_camera", "bump_sensor"]},
    "spot": {"name": "spot-arm", "skills": ["navigate", "pick", "place", "open", "close",
                                            "push", "toggle", "climb_stairs"],
             "payload_kg": 5.0, "max_speed_mps": 1.6,
             "sensors": ["rgbd_camera", "lidar", "thermal_camera"]},
    "hsr": {"name": "hsr-care", "skills": [*_FULL, "wipe", "speak"], "payload_kg": 1.2,
            "max_speed_mps": 0.4,
            "sensors": ["rgbd_camera", "lidar", "microphone", "thermal_camera"]},
}


def robot(preset: str, room: str, **overrides: Any) -> Json:
    """A robot from a preset, placed in `room`; `overrides` replace preset fields."""
    return {**ROBOTS[preset], "room": room, **overrides}


def kitchen(room: str = "kitchen", **changes: Json) -> list[Json]:
    """The fixtures every kitchen has; `changes` maps a fixture id to extra properties."""
    base = [
        o("countertop_1", "CounterTop", room),
        o("stove_1", "StoveBurner", room, on=False),
        o("stoveknob_1", "StoveKnob", room),
        o("fridge_1", "Fridge", room, open=False),
        o("sink_1", "SinkBasin", room),
        o("faucet_1", "Faucet", room, on=False),
        o("microwave_1", "Microwave", room, on=False, electrical=True),
        o("cabinet_1", "Cabinet", room, open=False),
        o("drawer_1", "Drawer", room, open=False),
        o("garbage_1", "GarbageCan", room),
    ]
    for fixture in base:
        fixture.setdefault("properties", {}).update(changes.get(fixture["id"], {}))
        if not fixture["properties"]:
            del fixture["properties"]
    return base


def living(room: str = "living_room") -> list[Json]:
    """Living-room furniture."""
    return [o("sofa_1", "Sofa", room), o("coffeetable_1", "CoffeeTable", room),
            o("tv_1", "Television", room, on=False, electrical=True),
            o("floorlamp_1", "FloorLamp", room, on=True, electrical=True)]


def bedroom(room: str = "bedroom") -> list[Json]:
    """Bedroom furniture."""
    return [o("bed_1", "Bed", room), o("sidetable_1", "SideTable", room),
            o("dresser_1", "Dresser", room), o("desklamp_1", "DeskLamp", room, on=False)]


def bathroom(room: str = "bathroom") -> list[Json]:
    """Bathroom fixtures."""
    return [o("toilet_1", "Toilet", room), o("bathsink_1", "SinkBasin", room),
            o("bathtub_1", "Bathtub", room), o("medcabinet_1", "Cabinet", room, open=False)]


FIXTURE_SETS = {"kitchen": kitchen, "living": living, "bedroom": bedroom, "bathroom": bathroom}


@dataclass(frozen=True)
class Case:
    """One case description before it is written as a JSONL line."""

    domain: str
    complexity: str
    label: str
    category: str | None
    reasoning: str | None
    steps: int
    command: str
    why: str
    scene: Json
    user: Json
    robot: Json
    missing: list[Json] = field(default_factory=list)
