"""Repair: the nearest plan that Stage 5 proves, per kind of edit; fail closed on every path."""

from __future__ import annotations

from typing import Any

import pytest
import z3

from app.domain.planning import RepairBudget, repair_plan
from app.domain.verify import verify_plan
from tests.domain.planning.planning_kit import KNIFE_AWAY, KNIFE_AWAY_SCOPE, contract, kitchen

TIMEOUT_MS = 5000
Plan = list[dict[str, Any]]

THROWN = [*KNIFE_AWAY[:3], {"action": "ThrowObject", "object": "knife_1"}]
NO_THROWING = contract(guards=(("ThrowObject", "false"),))
STOVE_ON = [{"action": "GoToObject", "object": "stove_1"},
            {"action": "ToggleObjectOn", "object": "stove_1"}]
LEAVE_STOVE_OFF = contract(guards=(("Finish", "not is_on(#stove_1)"),))
KEPT_IN_HAND = KNIFE_AWAY[:2]
PUT_DOWN_AT_THE_END = contract(guards=(("Finish", "not holding(robot, #knife_1)"),))
STOVE_DETOUR = [*KNIFE_AWAY[:2], *STOVE_ON, *KNIFE_AWAY[2:]]
FAST_TO_ANN = [{"action": "navigate", "target": "den", "speed": 1.0}]
SLOW_NEAR_PEOPLE = contract(
    invariants=("forall p: person . same_room(robot, p) -> speed(robot) <= 0.3",))
OPEN_HOLDING = KNIFE_AWAY
OPEN_WITH_FREE_HANDS = contract(guards=(("OpenObject", "not holding(robot, #knife_1)"),))
FAR_PICKUP = [{"action": "PickupObject", "object": "book_1"}]

FAILING: list[tuple[str, Plan, Any, str]] = [
    ("throw replaced by a put", THROWN, NO_THROWING, "replace_throw"),
    ("switch-off inserted", STOVE_ON, LEAVE_STOVE_OFF, "insert_switch_off"),
    ("put-away inserted", KEPT_IN_HAND, PUT_DOWN_AT_THE_END, "insert_put_away"),
    ("out-of-scope step dropped", STOVE_DETOUR, contract(scope=KNIFE_AWAY_SCOPE), "drop"),
    ("move slowed down", FAST_TO_ANN, SLOW_NEAR_PEOPLE, "slow_down"),
    ("steps reordered", OPEN_HOLDING, OPEN_WITH_FREE_HANDS, "reorder"),
    ("approach inserted", FAR_PICKUP, contract(), "insert_approach"),
]


class TestRepairEdits:
    @pytest.mark.parametrize(("name", "plan", "rules", "kind"), FAILING,
                             ids=[f[0] for f in FAILING])
    def test_one_edit_repairs_the_plan_and_the_repair_verifies(
            self, name: str, plan: Plan, rules: Any, kind: str) -> None:
        state = kitchen()
        assert not verify_plan(plan, rules, state, timeout_ms=TIMEOUT_MS).ok
        repair = repair_plan(plan, rules, state, timeout_ms=TIMEOUT_MS)
        assert repair.plan is not None, repair.reason
        assert [e.kind for e in repair.edits] == [kind]
        assert repair.verification is not None and repair.verification.ok
        assert verify_plan(list(repair.plan), rules, state, timeout_ms=TIMEOUT_MS).ok

    def test_the_throw_becomes_a_put_where_the_robot_stands(self) -> None:
        repair = repair_plan(THROWN, NO_THROWING, kitchen(), timeout_ms=TIMEOUT_MS)
        assert repair.plan is not None
        assert repair.plan[-1] == {"action": "PutObject", "object": "knife_1",
                                   "target": "drawer_1"}
        assert list(repair.plan[:3]) == THROWN[:3]  # untouched steps stay as sent

    def test_a_move_too_fast_near_people_is_slowed_not_dropped(self) -> None:
        repair = repair_plan(FAST_TO_ANN, SLOW_NEAR_PEOPLE, kitchen(), timeout_ms=TIMEOUT_MS)
        assert repair.plan is not None
        assert repair.plan[0]["target"] == "den" and repair.plan[0]["speed"] <= 0.3

    def test_the_repair_with_fewest_edits_wins(self) -> None:
        # Throwing and leaving the stove on: two faults, two edits, nothing more.
        plan = [*STOVE_ON, *THROWN]
        rules = contract(guards=(("ThrowObject", "false"), ("Finish", "not is_on(#stove_1)")))
        repair = repair_plan(plan, rules, kitchen(), timeout_ms=TIMEOUT_MS)
        assert repair.plan is not None
        assert sorted(e.kind for e in repair.edits) == ["insert_switch_off", "replace_throw"]

    def test_the_verdict_of_stage_5_lets_the_search_skip_the_passed_steps(self) -> None:
        state = kitchen()
        verdict = verify_plan(THROWN, NO_THROWING, state, timeout_ms=TIMEOUT_MS)
        told = repair_plan(THROWN, NO_THROWING, state, timeout_ms=TIMEOUT_MS, failed=verdict)
        alone = repair_plan(THROWN, NO_THROWING, state, timeout_ms=TIMEOUT_MS)
        assert told.plan == alone.plan and told.edits == alone.edits


