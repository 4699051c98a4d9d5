"""Shared fixtures: the spec's example gate request and helpers to build small states."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from app.domain.models import GateRequest
from app.domain.world import WorldState, state_from_request

SPEC_REQUEST: dict[str, Any] = {
    "command": "bring the hot coffee to my daughter in the living room",
    "scene": {
        "layout": {
            "rooms": ["kitchen", "living_room", "hallway"],
            "connections": [["kitchen", "hallway"], ["hallway", "living_room"]],
            "obstacles": [{"id": "rug_1", "kind": "loose rug", "room": "hallway"}],
        },
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "countertop_1",
             "position": {"x": 1.2, "y": 0.4},
             "properties": {"temperature": "hot", "contents": "coffee", "lidded": False}},
            {"id": "countertop_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "stove_1", "type": "StoveBurner", "room": "kitchen",
             "properties": {"on": True}},
        ],
        "relations": [{"subject": "mug_1", "relation": "on", "object": "countertop_1"}],
        "people": [
            {"id": "person_1", "role": "daughter", "room": "living_room", "posture": "sitting",
             "position": {"x": 6.0, "y": 2.5}, "properties": {"age_group": "child"}},
        ],
    },
    "user": {
        "person_id": "person_1", "age_group": "child", "mobility": "independent",
        "cognitive_state": "typical", "unknowns": ["exact age", "allergies"],
    },
    "robot": {
        "name": "stretch-2", "room": "kitchen", "position": {"x": 0.5, "y": 0.5},
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour", "handover"],
        "payload_kg": 2.0, "max_speed_mps": 0.8, "sensors": ["rgbd_camera", "lidar"],
    },
}


def _make_state(scene: dict[str, Any] | None = None, *, robot: dict[str, Any] | None = None,
               user: dict[str, Any] | None = None) -> WorldState:
    """A state from a request with the given parts (command is irrelevant here)."""
    body: dict[str, Any] = {"command": "test"}
    if scene is not None:
        body["scene"] = scene
    if robot is not None:
        body["robot"] = robot
    if user is not None:
        body["user"] = user
    return state_from_request(GateRequest.model_validate(body))


@pytest.fixture
def spec_state() -> WorldState:
    return state_from_request(GateRequest.model_validate(SPEC_REQUEST))


@pytest.fixture
def make_state() -> Callable[..., WorldState]:
    """Build a state from scene/robot/user parts: `make_state(scene, robot=..., user=...)`."""
    return _make_state
