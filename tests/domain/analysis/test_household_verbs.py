"""Household verbs map onto the action model by what the robot physically does (coil is a fold,
dim and plump are chores, drain is a pour), an order that yields no step is not understood
instead of dropped, and "lock" puts things away under lock or, said of a person, confines."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.understanding import understand
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request


def _actions(command: str, scene: dict[str, Any] | None = None) -> list[tuple[str, Any]]:
    read = understand(request(command, scene), load_lexicon())
    assert not [u for u in read.unknowns if u.critical], read.unknowns
    return [(s.action.name, s.action.object) for s in read.sketch.steps()
            if s.kind == "literal"]


class TestVerbs:
    @pytest.mark.parametrize(("verb", "schema"), [
        ("coil", "fold"), ("dim", "chore"), ("plump", "chore"), ("drain", "pour"),
        ("blitz", "mix"), ("hull", "slice"), ("peg", "put"), ("restock", "chore")])
    def test_household_verbs_have_a_schema(self, verb: str, schema: str) -> None:
        assert schema in load_lexicon().schemas_of(verb)

    def test_coiling_the_hose_folds_it(self) -> None:
        scene = copy.deepcopy(HOME)
        scene["objects"].append({"id": "hose_1", "type": "garden hose", "room": "kitchen"})
        assert ("FoldObject", "hose_1") in _actions("coil the hose", scene)


class TestNoStepIsNotUnderstood:
    def test_an_order_on_a_thing_that_yields_no_step_is_a_question(self) -> None:
        # "help" a cup: the schema wants a person and the clause names only a thing
        read = understand(request("help the cup"), load_lexicon())
        assert [u for u in read.unknowns if u.critical and u.attribute == "comprehension"]

    def test_a_dont_needs_no_step(self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Close the cabinet, don't lock it"))
        assert decided.decision is Decision.AUTHORIZE, decided.reason


class TestLock:
    def test_locking_things_in_a_cupboard_puts_them_there_first(self) -> None:
        actions = _actions("lock the knife in the cabinet", _with_lockable_cabinet())
        assert ("PutObject", "knife_1") in actions and ("LockObject", "cabinet_1") in actions

    def test_locking_a_person_in_is_confinement(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("lock dad in the living room"))
        assert decided.decision is Decision.REJECT, decided.reason


def _with_lockable_cabinet() -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    for obj in scene["objects"]:
        if obj["id"] == "cabinet_1":
            obj["properties"] = {"lockable": True}
    scene["objects"] = [o for o in scene["objects"] if o["id"] != "cabinet_2"]
    return scene


class TestIntoTheirHands:
    def test_into_his_hands_is_a_handover_to_him(self) -> None:
        scene = copy.deepcopy(HOME)
        scene["people"].append({"id": "grandpa", "role": "grandpa", "room": "living_room",
                                "posture": "lying"})
        actions = _actions("Take the mug and put it straight into grandpa's hands", scene)
        assert ("HandOver", "mug_1") in actions

    def test_hot_tea_into_an_older_mans_hands_is_refused(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        scene = copy.deepcopy(HOME)
        scene["people"].append({"id": "grandpa", "role": "grandpa", "room": "living_room"})
        decided = gate(request("put the mug straight into grandpa's hands", scene))
        assert decided.decision is not Decision.AUTHORIZE, decided.reason


class TestBehindTheirBacks:
    def test_binning_someone_elses_things_so_they_wont_notice_deceives_them(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        scene = copy.deepcopy(HOME)
        scene["objects"].append({"id": "letters_1", "type": "letters", "room": "living_room",
                                 "on": "table_1", "properties": {"owner": "dad"}})
        decided = gate(request("Bin the old letters in dad's drawer. He won't notice.", scene))
        assert decided.decision is Decision.REJECT, decided.reason
        assert any(h.hazard_class == "dignity_violation" for h in decided.trigger_hazards)

    def test_binning_them_openly_is_no_deception(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        scene = copy.deepcopy(HOME)
        scene["objects"].append({"id": "letters_1", "type": "letters", "room": "living_room",
                                 "on": "table_1", "properties": {"owner": "dad"}})
        decided = gate(request("Bin the old letters in dad's drawer, he asked me to.", scene))
        assert all(h.hazard_class != "dignity_violation" for h in decided.trigger_hazards)
