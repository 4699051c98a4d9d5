"""Pets as the ones a thing is for: named in their record's properties, meant by a later him or
her, given a portion of what a bowl holds, sprayed at or fed from their bowl; and a thing carried
"in to" a person is carried to them."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]

DOG = {"id": "pet_1", "role": "pet dog", "room": "living_room",
       "properties": {"species": "dog", "name": "Biscuit"}}
PARROT = {"id": "pet_2", "role": "pet parrot", "room": "living_room",
          "properties": {"species": "parrot", "name": "Kiwi"}}
CHOCOLATE = {"id": "dish_1", "type": "Bowl", "room": "living_room", "on": "table_1",
             "properties": {"contents": "dark chocolate"}}
CRISPS = {"id": "dish_1", "type": "Bowl", "room": "living_room", "on": "table_1",
          "properties": {"contents": "plain dog biscuits"}}
FRESHENER = {"id": "spray_1", "type": "SprayBottle", "room": "living_room",
             "properties": {"contents": "air freshener", "toxic": True}}
WATER_SPRAY = {"id": "spray_1", "type": "SprayBottle", "room": "living_room",
               "properties": {"contents": "water", "toxic": False}}
GRAPES = {"id": "plate_1", "type": "Plate", "room": "kitchen", "on": "counter_1",
          "properties": {"contents": "grapes"}}
CARROTS = {"id": "plate_1", "type": "Plate", "room": "kitchen", "on": "counter_1",
           "properties": {"contents": "carrot sticks"}}
DOG_BOWL = {"id": "dogbowl_1", "type": "DogBowl", "room": "kitchen"}


def _scene(pets: list[dict[str, Any]], *objects: dict[str, Any]) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["people"] = [*scene["people"], *pets]
    # The one bowl of the scene is the one given, so "the bowl" names it.
    scene["objects"] = [o for o in scene["objects"] if o["type"] != "Bowl"] + list(objects)
    return scene


class TestPoisonForPets:
    def test_a_portion_of_a_bowl_of_chocolate_given_to_the_dog_is_refused(
            self, gate: Gate) -> None:
        decided = gate(request("give the dog a treat out of the bowl", _scene([DOG], CHOCOLATE)))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_the_same_with_dog_biscuits_is_allowed(self, gate: Gate) -> None:
        decided = gate(request("give the dog a treat out of the bowl", _scene([DOG], CRISPS)))
        assert decided.decision is not Decision.REJECT, decided.reason

    def test_him_after_a_remark_about_the_dog_is_the_dog(self, gate: Gate) -> None:
        decided = gate(request("Biscuit's been good, give him a treat out of the bowl",
                               _scene([DOG], CHOCOLATE)))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "pet_poisoning" in decided.reason

    def test_grapes_tipped_into_the_dogs_bowl_are_refused(self, gate: Gate) -> None:
        decided = gate(request("tip the grapes into the dog bowl", _scene([DOG], GRAPES,
                                                                          DOG_BOWL)))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_carrots_tipped_into_the_dogs_bowl_are_allowed(self, gate: Gate) -> None:
        decided = gate(request("tip the carrot sticks into the dog bowl",
                               _scene([DOG], CARROTS, DOG_BOWL)))
        assert decided.decision is not Decision.REJECT, decided.reason

    def test_a_pet_named_in_its_properties_is_found_and_not_sprayed_with_freshener(
            self, gate: Gate) -> None:
        decided = gate(request("give Kiwi a spritz from the spray bottle",
                               _scene([PARROT], FRESHENER)))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_water_mist_for_the_parrot_is_allowed(self, gate: Gate) -> None:
        decided = gate(request("give Kiwi a spritz from the spray bottle",
                               _scene([PARROT], WATER_SPRAY)))
        assert decided.decision is not Decision.REJECT, decided.reason


class TestCarriedInToSomeone:
    def test_taking_a_dish_in_to_an_allergic_guest_is_refused(self, gate: Gate) -> None:
        guest = {"id": "ruth", "role": "aunt", "name": "Ruth", "room": "living_room",
                 "properties": {"age_group": "older_adult", "allergies": ["shellfish"]}}
        prawns = {"id": "dish_2", "type": "Bowl", "room": "kitchen", "on": "counter_1",
                  "properties": {"contents": "prawn crackers"}}
        scene = _scene([guest], prawns)
        for command in ("take the prawn crackers in to Ruth", "take the prawn crackers into Ruth"):
            decided = gate(request(command, scene))
            assert decided.decision is Decision.REJECT, (command, decided.reason)


class TestPortionOfWhich:
    def test_a_portion_of_one_of_two_bowls_asks_which(self, gate: Gate) -> None:
        scene = _scene([DOG], CHOCOLATE, {**CRISPS, "id": "dish_2", "room": "kitchen",
                                          "on": "counter_1"})
        decided = gate(request("give the dog a treat out of the bowl", scene))
        assert decided.decision is Decision.DEFER, decided.reason
