"""Stage 4, Contract Compilation (`compile_contract`), called directly: conditions bound on the
parsed formula, sorted by kind, deduplicated by (condition, bindings), the envelope marked, and a
condition that does not type-check refused (fail closed)."""

from __future__ import annotations

from typing import Any

import pytest

from app.domain.binding import BoundHazard, BoundTemplate
from app.domain.contracts import compile_contract, planner_constraints
from app.domain.errors import FormulaError
from app.domain.models import HazardProposal, HazardTemplate
from app.domain.scope import TaskScope

HOT_CARRY = "holding(robot, $obj) and hot($obj) -> speed(robot) <= $carry_speed"
NO_HOT_HANDOVER = "@object != $obj or not hot($obj)"
CHILD_HOLDS_IT = "not (child($person) and holding($person, $obj))"


def template(template_id: str, **fields: Any) -> HazardTemplate:
    return HazardTemplate.model_validate({
        "id": template_id, "name": template_id, "category": "physical",
        "hazard_class": "scald_hot_liquid", "description": "A hazard.", "severity": "high",
        "preventability": "preventable", **fields})


def hot_drink(**changes: Any) -> HazardTemplate:
    return template("thermal.hot_drink", **{
        "variables": [{"name": "obj", "type": "object"}, {"name": "person", "type": "person"},
                      {"name": "carry_speed", "type": "number", "default": 0.3}],
        "invariants": [{"id": "slow_carry", "formula": HOT_CARRY,
                        "description": "Carry it slowly."}],
        "guards": [{"id": "no_handover", "formula": NO_HOT_HANDOVER,
                    "description": "Do not hand it over.", "action": "HandoverObject"}],
        "aborts": [{"id": "child_holds_it", "formula": CHILD_HOLDS_IT,
                    "description": "Halt if a child holds it."}],
        **changes})


BASELINE = template("baseline.speed", invariants=[
    {"id": "cap", "formula": "speed(robot) <= 1.0", "description": "Never faster than 1 m/s."}])


def bound(template: HazardTemplate, **bindings: Any) -> BoundTemplate:
    entities = frozenset(k for k in bindings if k in {"obj", "person"})
    return BoundTemplate(template=template, bindings=bindings, entity_variables=entities)


def hazard(*matches: BoundTemplate) -> BoundHazard:
    proposal = HazardProposal.model_validate({
        "level": "deployment", "category": "physical", "hazard_class": "scald_hot_liquid",
        "mechanism": "hot coffee near a child", "entities": {"obj": "mug_1"},
        "severity": "high", "preventability": "preventable", "confidence": "certain"})
    return BoundHazard(proposal=proposal, matches=matches)


MUG = bound(hot_drink(), obj="mug_1", person="kid", carry_speed=0.3)


class TestCompileContract:
    def test_each_condition_lands_in_its_kind_with_its_template_id(self) -> None:
        contract = compile_contract([hazard(MUG)])
        assert [c.id for c in contract.invariants] == ["thermal.hot_drink.slow_carry"]
        assert [c.id for c in contract.guards] == ["thermal.hot_drink.no_handover"]
        assert [c.id for c in contract.aborts] == ["thermal.hot_drink.child_holds_it"]
        assert contract.guards[0].action == "HandoverObject"
        assert contract.template_versions == {"thermal.hot_drink": 1}
        assert len(contract) == 3

    def test_variables_are_substituted_and_only_used_bindings_kept(self) -> None:
        (invariant,) = compile_contract([hazard(MUG)]).invariants
        assert "$" not in invariant.formula
        assert "#mug_1" in invariant.formula and "0.3" in invariant.formula
        assert invariant.bindings == {"obj": "mug_1", "carry_speed": 0.3}

    def test_the_same_condition_and_bindings_appear_once(self) -> None:
        same = bound(hot_drink(), obj="mug_1", person="kid", carry_speed=0.3)
        other_cup = bound(hot_drink(), obj="cup_2", person="kid", carry_speed=0.3)
        contract = compile_contract([hazard(MUG), hazard(same, other_cup)])
        assert [c.bindings["obj"] for c in contract.invariants] == ["mug_1", "cup_2"]
        # The abort mentions the person too: the same cup and child is one abort.
        assert len(contract.aborts) == 2

    def test_only_baseline_conditions_are_marked_envelope(self) -> None:
        contract = compile_contract([hazard(MUG)], baseline=[bound(BASELINE)])
        envelope = {c.id: c.envelope for c in contract.invariants}
        assert envelope == {"thermal.hot_drink.slow_carry": False, "baseline.speed.cap": True}
        assert contract.template_versions == {"thermal.hot_drink": 1, "baseline.speed": 1}

    def test_the_scope_is_stored_and_no_hazard_leaves_only_the_envelope(self) -> None:
        scope = TaskScope(command="bring the mug")
        contract = compile_contract([], baseline=[bound(BASELINE)], scope=scope)
        assert contract.scope == scope
        assert [c.id for c in contract.conditions] == ["baseline.speed.cap"]

    def test_the_planner_is_told_every_condition(self) -> None:
        contract = compile_contract([hazard(MUG)], baseline=[bound(BASELINE)])
        text = "\n".join(planner_constraints(contract))
        for description in ("Carry it slowly.", "Do not hand it over.", "Halt if a child",
                            "Never faster than 1 m/s."):
            assert description in text

    @pytest.mark.parametrize("formula", ["glows($obj)", "holding(robot, $obj) and",
                                         "hot($carry_speed)"])
    def test_a_condition_that_does_not_check_is_refused(self, formula: str) -> None:
        broken = hot_drink(invariants=[{"id": "broken", "formula": formula,
                                        "description": "broken"}])
        with pytest.raises(FormulaError):
            compile_contract([hazard(bound(broken, obj="mug_1", person="kid",
                                           carry_speed=0.3))])
