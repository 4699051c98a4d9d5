"""Stage 5 with facts the request did not give: free variables, counterexamples, fail closed."""

from __future__ import annotations

import pytest
import z3
from verify_kit import PICK_KNIFE, contract, kitchen

from app.domain.errors import FormulaError, PlanError
from app.domain.verify import CheckKind, verify_plan

TIMEOUT_MS = 5000
PICK_VASE = [{"action": "GoToObject", "object": "vase_1"},
             {"action": "PickupObject", "object": "vase_1"}]


class TestUnknownFacts:
    def test_plan_fails_when_some_value_of_an_unknown_breaks_the_contract(self) -> None:
        guards = (("PickupObject", "@object != #vase_1 or lidded(#vase_1)"),)
        result = verify_plan(PICK_VASE, contract(guards=guards), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        [violation] = result.violations
        assert violation.counterexample == {"lidded(vase_1)": False}
        assert violation.free == ("lidded(vase_1)",)

    def test_the_same_plan_passes_once_the_fact_is_known(self) -> None:
        guards = (("PickupObject", "@object != #vase_1 or lidded(#vase_1)"),)
        result = verify_plan(PICK_VASE, contract(guards=guards),
                             kitchen(vase_1={"lidded": True}), timeout_ms=TIMEOUT_MS)
        assert result.ok

    def test_condition_true_for_every_value_of_an_unknown_passes(self) -> None:
        invariants = ("toxic(#vase_1) or not toxic(#vase_1)",)
        result = verify_plan(PICK_VASE, contract(invariants=invariants), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert result.ok
        assert result.solver_calls >= 1

    def test_an_effect_that_copies_an_unknown_keeps_the_link(self) -> None:
        # Dropping the vase breaks it exactly when it is breakable: the same unknown.
        plan = [*PICK_VASE, {"action": "DropHandObject"}]
        invariants = ("broken(#vase_1) -> breakable(#vase_1)",)
        result = verify_plan(plan, contract(invariants=invariants),
                             kitchen(vase_1={"broken": False}), timeout_ms=TIMEOUT_MS)
        assert result.ok, result

    def test_maybe_broken_maybe_glass_is_maybe_sharp(self) -> None:
        # Dropped with breakable unknown, the vase may break; of unknown material, the pieces
        # may be sharp. "Not sharp" was decided there and the plan verified (found by the
        # brute-force comparison): it must fail with a counterexample instead.
        plan = [*PICK_VASE, {"action": "DropHandObject"}]
        invariants = ("broken(#vase_1) -> not sharp(#vase_1)",)
        result = verify_plan(plan, contract(invariants=invariants),
                             kitchen(vase_1={"broken": False}),
                             timeout_ms=TIMEOUT_MS)
        assert not result.ok, result
        assert result.violations[0].counterexample.get("sharp(vase_1)") is True

    def test_unknown_words_range_over_their_vocabulary(self) -> None:
        every_age = " or ".join(f'age_group(#tom) == "{a}"' for a in
                                ("infant", "child", "teen", "adult", "older_adult"))
        assert verify_plan([], contract(invariants=(every_age,)), kitchen(),
                           timeout_ms=TIMEOUT_MS).ok
        some_ages = every_age.rsplit(" or ", 1)[0]
        [violation] = verify_plan([], contract(invariants=(some_ages,)), kitchen(),
                                  timeout_ms=TIMEOUT_MS).violations
        assert violation.counterexample["age_group(tom)"] == "older_adult"


@pytest.mark.faults
class TestSolverFailures:
    def test_spent_budget_fails_the_verification_with_that_reason(self) -> None:
        guards = (("PickupObject", "lidded(#vase_1) or not lidded(#vase_1)"),)
        result = verify_plan(PICK_VASE, contract(guards=guards), kitchen(), timeout_ms=0)
        assert not result.ok
        assert result.violations == ()
        [undecided] = result.undecided
        assert undecided.kind is CheckKind.GUARD
        assert "timeout" in undecided.detail and "timeout" in (result.reason or "")

    def test_decided_by_the_evaluator_needs_no_solver_budget(self) -> None:
        result = verify_plan(PICK_KNIFE, contract(invariants=("not holding(robot, #mug_1)",)),
                             kitchen(), timeout_ms=0)
        assert result.ok and result.solver_calls == 0

    def test_solver_unknown_never_passes(self, monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setattr(z3.Solver, "check", lambda self, *args: z3.unknown)
        monkeypatch.setattr(z3.Solver, "reason_unknown", lambda self: "incomplete")
        invariants = ("toxic(#vase_1) or not toxic(#vase_1)",)
        result = verify_plan(PICK_VASE, contract(invariants=invariants), kitchen(),
                             timeout_ms=TIMEOUT_MS)
        assert not result.ok
        assert result.undecided[0].detail == "solver unknown: incomplete"


class TestBadInput:
    @pytest.mark.parametrize(("plan", "field"), [
        ([{"action": "Wait"}, {"action": "Teleport", "object": "mug_1"}], "plan[1].action"),
        ([{"action": "PickupObject", "object": "unicorn_9"}], "plan[0].object"),
        ([{"action": "Wait"}, {"action": "Wait"}, "pick mug"], "plan[2]"),
        ([{"object": "mug_1"}], "plan[0].action"),
    ])
    def test_bad_step_is_a_plan_error_naming_it(self, plan: list[object], field: str) -> None:
        with pytest.raises(PlanError) as raised:
            verify_plan(plan, contract(), kitchen(), timeout_ms=TIMEOUT_MS)
        assert raised.value.field == field

    def test_bad_condition_is_a_formula_error_naming_it(self) -> None:
        with pytest.raises(FormulaError) as raised:
            verify_plan([], contract(aborts=("true", "hot(#mug_1) and")), kitchen(),
                        timeout_ms=TIMEOUT_MS)
        assert raised.value.field == "contract.aborts[1].formula"
