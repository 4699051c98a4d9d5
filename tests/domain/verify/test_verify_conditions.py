"""Stage 5 per condition kind: invariants, guards, aborts, action preconditions."""

from __future__ import annotations

import pytest
from verify_kit import PICK_KNIFE, contract, kitchen

from app.domain.verify import CheckKind, verify_plan

TIMEOUT_MS = 5000


class TestInvariants:
    def test_invariant_kept_in_every_state_passes(self) -> None:
        result = verify_plan(PICK_KNIFE, contract(invariants=("not holding(robot, #mug_1)",)),
                             kitchen(), timeout_ms=TIMEOUT_MS)
        assert result.ok, result
        assert result.states_checked == len(PICK_KNIFE) + 1

    def test_invariant_broken_after_an_action_names_that_step(self) -> None:
        result = verify_plan(PICK_KNIFE, contract(invariants=("not holding(robot, #knife_1)",)),
                             kitchen(), timeout_ms=TIMEOUT_MS)
        assert not result.ok
        [violation] = result.violations
        assert (violation.kind, violation.step, violation.state) == (CheckKind.INVARIANT, 1, 2)
        assert violation.action == {"action": "PickupObject", "object": "knife_1"}
        assert violation.condition_id == "inv0"
        assert violation.formula == "not holding(robot, #knife_1)"
        assert violation.counterexample == {"holding(robot,knife_1)": True}

    def test_invariant_broken_in_the_initial_state(self) -> None:
        result = verify_plan(PICK_KNIFE, contract(invariants=("same_room(robot, #tom)",)),
                             kitchen(), timeout_ms=TIMEOUT_MS)
        [violation] = result.violations
        assert (violation.state, violation.action) == (0, None)

    def test_each_invariant_is_reported_once_at_its_first_violation(self) -> None:
        plan = [{"action": "PickupObject", "object": "knife_1"}, {"action": "Wait"},
                {"action": "Wait"}]
        result = verify_plan(plan, contract(invariants=("not holding(robot, #knife_1)",)),
                             kitchen(), timeout_ms=TIMEOUT_MS)
        assert [v.state for v in result.violations] == [1]


class TestGuards:
    def test_guard_is_checked_in_the_state_before_its_action(self) -> None:
        # True before the pickup, false after it: a check after the action would fail.
        guards = (("PickupObject", "on(@object, #counter_1)"),)
        result = verify_plan(PICK_KNIFE, contract(guards=guards), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert result.ok, result

    def test_guard_broken_reports_the_action_with_its_arguments(self) -> None:
        guards = (("PickupObject", "@object != #mug_1 or not hot(#mug_1)"),)
        plan = [{"action": "pick", "object": "mug_1"}]
        result = verify_plan(plan, contract(guards=guards), kitchen(), timeout_ms=TIMEOUT_MS)
        [violation] = result.violations
        assert violation.kind is CheckKind.GUARD
        assert violation.action == {"action": "PickupObject", "object": "mug_1"}
        assert violation.counterexample["hot(mug_1)"] is True

    def test_guard_only_applies_to_its_action(self) -> None:
        guards = (("HandOver", "not holding(robot, #knife_1)"),)
        result = verify_plan(PICK_KNIFE, contract(guards=guards), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert result.ok

    def test_guard_on_other_object_does_not_restrict_this_one(self) -> None:
        guards = (("PickupObject", "@object != #mug_1 or not hot(#mug_1)"),)
        result = verify_plan(PICK_KNIFE, contract(guards=guards), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert result.ok


class TestAborts:
    def test_abort_that_never_holds_passes(self) -> None:
        aborts = ("holding(robot, #knife_1) and same_room(robot, #tom)",)
        result = verify_plan(PICK_KNIFE, contract(aborts=aborts), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert result.ok

    def test_abort_reached_is_a_violation_with_the_state_that_reaches_it(self) -> None:
        aborts = ("holding(robot, #knife_1) and same_room(robot, #ann)",)
        result = verify_plan(PICK_KNIFE, contract(aborts=aborts), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        [violation] = result.violations
        assert (violation.kind, violation.step) == (CheckKind.ABORT, 1)
        assert violation.counterexample == {"holding(robot,knife_1)": True,
                                            "same_room(robot,ann)": True}


class TestPreconditions:
    def test_picking_up_what_is_not_reachable(self) -> None:
        plan = [{"action": "PickupObject", "object": "book_1"}, {"action": "Wait"}]
        result = verify_plan(plan, contract(), kitchen(), timeout_ms=TIMEOUT_MS)
        [violation] = result.violations
        assert violation.kind is CheckKind.PRECONDITION
        assert violation.formula == "near(robot, @object)"
        assert violation.counterexample == {"near(robot,book_1)": False}
        assert result.states_checked == 1  # the trace stops: the action would not run

    def test_putting_down_with_empty_hands(self) -> None:
        plan = [{"action": "PutObject", "object": "mug_1", "target": "table_1"}]
        [violation] = verify_plan(plan, contract(), kitchen(), timeout_ms=TIMEOUT_MS).violations
        assert (violation.kind, violation.formula) == (CheckKind.PRECONDITION,
                                                       "holding(robot, @object)")

    def test_smart_llm_put_with_empty_hands_is_a_precondition_not_a_bad_plan(self) -> None:
        plan = [{"action": "PutObject", "target": "table_1"}]
        [violation] = verify_plan(plan, contract(), kitchen(), timeout_ms=TIMEOUT_MS).violations
        assert violation.kind is CheckKind.PRECONDITION
        assert violation.action == {"action": "PutObject", "target": "table_1"}

    def test_picking_up_with_full_hands(self) -> None:
        plan = [{"action": "PickupObject", "object": "knife_1"},
                {"action": "PickupObject", "object": "mug_1"}]
        [violation] = verify_plan(plan, contract(), kitchen(), timeout_ms=TIMEOUT_MS).violations
        assert (violation.step, violation.description) == (1, "the robot's gripper is empty")

    def test_a_plan_whose_preconditions_hold_passes_an_empty_contract(self) -> None:
        assert verify_plan(PICK_KNIFE, contract(), kitchen(), timeout_ms=TIMEOUT_MS).ok

    @pytest.mark.faults
    def test_an_unknown_precondition_fails_closed(self) -> None:
        # An ordinary thing of a type no table knows: whether it can be picked up is open.
        plan = [{"action": "GoToObject", "object": "widget_1"},
                {"action": "PickupObject", "object": "widget_1"}]
        [violation] = verify_plan(plan, contract(), kitchen(), timeout_ms=TIMEOUT_MS).violations
        assert violation.counterexample == {"pickupable(widget_1)": False}
        assert violation.free == ("pickupable(widget_1)",)
