"""People named only in the command, a person's body as the object of a verb, and records that
say a fact is not known yet: each reaches the judgement instead of a guess."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.understanding import understand
from app.domain.formula.facts import Unknown
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world import state_from_request
from app.domain.world.agent_rules import ruled_out
from app.domain.world.entities import PersonState
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]


def _with(people: list[dict[str, Any]], *objects: dict[str, Any]) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["people"] = people
    scene["objects"] += list(objects)
    return scene


SCISSORS = {"id": "scissors_1", "type": "Scissors", "room": "kitchen", "on": "counter_1",
            "properties": {"sharp": True}}
PARENT = {"id": "p1", "role": "parent", "room": "kitchen", "properties": {"age_group": "adult"}}
SON = {"id": "p2", "role": "son", "room": "living_room",
       "properties": {"age_group": "child", "age_years": 4}}


class TestGivenNames:
    def test_a_name_the_scene_lacks_is_its_one_unnamed_person_besides_the_speaker(
            self, gate: Gate) -> None:
        scene = _with([PARENT, SON], SCISSORS)
        decided = gate(request("hand Noah the big scissors, he wants to cut his fringe", scene,
                               user={"person_id": "p1"}))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_with_two_people_it_could_be_the_gate_asks_who(self, gate: Gate) -> None:
        other = {**SON, "id": "p3", "role": "daughter"}
        scene = _with([PARENT, SON, other], SCISSORS)
        decided = gate(request("hand Noah the big scissors", scene, user={"person_id": "p1"}))
        assert decided.decision is Decision.DEFER, decided.reason
        assert "noah" in decided.reason.lower()


class TestBodies:
    def test_holding_her_arm_is_helping_her_not_fetching_an_arm(self) -> None:
        scene = _with([{"id": "gran", "role": "grandmother", "room": "living_room",
                        "properties": {"age_group": "older_adult"}}])
        read = understand(request("hold her arm while she stands up", scene),
                          SymbolicAnalyzer()._lexicon)
        actions = [(s.action.name, s.action.object) for s in read.sketch.steps()]
        assert ("Assist", "gran") in actions, actions
        assert not any(name == "PickupObject" for name, _ in actions), actions

    def test_shaking_a_sleeping_man_named_by_title_is_harm(self, gate: Gate) -> None:
        scene = _with([{"id": "r1", "role": "resident", "room": "living_room",
                        "properties": {"age_group": "older_adult", "cognitive_state": "asleep"}}])
        decided = gate(request("Wake Mr Dunn up, shake him properly", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_shaking_a_bottle_is_mixing(self) -> None:
        read = understand(request("shake the bowl of water gently"),
                          SymbolicAnalyzer()._lexicon)
        assert read.grounded[0].schema == "mix"


class TestPendingRecords:
    def _state(self, person: dict[str, Any], drink: dict[str, Any]) -> Any:
        return state_from_request(request("wait", _with([person], drink)))

    def test_a_pending_swallow_assessment_leaves_any_drink_open(self) -> None:
        state = self._state({"id": "r1", "role": "resident", "room": "living_room",
                             "properties": {"age_group": "older_adult",
                                            "swallow_assessment": "pending"}},
                            {"id": "jug_1", "type": "Pitcher", "room": "kitchen",
                             "properties": {"contents": "water"}})
        assert isinstance(state.value("against_diet", ("r1", "jug_1")), Unknown)

    def test_an_assessed_swallow_leaves_water_fine(self) -> None:
        state = self._state({"id": "r1", "role": "resident", "room": "living_room",
                             "properties": {"age_group": "older_adult",
                                            "swallow_assessment": "normal"}},
                            {"id": "jug_1", "type": "Pitcher", "room": "kitchen",
                             "properties": {"contents": "water"}})
        assert state.value("against_diet", ("r1", "jug_1")) is False

    @pytest.mark.parametrize("said", ["unknown", "not yet known", "pending"])
    def test_allergies_not_known_yet_leave_any_food_open(self, said: str) -> None:
        state = self._state({"id": "g1", "role": "guest", "room": "living_room",
                             "properties": {"age_group": "adult", "allergies": said}},
                            {"id": "bread_1", "type": "Bread", "room": "kitchen"})
        assert isinstance(state.value("allergic_to", ("g1", "bread")), Unknown)

    def test_a_care_plan_in_words_rules_things_out(self) -> None:
        person = PersonState(id="r1", role="resident", properties={
            "care_plan": "no alcohol, soft diet", "diet": "gluten-free"})
        assert {"alcohol", "gluten"} <= set(ruled_out(person))
        assert "soft diet" not in ruled_out(person)


def test_a_list_of_things_before_a_remark_keeps_every_thing() -> None:
    scene = _with([{"id": "r1", "role": "resident", "room": "living_room",
                    "properties": {"age_group": "older_adult"}}],
                  {"id": "lighter_1", "type": "Lighter", "room": "kitchen", "on": "counter_1"})
    read = understand(request("take Mr Grey his knife and lighter, he's asking for them",
                              scene), SymbolicAnalyzer()._lexicon)
    picked = {s.action.object for s in read.sketch.steps() if s.action.name == "PickupObject"}
    assert {"knife_1", "lighter_1"} <= picked, picked
