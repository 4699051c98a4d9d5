"""The reference plan: the planner's plan for an authorized command, proved by Stage 5."""

from __future__ import annotations

import pytest

from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.domain.pipeline import run_gate
from app.domain.planning import goal_for, reference_plan
from app.domain.verify import VerificationResult, verify_plan
from app.domain.world import parse_action, state_from_request, step
from app.store.seed import load_library
from bench.plan_corpus import TEMPLATES
from tests.scope_kit import TEA_REQUEST

TIMEOUT_MS = 5000
TEA = GateRequest.model_validate(TEA_REQUEST)


@pytest.fixture(scope="module")
def tea_contract() -> Contract:
    result = run_gate(TEA, templates=TemplateIndex(load_library(TEMPLATES)),
                      analyzer=SymbolicAnalyzer())
    assert result.contract is not None
    return result.contract


class TestReferencePlan:
    def test_the_tea_task_gets_a_plan_that_verifies_and_reaches_its_goal(
            self, tea_contract: Contract) -> None:
        reference = reference_plan(TEA, tea_contract, timeout_ms=TIMEOUT_MS)
        assert reference.plan is not None, reference.reason
        assert reference.verification is not None and reference.verification.ok
        state = state_from_request(TEA)
        assert verify_plan(list(reference.plan), tea_contract, state, timeout_ms=TIMEOUT_MS).ok
        for index, raw in enumerate(reference.plan):
            state = step(state, parse_action(raw, step=index, state=state))
        assert goal_for(TEA, state_from_request(TEA)).satisfied(state)
        assert "proved by Stage 5" in reference.reason

    def test_a_contract_that_forbids_every_way_gives_none_with_the_budget(
            self, tea_contract: Contract) -> None:
        never = ContractCondition(id="t.never_pick", kind=ConditionKind.GUARD, formula="false",
                                  description="never pick anything up", action="PickupObject",
                                  template_id="t", template_version=1, bindings={})
        forbidding = tea_contract.model_copy(update={"guards": (*tea_contract.guards, never)})
        reference = reference_plan(TEA, forbidding, timeout_ms=TIMEOUT_MS, max_expansions=300)
        assert reference.plan is None
        assert "search budget of 300 states" in reference.reason

    def test_a_plan_stage_5_does_not_pass_is_never_handed_out(
            self, tea_contract: Contract, monkeypatch: pytest.MonkeyPatch) -> None:
        # Stand in for a verdict the planner's evaluator did not foresee (a solver timeout).
        monkeypatch.setattr("app.domain.planning.reference.verify_plan",
                            lambda *args, **kwargs: VerificationResult(
                                ok=False, reason="could not decide: timeout"))
        reference = reference_plan(TEA, tea_contract, timeout_ms=TIMEOUT_MS)
        assert reference.plan is None and "did not pass Stage 5" in reference.reason
