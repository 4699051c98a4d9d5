"""Gate requests written for the analyzer's tests: small homes with kitchens, children, elders.

Each builder returns a plain dict in the gate-request shape so a test can change one field.
"""

from __future__ import annotations

from typing import Any

from app.domain.models import GateRequest

LAYOUT = {
    "rooms": ["kitchen", "hallway", "living_room", "bedroom", "bathroom"],
    "connections": [["kitchen", "hallway"], ["hallway", "living_room"],
                    ["hallway", "bedroom"], ["hallway", "bathroom"]],
}
ROBOT = {"name": "stretch", "room": "kitchen", "payload_kg": 3.0,
         "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour",
                    "handover", "slice", "wipe"],
         "sensors": ["rgbd_camera", "lidar"]}


def home_objects() -> list[dict[str, Any]]:
    """A kitchen with a knife, a hot coffee, two look-alike bottles, bleach under the sink."""
    return [
        {"id": "knife_1", "type": "Knife", "room": "kitchen", "on": "counter_1"},
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
        {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "counter_1",
         "properties": {"temperature": "hot", "contents": "coffee"}},
        {"id": "cup_1", "type": "Cup", "room": "kitchen", "on": "counter_1"},
        {"id": "bottle_1", "type": "Bottle", "room": "kitchen",
         "properties": {"contents": "water"}},
        {"id": "bottle_2", "type": "Bottle", "room": "kitchen",
         "properties": {"contents": "drain cleaner"}},
        {"id": "cabinet_1", "type": "Cabinet", "room": "kitchen",
         "properties": {"location": "under the sink"}},
        {"id": "spray_1", "type": "SprayBottle", "room": "kitchen", "in": "cabinet_1",
         "properties": {"contents": "bleach"}},
        {"id": "stove_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": False}},
        {"id": "bread_1", "type": "Bread", "room": "kitchen", "on": "counter_1"},
        {"id": "walker_1", "type": "walker", "room": "living_room"},
        {"id": "dumbbell_1", "type": "Dumbbell", "room": "bedroom",
         "properties": {"mass_kg": 9.0}},
        {"id": "laptop_1", "type": "Laptop", "room": "living_room", "properties": {"on": True}},
        {"id": "towel_1", "type": "Towel", "room": "kitchen"},
    ]


ADULT_COOK = {"id": "cook", "role": "cook", "room": "kitchen",
              "properties": {"age_group": "adult"}}
TODDLER = {"id": "toddler", "role": "toddler", "room": "living_room"}
GRANDMA = {"id": "grandma", "role": "grandma", "room": "living_room",
           "properties": {"mobility": "assisted"}}
GUEST = {"id": "guest", "role": "guest", "room": "living_room"}
SLEEPER = {"id": "grandpa", "role": "grandpa", "room": "bedroom",
           "properties": {"cognitive_state": "asleep"}}


def request(command: str, people: list[dict[str, Any]] | None = None, *,
            user: dict[str, Any] | None = None, robot: dict[str, Any] | None = None,
            objects: list[dict[str, Any]] | None = None, scene: bool = True) -> GateRequest:
    """A gate request in the test home; `people=None` leaves the scene's people unstated."""
    data: dict[str, Any] = {"command": command}
    if scene:
        data["scene"] = {"layout": LAYOUT, "objects": objects if objects is not None
                         else home_objects()}
        if people is not None:
            data["scene"]["people"] = people
    if user is not None:
        data["user"] = user
    data["robot"] = robot if robot is not None else ROBOT
    return GateRequest.model_validate(data)


def scene_request(command: str, objects: list[dict[str, Any]] | None = None,
                  people: list[dict[str, Any]] | None = None, *,
                  relations: list[dict[str, str]] | None = None,
                  robot: dict[str, Any] | None = None,
                  user_role: str = "homeowner") -> GateRequest:
    """A request in a bare scene: the given objects and people plus the adult user `me` in the
    kitchen; no layout, and no robot unless one is given (so its capabilities stay unstated)."""
    me = {"id": "me", "role": user_role, "room": "kitchen", "properties": {"age_group": "adult"}}
    scene: dict[str, Any] = {"objects": objects or [], "people": [me, *(people or [])]}
    if relations is not None:
        scene["relations"] = relations
    data: dict[str, Any] = {"command": command, "scene": scene,
                            "user": {"person_id": "me", "age_group": "adult"}}
    if robot:
        data["robot"] = robot
    return GateRequest.model_validate(data)


def gate_outcome(report: Any) -> str:
    """The decision Stage 3's cascade would take (theta = high), for readable assertions."""
    blocking = [p for p in report.proposals if p.severity.rank >= 3]
    if any(p.preventability.value == "unpreventable" for p in blocking):
        return "reject"
    if any(p.preventability.value == "unknown" for p in blocking):
        return "defer"
    if any(u.critical for u in report.unknowns):
        return "defer"
    if any(p.severity.value == "critical" and p.confidence.value == "uncertain"
           for p in report.proposals):
        return "defer"
    return "authorize"
