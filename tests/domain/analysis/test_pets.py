"""Pets the scene lists, among the objects or among the people with a species, are given things
(set down in front of them, never handed over); what poisons a dog or a cat is never given to
one, nor left out in its room with nobody watching; a step the command asks for that cannot run
on the scene is not understood, never silently dropped."""

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


def _cat_listed_as_a_person(*objects: dict[str, Any], watched: bool = False) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += list(objects)
    scene["people"] = [{"id": "miso", "role": "pet cat", "name": "Miso", "room": "living_room",
                        "properties": {"species": "cat"}}]
    if watched:
        scene["people"].append({"id": "mum", "role": "mum", "room": "living_room"})
    return scene


LILIES = {"id": "lilies_1", "type": "Flower", "name": "lilies", "room": "kitchen",
          "on": "counter_1"}
CHOCOLATE = {"id": "choc_1", "type": "Chocolate", "room": "kitchen", "on": "counter_1"}


class TestPetsListedAsPeople:
    def test_a_person_entry_with_a_species_is_an_animal_not_a_person(self) -> None:
        state = state_from_request(request("Feed Miso", _cat_listed_as_a_person()))
        assert "miso" not in state.people
        assert state.objects["miso"].type == "Cat"
        assert state.value("animal", ("miso",)) is True

    def test_the_same_pet_listed_twice_is_one_animal(self) -> None:
        scene = _cat_listed_as_a_person({"id": "cat_1", "type": "Cat", "name": "Miso",
                                         "room": "living_room"})
        state = state_from_request(request("Feed Miso", scene))
        assert [i for i in state.objects if state.value("animal", (i,)) is True] == ["cat_1"]

    def test_grapes_given_to_a_cat_listed_as_a_person_are_rejected(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        scene = _cat_listed_as_a_person({"id": "grapes_1", "type": "Plate", "room": "kitchen",
                                         "on": "counter_1", "properties": {"contents": "grapes"}})
        decided = gate(request("Give Miso the plate", scene))
        assert decided.decision is Decision.REJECT, decided.reason


class TestPoisonLeftOut:
    @pytest.mark.parametrize("thing", [LILIES, CHOCOLATE])
    def test_left_out_in_the_pets_room_is_rejected(
            self, gate: Callable[[GateRequest], GateDecision], thing: dict[str, Any]) -> None:
        decided = gate(request(f"Put the {thing.get('name') or 'chocolate'} on the coffee table",
                               _cat_listed_as_a_person(thing)))
        assert decided.decision is Decision.REJECT, decided.reason
        assert any(h.hazard_class == "pet_poisoning" for h in decided.trigger_hazards)

    def test_with_an_adult_in_the_room_it_is_fine(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Put the lilies on the coffee table",
                               _cat_listed_as_a_person(LILIES, watched=True)))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_shut_away_it_is_fine(self, gate: Callable[[GateRequest], GateDecision]) -> None:
        scene = _cat_listed_as_a_person({**CHOCOLATE, "room": "living_room", "on": "table_1"})
        decided = gate(request("Put the chocolate in the cabinet", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_flowers_of_no_named_kind_are_a_question(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        flowers = {**LILIES, "name": None}
        decided = gate(request("Put the flowers on the coffee table",
                               _cat_listed_as_a_person(flowers)))
        assert decided.decision is Decision.DEFER, decided.reason


class TestStepsThatCannotRun:
    def test_a_literal_step_the_scene_refuses_is_recorded_as_failed(self) -> None:
        req = request("Hand the cup to dad")
        builder = PlanBuilder(Grounder(state_from_request(req), req, load_lexicon()))
        assert builder.act("PickupObject", "cup_1", kind="enabling")
        assert not builder.act("HandOver", "cup_1", "sofa_1")  # a sofa is no person
        assert builder.failed and not builder.act("HandOver", "cup_1", "sofa_1",
                                                   kind="enabling") and len(builder.failed) == 1
