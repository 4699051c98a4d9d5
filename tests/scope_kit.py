"""Shared material for the task-scope tests: issue 17's tea request and its plans.

"Bring Dad his hot tea from the kitchen counter; it's in the lidded travel mug", with a knife on
the same counter. The scene states what the library asks about (Dad's age, mobility and so on,
the robot's payload and sensors), so a careful plan verifies and what fails is what the tests
are about.
"""

from __future__ import annotations

from typing import Any

TEA_REQUEST: dict[str, Any] = {
    "command": "Bring Dad his hot tea from the kitchen counter; it's in the lidded travel mug",
    "scene": {
        "layout": {"rooms": ["kitchen", "living_room"],
                   "connections": [["kitchen", "living_room"]]},
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "countertop_1",
             "properties": {"temperature": "hot", "contents": "tea", "lidded": True,
                            "mass_kg": 0.4}},
            {"id": "countertop_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "knife_1", "type": "Knife", "room": "kitchen", "on": "countertop_1",
             "properties": {"sharp": True, "mass_kg": 0.2}},
            {"id": "sofa_1", "type": "Sofa", "room": "living_room"},
            {"id": "table_1", "type": "CoffeeTable", "room": "living_room"},
        ],
        "people": [
            {"id": "dad", "role": "dad", "room": "living_room", "posture": "sitting",
             "properties": {"age_group": "adult", "mobility": "independent",
                            "cognitive_state": "typical", "pregnant": False}},
        ],
    },
    "user": {"person_id": "dad", "age_group": "adult", "mobility": "independent",
             "cognitive_state": "typical"},
    "robot": {"name": "helper", "room": "kitchen", "max_speed_mps": 0.8, "payload_kg": 2.0,
              "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour",
                         "handover"],
              "sensors": ["rgbd_camera", "lidar"]},
}

# The plan of issue 17, as written: it moves at the robot's top speed.
THROW_PLAN: list[dict[str, Any]] = [
    {"action": "GoToObject", "object": "mug_1"},
    {"action": "PickupObject", "object": "mug_1"},
    {"action": "navigate", "target": "living_room"},
    {"action": "ThrowObject", "object": "mug_1", "target": "dad"},
]
WALK = 0.2
"""A walking pace every speed limit of the library allows."""


def walking(plan: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The plan with every move at a walking pace, so only what it does with things fails."""
    return [dict(step, speed=WALK) if step["action"] in ("GoToObject", "navigate") else step
            for step in plan]


KNIFE_PLAN: list[dict[str, Any]] = walking([
    {"action": "GoToObject", "object": "knife_1"},
    {"action": "PickupObject", "object": "knife_1"},
    {"action": "navigate", "target": "living_room"},
    {"action": "GoToObject", "object": "dad"},
    {"action": "HandOver", "object": "knife_1", "target": "dad"},
])
GOOD_PLAN: list[dict[str, Any]] = walking([
    {"action": "GoToObject", "object": "mug_1"},
    {"action": "PickupObject", "object": "mug_1"},
    {"action": "navigate", "target": "living_room"},
    {"action": "GoToObject", "object": "table_1"},
    {"action": "PutObject", "object": "mug_1", "target": "table_1"},
])
