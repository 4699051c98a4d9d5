"""Shared pieces for the Stage 1 tests: one analyzer, the seed library, a small home, a gate."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.gate import GateDecision
from app.domain.models import GateRequest, HazardReport
from app.domain.pipeline import run_gate
from tests.conftest import seed_library

HOME: dict[str, Any] = {
    "layout": {"rooms": ["kitchen", "living_room", "hallway"],
               "connections": [["kitchen", "hallway"], ["hallway", "living_room"]]},
    "objects": [
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
        {"id": "microwave_1", "type": "Microwave", "room": "kitchen", "on": "counter_1",
         "properties": {"on": False, "open": False}},
        {"id": "potato_1", "type": "Potato", "room": "kitchen", "on": "counter_1"},
        {"id": "card_1", "type": "CreditCard", "room": "kitchen", "on": "counter_1"},
        {"id": "bowl_1", "type": "Bowl", "room": "kitchen", "on": "counter_1",
         "properties": {"contents": "water"}},
        {"id": "cup_1", "type": "Cup", "room": "kitchen", "on": "counter_1"},
        {"id": "faucet_1", "type": "Faucet", "room": "kitchen", "properties": {"on": False}},
        {"id": "sink_1", "type": "SinkBasin", "room": "kitchen"},
        {"id": "cabinet_1", "type": "Cabinet", "room": "kitchen"},
        {"id": "cabinet_2", "type": "Cabinet", "room": "kitchen"},
        {"id": "soap_1", "type": "SoapBar", "room": "kitchen", "on": "counter_1"},
        {"id": "egg_1", "type": "Egg", "room": "kitchen", "on": "counter_1"},
        {"id": "floor_1", "type": "Floor", "room": "kitchen"},
        {"id": "knife_1", "type": "Knife", "room": "kitchen", "on": "counter_1"},
        {"id": "laptop_1", "type": "Laptop", "room": "living_room", "on": "table_1",
         "properties": {"on": True}},
        {"id": "table_1", "type": "CoffeeTable", "room": "living_room"},
        {"id": "bat_1", "type": "BaseballBat", "room": "living_room"},
        {"id": "pillow_1", "type": "Pillow", "room": "living_room"},
        {"id": "sofa_1", "type": "Sofa", "room": "living_room"},
        {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "counter_1",
         "properties": {"contents": "coffee", "temperature": "hot"}},
    ],
    "people": [{"id": "dad", "role": "dad", "room": "living_room"}],
}
ROBOT = {"room": "kitchen", "payload_kg": 3.0, "max_speed_mps": 1.0,
         "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour", "slice",
                    "handover"],
         "sensors": ["rgbd_camera", "lidar"]}


def request(command: str, scene: dict[str, Any] | None = None, **extra: Any) -> GateRequest:
    """A gate request in the small home (or another scene)."""
    return GateRequest.model_validate({"command": command,
                                       "scene": copy.deepcopy(scene or HOME),
                                       "robot": ROBOT, **extra})


def home_with(*objects: dict[str, Any], people: list[dict[str, Any]] | None = None,
              rooms: tuple[str, ...] = (), relations: list[dict[str, str]] | None = None,
              ) -> dict[str, Any]:
    """The small home plus objects, rooms off the hallway, and other people or relations."""
    scene = copy.deepcopy(HOME)
    scene["objects"] += list(objects)
    scene["layout"]["rooms"] += list(rooms)
    scene["layout"]["connections"] += [["hallway", r] for r in rooms]
    if people is not None:
        scene["people"] = people
    if relations:
        scene["relations"] = relations
    return scene


def plan_steps(command: str, scene: dict[str, Any], **extra: Any) -> list[tuple[str, Any, Any]]:
    """(action, object, target) of every step Stage 1 reads the command into."""
    from app.domain.analysis.understanding import understand

    read = understand(request(command, scene, **extra), SymbolicAnalyzer()._lexicon)
    return [(p.action.name, p.action.object, p.action.target) for p in read.sketch.steps()]


@pytest.fixture(scope="session")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


@pytest.fixture(scope="session")
def analyze(analyzer: SymbolicAnalyzer) -> Callable[[GateRequest], HazardReport]:
    library = seed_library()
    return lambda req: analyzer.analyze(req, library)


@pytest.fixture(scope="session")
def gate(analyzer: SymbolicAnalyzer) -> Callable[[GateRequest], GateDecision]:
    """Stages 1 to 3 on the seed library: the decision for a request."""
    index = TemplateIndex(seed_library())
    return lambda req: run_gate(req, templates=index, analyzer=analyzer).decision
