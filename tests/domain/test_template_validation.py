"""Template validation in the pure domain: schema, language, Z3 meaning, duplicates, skeleton."""

from __future__ import annotations

from typing import Any

import pytest

from app.domain.models import (
    Category,
    Confidence,
    HazardProposal,
    HazardTemplate,
    Level,
    Preventability,
    Severity,
)
from app.domain.template_validation import class_conflict, suggest_template, validate_template


def document(**changes: Any) -> dict[str, Any]:
    base: dict[str, Any] = {
        "id": "thermal.iron_near_child",
        "name": "Hot iron near a child",
        "category": "physical",
        "hazard_class": "thermal_burn",
        "description": "A hot iron burns a child who touches it.",
        "severity": "high",
        "preventability": "preventable",
        "variables": [{"name": "obj", "type": "object"},
                      {"name": "max_speed", "type": "number", "default": 0.3}],
        "invariants": [{"id": "slow_with_iron", "description": "slow",
                        "formula": "holding(robot, $obj) -> speed(robot) <= $max_speed"}],
        "guards": [{"id": "no_hot_handover", "action": "HandOver", "description": "cool first",
                    "formula": "@object != $obj or not hot($obj)"}],
    }
    base.update(changes)
    return base


def codes(verdict: Any) -> list[str]:
    return [issue.code for issue in verdict.errors]


class TestValidateTemplate:
    def test_a_sound_template_is_valid(self) -> None:
        verdict = validate_template(document())
        assert verdict.ok and verdict.template is not None

    def test_unknown_field_is_an_error(self) -> None:
        verdict = validate_template(document(invariant=[]))
        assert verdict.errors[0].field == "body.invariant"

    def test_server_fields_are_ignored(self) -> None:
        assert validate_template(document(version=7, status="active", author="x")).ok

    def test_id_needs_a_family_prefix(self) -> None:
        assert "id" in codes(validate_template(document(id="iron")))

    def test_guard_action_must_be_canonical(self) -> None:
        guard = {"id": "g", "action": "give", "formula": "not hot($obj)", "description": "d"}
        verdict = validate_template(document(guards=[guard]))
        assert verdict.errors[0].field == "body.guards.0.action"
        assert "HandOver" in verdict.errors[0].message

    def test_number_variable_needs_a_default(self) -> None:
        variables = [{"name": "obj", "type": "object"}, {"name": "max_speed", "type": "number"}]
        assert "missing_default" in codes(validate_template(document(variables=variables)))

    def test_syntax_error_has_line_and_column(self) -> None:
        invariant = {"id": "i", "description": "d", "formula": "hot($obj) and\n  and cold"}
        issue = validate_template(document(invariants=[invariant])).errors[0]
        assert (issue.code, issue.line) == ("syntax", 2)

    def test_undeclared_variable_is_a_type_error(self) -> None:
        invariant = {"id": "i", "description": "d", "formula": "not hot($pan)"}
        issue = validate_template(document(invariants=[invariant])).errors[0]
        assert (issue.code, issue.column) == ("type", 9)

    def test_action_argument_outside_a_guard_is_refused(self) -> None:
        abort = {"id": "a", "description": "d", "formula": "hot(@object)"}
        assert validate_template(document(aborts=[abort])).errors[0].code == "type"

    def test_contradictory_invariants_are_named(self) -> None:
        invariants = [
            {"id": "hot", "description": "d", "formula": "hot($obj)"},
            {"id": "slow", "description": "d", "formula": "speed(robot) <= 1"},
            {"id": "cold", "description": "d", "formula": "not hot($obj)"},
        ]
        issue = validate_template(document(invariants=invariants)).errors[0]
        assert issue.code == "contradiction"
        assert "'hot'" in issue.message and "'cold'" in issue.message
        assert "'slow'" not in issue.message

    def test_guard_that_never_passes_is_an_error(self) -> None:
        guard = {"id": "g", "action": "HandOver", "description": "d",
                 "formula": "hot($obj) and not hot($obj)"}
        assert codes(validate_template(document(guards=[guard]))) == ["unsatisfiable_guard"]

    def test_abort_implied_by_the_invariants_is_an_error(self) -> None:
        invariants = [{"id": "hot", "description": "d", "formula": "hot($obj)"}]
        abort = {"id": "a", "description": "d", "formula": "hot($obj)"}
        verdict = validate_template(document(invariants=invariants, aborts=[abort]))
        assert codes(verdict) == ["valid_abort"]

    def test_unused_variable_is_only_a_warning(self) -> None:
        variables = [{"name": "obj", "type": "object"}, {"name": "person", "type": "person"},
                     {"name": "max_speed", "type": "number", "default": 0.3}]
        verdict = validate_template(document(variables=variables))
        assert verdict.ok
        assert "unused_variable" in [w.code for w in verdict.warnings]

    def test_duplicate_class_and_condition_are_warnings(self) -> None:
        existing = HazardTemplate.model_validate(document(id="thermal.other"))
        verdict = validate_template(document(), library=[existing])
        assert verdict.ok
        warned = [w.code for w in verdict.warnings]
        assert "duplicate_class" in warned and "duplicate_condition" in warned

    def test_a_revision_does_not_duplicate_itself(self) -> None:
        itself = HazardTemplate.model_validate(document())
        assert validate_template(document(), library=[itself]).warnings == ()


class TestClassConflict:
    def test_contradicting_the_class_is_reported(self) -> None:
        hot = [{"id": "hot", "description": "d", "formula": "hot($obj)"}]
        cold = [{"id": "cold", "description": "d", "formula": "not hot($obj)"}]
        mine = HazardTemplate.model_validate(document(invariants=hot, guards=[]))
        theirs = HazardTemplate.model_validate(document(id="thermal.b", invariants=cold))
        issue = class_conflict(mine, [theirs], 2000)
        assert issue is not None and "thermal.b" in issue.message
        assert class_conflict(mine, [], 2000) is None


class TestSuggestTemplate:
    @pytest.fixture
    def proposal(self) -> HazardProposal:
        return HazardProposal(
            level=Level.USER, category=Category.PHYSICAL, hazard_class="thermal_burn",
            mechanism="a hot pan touched", entities={"obj": "pan_1", "person": "p1"},
            severity=Severity.HIGH, preventability=Preventability.PREVENTABLE,
            confidence=Confidence.CERTAIN,
        )

    def test_skeleton_needs_only_conditions(self, proposal: HazardProposal) -> None:
        skeleton = suggest_template(proposal)
        assert [i.code for i in validate_template(skeleton).errors] == ["no_condition"]
        assert {v["name"]: v["type"] for v in skeleton["variables"]} == {
            "obj": "object", "person": "person"}

    def test_skeleton_takes_the_family_and_a_free_id(self, proposal: HazardProposal) -> None:
        existing = HazardTemplate.model_validate(document(id="thermal.thermal_burn"))
        assert suggest_template(proposal, [existing])["id"] == "thermal.thermal_burn_2"
