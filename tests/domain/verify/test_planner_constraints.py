"""The contract as planning constraints: concrete entities, the guarded action, the condition."""

from __future__ import annotations

from verify_kit import condition

from app.domain.contracts import Contract, planner_constraints
from app.domain.models import ConditionKind


def _contract() -> Contract:
    guard = condition(ConditionKind.GUARD, "@object != #knife_1 or not sharp(#knife_1)",
                      action="ThrowObject", id_="sharp.never_throw_blade")
    invariant = condition(ConditionKind.INVARIANT,
                          "holding(robot, #knife_1) -> speed(robot) <= 0.25",
                          id_="sharp.slow_with_blade")
    abort = condition(ConditionKind.ABORT, "holding(#tom, #knife_1)", id_="sharp.child_holds")
    return Contract(
        invariants=(invariant.model_copy(update={"bindings": {"obj": "knife_1",
                                                              "safe_speed": 0.25}}),),
        guards=(guard.model_copy(update={"bindings": {"obj": "knife_1"}}),),
        aborts=(abort,))


class TestPlannerConstraints:
    def test_guard_names_its_action_what_it_does_and_the_entity(self) -> None:
        line = planner_constraints(_contract())[1]
        assert line.startswith("Just before every ThrowObject step (throw the held object)")
        assert "Applies to: knife_1." in line
        assert "@object is that step's object" in line
        assert line.endswith("[sharp.never_throw_blade]")

    def test_invariant_lists_entities_by_id_and_values_by_name(self) -> None:
        line = planner_constraints(_contract())[0]
        assert line.startswith("In every state")
        assert "Applies to: knife_1; safe_speed = 0.25." in line
        assert "Condition: holding(robot, #knife_1) -> speed(robot) <= 0.25" in line

    def test_abort_is_a_stop_condition(self) -> None:
        assert planner_constraints(_contract())[2].startswith("Never let this happen")

    def test_one_line_per_condition_and_a_closing_note(self) -> None:
        lines = planner_constraints(_contract())
        assert len(lines) == 4
        assert "preconditions" in lines[-1] and "does not state" in lines[-1]
