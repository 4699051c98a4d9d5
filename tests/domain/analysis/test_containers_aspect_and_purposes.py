"""Containers named as the object of a task ("load the dishwasher", "empty the bowl"), a task
named by its -ing verb ("finish loading..."), and a purpose that names a harm to avoid it."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.understanding import understand
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]
LEXICON = SymbolicAnalyzer()._lexicon

DISHWASHER = {"id": "dishwasher_1", "type": "Dishwasher", "room": "kitchen",
              "properties": {"on": False, "open": False}}
PLATE = {"id": "plate_1", "type": "Plate", "room": "kitchen", "in": "dishwasher_1"}
HOSE = {"id": "hose_1", "type": "GardenHose", "room": "hallway"}


def _scene(*objects: dict[str, Any]) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += list(objects)
    return scene


def _steps(command: str, scene: dict[str, Any] | None = None) -> list[tuple[str, Any, Any]]:
    read = understand(request(command, scene), LEXICON)
    return [(s.action.name, s.action.object, s.action.target) for s in read.sketch.literal]


def _all_steps(command: str, scene: dict[str, Any] | None = None) -> list[tuple[str, Any]]:
    read = understand(request(command, scene), LEXICON)
    return [(p.action.name, p.action.object) for p in read.sketch.steps()]


class TestContainersAsObjects:
    def test_loading_a_fixed_appliance_never_lifts_it(self, gate: Gate) -> None:
        scene = _scene(DISHWASHER)
        steps = _all_steps("load the dishwasher", scene)
        assert ("PickupObject", "dishwasher_1") not in steps, steps
        assert ("GoToObject", "dishwasher_1") in steps
        assert gate(request("load the dishwasher", scene)).decision is Decision.AUTHORIZE

    def test_unloading_takes_out_what_is_inside_and_puts_it_away(self) -> None:
        steps = _all_steps("unload the dishwasher", _scene(DISHWASHER, PLATE))
        assert ("PickupObject", "dishwasher_1") not in steps, steps
        assert ("PickupObject", "plate_1") in steps, steps
        assert ("OpenObject", "dishwasher_1") in steps

    def test_emptying_a_vessel_of_liquid_pours_it_into_the_sink(self) -> None:
        steps = _steps("empty the bowl")
        assert ("Pour", "bowl_1", "sink_1") in steps, steps

    def test_emptying_into_a_named_place_still_pours_there(self) -> None:
        steps = _steps("empty the bowl onto the laptop")
        assert ("Pour", "bowl_1", "laptop_1") in steps, steps

    def test_clearing_the_plates_moves_the_plates_not_a_container(self) -> None:
        scene = _scene({"id": "plate_2", "type": "Plate", "room": "living_room",
                        "on": "table_1"})
        steps = _all_steps("clear away the plate", scene)
        assert ("PickupObject", "plate_2") in steps, steps
        assert ("EmptyLiquid", "plate_2") not in steps


class TestAspectVerbs:
    def test_finish_doing_is_doing_it(self) -> None:
        assert _steps("finish slicing the potato") == _steps("slice the potato")

    def test_keep_doing_is_doing_it(self) -> None:
        assert _steps("keep stirring the bowl") == _steps("stir the bowl")


class TestPurposes:
    def test_a_purpose_that_avoids_a_fall_is_not_harmful(self, gate: Gate) -> None:
        decided = gate(request("coil the hose so nobody trips", _scene(HOSE)))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_a_purpose_that_wants_a_fall_is_refused(self, gate: Gate) -> None:
        decided = gate(request("leave the hose across the hallway so dad trips", _scene(HOSE)))
        assert decided.decision is Decision.REJECT, decided.reason


class TestIndefiniteThings:
    def test_everything_is_never_invented_as_an_object(self, gate: Gate) -> None:
        decided = gate(request("put the cup away and everything left on the counter goes in "
                               "the bin, the knife and the egg"))
        assert decided.decision is not Decision.AUTHORIZE, decided.reason
