"""What a remark names is what the next order's "it" means ("I think I left the hob on, can
you turn it off"), by the word for its kind when the scene calls it something else; and a place
named after a destination only says which one ("out to the big bin by the gate")."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.understanding import understand
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request


def _kitchen_with_hob() -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"].append({"id": "burner_1", "type": "StoveBurner", "room": "kitchen",
                             "properties": {"on": True}})
    return scene


class TestRemarkAntecedents:
    def test_it_is_the_thing_the_remark_named_by_its_kind(self) -> None:
        read = understand(request("i think i left the hob on, can you turn it off",
                                  _kitchen_with_hob()), load_lexicon())
        assert not [u for u in read.unknowns if u.critical]
        assert [(s.action.name, s.action.object) for s in read.sketch.steps()][-1] == (
            "ToggleObjectOff", "burner_1")

    def test_a_kind_with_two_objects_in_the_scene_names_neither(self) -> None:
        scene = _kitchen_with_hob()
        scene["objects"].append({"id": "burner_2", "type": "StoveBurner", "room": "kitchen"})
        read = understand(request("i think i left the hob on, can you turn it off", scene),
                          load_lexicon())
        assert [u for u in read.unknowns if u.critical]


class TestWhichDestination:
    def test_a_place_after_the_destination_only_says_which_one(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        scene = copy.deepcopy(HOME)
        scene["objects"] += [
            {"id": "bag_1", "type": "GarbageBag", "room": "kitchen", "on": "floor_1",
             "properties": {"mass_kg": 1.0}},
            {"id": "bin_big", "type": "GarbageCan", "name": "big bin", "room": "hallway"},
            {"id": "gate_1", "type": "Gate", "room": "hallway"}]
        read = understand(request("take the bag out to the big bin by the gate", scene),
                          load_lexicon())
        put = [s.action for s in read.sketch.steps() if s.action.name == "PutObject"]
        assert put and put[-1].target == "bin_big"
        decided = gate(request("take the bag out to the big bin by the gate", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason
