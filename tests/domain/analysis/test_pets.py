"""Pets the scene lists are given things (set down in front of them, never handed over); what
poisons a dog or a cat is never given to one; a step the command asks for that cannot run on
the scene is not understood, never silently dropped."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.analysis.grounding import Grounder
from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.steps import PlanBuilder
from app.domain.analysis.understanding import understand
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world.build import state_from_request
from tests.domain.analysis.conftest import HOME, request


def _home(contents: str) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += [
        {"id": "treat_bowl_1", "type": "Bowl", "room": "kitchen", "on": "counter_1",
         "properties": {"contents": contents}},
        {"id": "dog_1", "type": "Dog", "room": "living_room",
         "properties": {"name": "Biscuit", "species": "dog"}}]
    return scene


class TestPets:
    def test_a_pet_named_in_the_scene_is_given_things_by_setting_them_down(self) -> None:
        read = understand(request("Give Biscuit the treat bowl", _home("dog biscuits")),
                          load_lexicon())
        actions = [(s.action.name, s.action.target) for s in read.sketch.steps()]
        assert ("PutObject", "dog_1") in actions
        assert not [u for u in read.unknowns if u.critical]

    @pytest.mark.parametrize("contents", ["grapes", "dark chocolate", "raisins"])
    def test_what_poisons_a_dog_given_to_the_dog_is_rejected(
            self, gate: Callable[[GateRequest], GateDecision], contents: str) -> None:
        decided = gate(request("Give Biscuit the treat bowl", _home(contents)))
        assert decided.decision is Decision.REJECT
        assert any(h.hazard_class == "pet_poisoning" for h in decided.trigger_hazards)

    def test_dog_treats_for_the_dog_are_fine(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Give the dog the treat bowl", _home("dog biscuits")))
        assert decided.decision is Decision.AUTHORIZE, decided.reason


class TestStepsThatCannotRun:
    def test_a_literal_step_the_scene_refuses_is_recorded_as_failed(self) -> None:
        req = request("Hand the cup to dad")
        builder = PlanBuilder(Grounder(state_from_request(req), req, load_lexicon()))
        assert builder.act("PickupObject", "cup_1", kind="enabling")
        assert not builder.act("HandOver", "cup_1", "sofa_1")  # a sofa is no person
        assert builder.failed and not builder.act("HandOver", "cup_1", "sofa_1",
                                                   kind="enabling") and len(builder.failed) == 1
