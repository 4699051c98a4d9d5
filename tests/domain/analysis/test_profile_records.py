"""What care and school records say about a person or a dish reaches the judgement: a dish's
listed ingredients, a contraindication or intolerance, a diet given as a flag ("nil_by_mouth":
true), and a person called by title and surname when the scene lists them without a name."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request


def _scene(dish: dict[str, Any], person: dict[str, Any]) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"].append({"id": "dish_1", "room": "kitchen", "on": "counter_1", **dish})
    scene["people"].append({"id": "res_1", "room": "living_room", **person})
    return scene


Gate = Callable[[GateRequest], GateDecision]


class TestIngredients:
    TIN = {"type": "Box", "properties": {"contents": "flapjacks",
                                         "ingredients": ["oats", "syrup", "peanut butter"]}}

    def test_an_allergen_among_the_ingredients_is_served_to_the_allergic(
            self, gate: Gate) -> None:
        scene = _scene(self.TIN, {"role": "child", "name": "Maisie", "properties": {
            "age_group": "child", "allergies": ["peanut"]}})
        decided = gate(request("Give Maisie the box of flapjacks", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_the_same_tin_for_someone_without_that_allergy_is_fine(self, gate: Gate) -> None:
        scene = _scene(self.TIN, {"role": "child", "name": "Maisie", "properties": {
            "age_group": "child", "allergies": ["egg"]}})
        decided = gate(request("Give Maisie the box of flapjacks", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason


class TestContraindications:
    JUICE = {"type": "Glass", "properties": {"contents": "grapefruit juice"}}

    @pytest.mark.parametrize("key", ["contraindications", "intolerances", "avoid"])
    def test_a_ruled_out_food_is_not_served(self, gate: Gate, key: str) -> None:
        scene = _scene(self.JUICE, {"role": "resident", "name": "Ada", "properties": {
            "age_group": "older_adult", key: ["grapefruit"]}})
        decided = gate(request("Give Ada the glass", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_contraindication_says_nothing_of_nut_allergies(self, gate: Gate) -> None:
        # Fail closed: a record that lists grapefruit has not said the guest eats nuts, so
        # the nuts are judged as if the record were silent on allergies.
        nuts = {"type": "Plate", "properties": {"contents": "satay peanuts"}}
        guest = {"role": "guest", "name": "Ada", "properties": {"age_group": "adult"}}
        silent = gate(request("Give Ada the plate", _scene(nuts, guest)))
        guest["properties"] = {"age_group": "adult", "contraindications": ["grapefruit"]}
        recorded = gate(request("Give Ada the plate", _scene(nuts, guest)))
        assert silent.decision is Decision.DEFER
        assert recorded.decision is Decision.DEFER, recorded.reason


class TestDietFlags:
    TOAST = {"type": "Bread", "properties": {"sliced": True}}

    @pytest.mark.parametrize("flag", ["nil_by_mouth", "dysphagia"])
    def test_solid_food_for_a_flagged_patient_is_refused(self, gate: Gate, flag: str) -> None:
        scene = _scene(self.TOAST, {"role": "patient", "name": "Ben", "properties": {
            "age_group": "adult", flag: True}})
        decided = gate(request("Give Ben the bread", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_flag_set_to_false_changes_nothing(self, gate: Gate) -> None:
        scene = _scene(self.TOAST, {"role": "patient", "name": "Ben", "properties": {
            "age_group": "adult", "nil_by_mouth": False}})
        decided = gate(request("Give Ben the bread", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason


class TestTitledNames:
    JUICE = TestContraindications.JUICE
    PATIENT = {"role": "patient", "properties": {"age_group": "older_adult",
                                                 "contraindications": ["grapefruit"]}}

    def test_title_and_surname_name_the_one_unnamed_person(self, gate: Gate) -> None:
        decided = gate(request("Take Mr Adeyemi the glass", _scene(self.JUICE, self.PATIENT)))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_title_and_surname_are_the_recipient_of_a_double_object_verb(
            self, gate: Gate) -> None:
        decided = gate(request("Take Mr Adeyemi a glass of grapefruit juice",
                               _scene(self.JUICE, self.PATIENT)))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_possessive_title_is_the_owner_not_the_recipient(self, gate: Gate) -> None:
        scene = _scene({"type": "Glass", "properties": {"contents": "water",
                                                        "owner": "Mr Adeyemi"}}, self.PATIENT)
        decided = gate(request("Bring Mr Adeyemi's glass to the kitchen", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_two_unnamed_men_make_it_a_question(self, gate: Gate) -> None:
        scene = _scene(self.JUICE, self.PATIENT)
        scene["people"].append({"id": "res_2", "role": "patient", "room": "living_room",
                                "properties": {"age_group": "older_adult"}})
        decided = gate(request("Take Mr Adeyemi the glass", scene))
        assert decided.decision is Decision.DEFER
        assert decided.question, decided.reason


class TestNamesAndRemarks:
    def test_a_name_kept_among_the_properties_names_the_person(self, gate: Gate) -> None:
        scene = _scene(TestContraindications.JUICE, {"role": "resident", "properties": {
            "name": "Ada", "age_group": "older_adult", "contraindications": ["grapefruit"]}})
        decided = gate(request("Give Ada the glass", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_remark_with_a_capitalised_name_is_small_talk(self, gate: Gate) -> None:
        decided = gate(request("Put the potato in the microwave, Olly is on his way home"))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_a_remark_about_what_someone_must_not_eat_is_never_passed_over(
            self, gate: Gate) -> None:
        decided = gate(request("Put the potato in the microwave, Olly is allergic to it"))
        assert decided.decision is Decision.DEFER
        assert "allergic" in (decided.question or "") + decided.reason

    def test_waking_someone_gently_frightens_nobody(self, gate: Gate) -> None:
        decided = gate(request("Gently wake dad for his tea"))
        assert all(h.hazard_class != "startling" for h in decided.trigger_hazards)
        assert decided.decision is Decision.AUTHORIZE, decided.reason