class TestNoRepair:
    def test_a_contract_no_plan_can_keep_gives_none_with_the_budget(self) -> None:
        repair = repair_plan(KNIFE_AWAY, contract(guards=(("Finish", "false"),)), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert repair.plan is None and repair.edits == ()
        assert "no repair found" in repair.reason and "at most 4 edits" in repair.reason

    def test_a_start_that_breaks_the_contract_cannot_be_repaired(self) -> None:
        repair = repair_plan(KNIFE_AWAY, contract(invariants=("is_on(#stove_1)",)), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert repair.plan is None and "starting state" in repair.reason

    def test_a_spent_search_budget_gives_none(self) -> None:
        plan = [*STOVE_ON, *THROWN]
        rules = contract(guards=(("ThrowObject", "false"), ("Finish", "not is_on(#stove_1)")))
        repair = repair_plan(plan, rules, kitchen(), timeout_ms=TIMEOUT_MS,
                             budget=RepairBudget(max_screens=2))
        assert repair.plan is None and "search budget was spent" in repair.reason
        assert repair.screened == 2


# Whether the pot is lidded is unknown: only the solver settles the guard on putting it down,
# and every repair must put it down (no throw, not held at the end).
SOLVER_ONLY = contract(guards=(("ThrowObject", "false"),
                               ("PutObject", "lidded(@object) or not lidded(@object)"),
                               ("Finish", "not holding(robot, #pot_1)")))
POT_THROWN = [{"action": "GoToObject", "object": "pot_1"},
              {"action": "PickupObject", "object": "pot_1"},
              {"action": "ThrowObject", "object": "pot_1"}]


@pytest.mark.faults
class TestFailsClosed:
    def test_with_a_working_solver_the_repair_is_proved(self) -> None:
        repair = repair_plan(POT_THROWN, SOLVER_ONLY, kitchen(), timeout_ms=TIMEOUT_MS)
        assert repair.plan is not None and repair.plan[-1]["action"] == "PutObject"
        assert repair.verification is not None and repair.verification.solver_calls >= 1

    def test_a_solver_that_cannot_decide_never_yields_a_repair(
            self, monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setattr(z3.Solver, "check", lambda self, *args: z3.unknown)
        monkeypatch.setattr(z3.Solver, "reason_unknown", lambda self: "incomplete")
        repair = repair_plan(POT_THROWN, SOLVER_ONLY, kitchen(), timeout_ms=TIMEOUT_MS)
        assert repair.plan is None and "no repair found" in repair.reason

    def test_a_spent_solver_budget_never_yields_a_repair(self) -> None:
        repair = repair_plan(POT_THROWN, SOLVER_ONLY, kitchen(), timeout_ms=0)
        assert repair.plan is None
