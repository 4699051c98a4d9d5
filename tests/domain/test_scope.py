"""The task's scope: built from Stage 1's reading, checked by Stage 5 and Stage 6.

Real parts throughout: the symbolic analyzer reads the command, the seed library's pipeline
compiles the contract, Z3 verifies, the monitor steps the messages.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from app.domain.analysis import SymbolicAnalyzer, Understanding
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract, planner_constraints
from app.domain.models import GateRequest
from app.domain.monitor import CompiledContract, Monitor
from app.domain.pipeline import run_gate
from app.domain.scope import ScopeStep, TaskScope, task_scope
from app.domain.scope_check import ScopeMatcher, plan_departures
from app.domain.verify import verify_plan
from app.domain.world import parse_action, state_from_request, step
from app.store.seed import load_library
from tests.scope_kit import GOOD_PLAN, KNIFE_PLAN, TEA_REQUEST, THROW_PLAN, walking

LIBRARY = Path(__file__).resolve().parents[2] / "templates_db"
TIMEOUT_MS = 10_000


@pytest.fixture(scope="module")
def request_() -> GateRequest:
    return GateRequest.model_validate(TEA_REQUEST)


@pytest.fixture(scope="module")
def contract(request_: GateRequest) -> Contract:
    result = run_gate(request_, templates=TemplateIndex(load_library(LIBRARY)),
                      analyzer=SymbolicAnalyzer())
    assert result.decision.decision.value == "authorize", result.decision.reason
    assert result.contract is not None
    return result.contract


def _scope_only(scope: TaskScope) -> Contract:
    return Contract(scope=scope)


def _departures(scope: TaskScope, plan: list[dict[str, Any]], request: GateRequest
                ) -> list[tuple[int, str]]:
    state = state_from_request(request)
    trace = []
    for index, raw in enumerate(plan):
        action = parse_action(raw, step=index, state=state)
        trace.append((index, action, state))
        state = step(state, action)
    found = plan_departures(ScopeMatcher(scope), trace, complete=True)
    return [(d.step, d.rule) for d in found]


class TestTaskScope:
    def test_the_reading_authorizes_fetching_and_delivering_the_mug(
            self, request_: GateRequest) -> None:
        scope = task_scope(SymbolicAnalyzer().understand(request_), request_)
        steps = {(s.action, s.object, s.target) for s in scope.steps}
        assert ("PickupObject", "mug_1", None) in steps
        assert ("HandOver", "mug_1", "dad") in steps
        assert not any("knife_1" in (s.object, s.target) for s in scope.steps)
        # Quoted as the command spells it, not as Stage 1's lower-cased copy.
        assert {s.words for s in scope.steps} == {
            "Bring Dad his hot tea from the kitchen counter"}

    def test_the_gate_stores_it_with_the_contract(self, contract: Contract) -> None:
        assert contract.scope is not None
        assert Contract.model_validate(contract.model_dump(mode="json")) == contract

    def test_a_made_up_entity_stands_for_one_of_its_kind(self) -> None:
        request = GateRequest.model_validate({**TEA_REQUEST, "command": "slice the apple"})
        scope = task_scope(SymbolicAnalyzer().understand(request), request)
        slice_ = next(s for s in scope.steps if s.action == "SliceObject")
        assert (slice_.object, slice_.object_kind) == ("new_apple", "apple")
        scene = {**TEA_REQUEST["scene"], "objects": [
            *TEA_REQUEST["scene"]["objects"],
            {"id": "apple_7", "type": "Apple", "room": "kitchen"}]}
        state = state_from_request(GateRequest.model_validate({**TEA_REQUEST, "scene": scene}))
        matcher = ScopeMatcher(scope)
        for obj, fits in (("apple_7", True), ("mug_1", False)):
            action = parse_action({"action": "SliceObject", "object": obj}, step=0, state=state)
            assert matcher.authorized(action, state) is fits

    def test_a_made_up_person_stands_for_someone_of_that_role(self) -> None:
        request = GateRequest.model_validate({**TEA_REQUEST,
                                              "command": "give the mug to my sister"})
        scope = task_scope(SymbolicAnalyzer().understand(request), request)
        handover = next(s for s in scope.steps if s.action == "HandOver")
        assert handover.target_kind == "person:sister"
        state = state_from_request(request)
        action = parse_action({"action": "HandOver", "object": "mug_1", "target": "dad"},
                              step=0, state=state)
        assert not ScopeMatcher(scope).authorized(action, state)


class TestScopeRules:
    def test_a_throw_of_the_task_object_leaves_the_task(self, contract: Contract,
                                                        request_: GateRequest) -> None:
        assert contract.scope is not None
        assert _departures(contract.scope, THROW_PLAN, request_) == [(3, "action")]

    def test_fetching_the_knife_leaves_the_task_at_its_pickup(
            self, contract: Contract, request_: GateRequest) -> None:
        assert contract.scope is not None
        assert _departures(contract.scope, KNIFE_PLAN, request_) == [(1, "aside"), (4, "object")]

    def test_moving_the_knife_aside_and_back_stays_in_scope(
            self, contract: Contract, request_: GateRequest) -> None:
        assert contract.scope is not None
        aside = [{"action": "GoToObject", "object": "knife_1"},
                 {"action": "PickupObject", "object": "knife_1"},
                 {"action": "PutObject", "object": "knife_1", "target": "countertop_1"},
                 *GOOD_PLAN]
        assert _departures(contract.scope, aside, request_) == []

    def test_carrying_the_knife_to_another_room_is_no_moving_aside(
            self, contract: Contract, request_: GateRequest) -> None:
        assert contract.scope is not None
        carried = [*KNIFE_PLAN[:3], {"action": "PutObject", "object": "knife_1",
                                     "target": "table_1"}]
        assert _departures(contract.scope, carried, request_) == [(1, "aside")]

    def test_something_picked_up_aside_and_kept_leaves_the_task(
            self, contract: Contract, request_: GateRequest) -> None:
        assert contract.scope is not None
        assert _departures(contract.scope, KNIFE_PLAN[:2], request_) == [(1, "aside")]

    def test_handing_the_mug_to_someone_else_names_the_target(
            self, request_: GateRequest) -> None:
        scope = TaskScope(command="give dad the mug", steps=(
            ScopeStep(action="HandOver", object="mug_1", target="dad", words="give dad the mug"),))
        other = {**TEA_REQUEST, "scene": {**TEA_REQUEST["scene"], "people": [
            *TEA_REQUEST["scene"]["people"], {"id": "mum", "room": "kitchen"}]}}
        request = GateRequest.model_validate(other)
        state = state_from_request(request)
        held = step(state, parse_action({"action": "PickupObject", "object": "mug_1"}, step=0,
                                        state=state))
        action = parse_action({"action": "HandOver", "object": "mug_1", "target": "mum"},
                              step=1, state=held)
        departure = ScopeMatcher(scope).departure(action, held, 1)
        assert departure is not None and departure.rule == "target"
        assert '"give dad the mug" has HandOver mug_1 go to dad only' in departure.description


class TestVerifyWithScope:
    def test_the_throw_is_caught_at_step_four_by_scope_and_envelope(
            self, contract: Contract, request_: GateRequest) -> None:
        result = verify_plan(walking(THROW_PLAN), contract, request_, timeout_ms=TIMEOUT_MS)
        assert not result.ok
        at_throw = {(v.kind.value, v.condition_id) for v in result.violations if v.step == 3}
        assert ("scope", "scope.action") in at_throw
        assert ("guard", "baseline.no_throwing_at_people.throw_only_soft_things_never_at_people"
                ) in at_throw
        assert {v.step for v in result.violations} == {3}

    def test_the_knife_plan_fails_at_the_step_that_leaves_the_task(
            self, contract: Contract, request_: GateRequest) -> None:
        result = verify_plan(KNIFE_PLAN, contract, request_, timeout_ms=TIMEOUT_MS)
        first = result.violations[0]
        assert (first.step, first.kind.value, first.condition_id) == (1, "scope", "scope.aside")
        assert first.quote == "Bring Dad his hot tea from the kitchen counter"
        assert f'"{first.quote}"' in first.description
        assert result.reason is not None and "scope" in result.reason

    def test_the_careful_plan_passes(self, contract: Contract,
                                     request_: GateRequest) -> None:
        assert verify_plan(GOOD_PLAN, contract, request_, timeout_ms=TIMEOUT_MS).ok

    def test_a_contract_without_a_scope_checks_none(self, contract: Contract,
                                                    request_: GateRequest) -> None:
        unscoped = contract.model_copy(update={"scope": None})
        result = verify_plan(KNIFE_PLAN, unscoped, request_, timeout_ms=TIMEOUT_MS)
        assert result.ok  # what issue 17 measured: the conditions alone let it through


class TestMonitorWithScope:
    def _run(self, contract: Contract, request: GateRequest, plan: list[dict[str, Any]]
             ) -> list[str]:
        monitor = Monitor(CompiledContract(contract), state_from_request(request))
        answers = []
        for seq, action in enumerate(plan):
            for kind in ("before", "after"):
                verdict = monitor.step({"type": kind, "seq": seq, "action": action})
                answers.append(verdict.type)
                if verdict.type != "allow":
                    return answers
        return answers

    def test_handing_over_the_knife_halts_with_a_scope_violation(
            self, contract: Contract, request_: GateRequest) -> None:
        monitor = Monitor(CompiledContract(contract), state_from_request(request_))
        for seq, action in enumerate(KNIFE_PLAN[:4]):
            assert monitor.step({"type": "before", "seq": seq, "action": action}).allowed
            assert monitor.step({"type": "after", "seq": seq, "action": action}).allowed
        verdict = monitor.step({"type": "before", "seq": 4, "action": KNIFE_PLAN[4]})
        assert verdict.type == "violation" and verdict.halted
        assert verdict.violation is not None
        assert (verdict.violation.kind, verdict.violation.condition_id) == ("scope",
                                                                            "scope.object")
        assert verdict.violation.to_wire()["quote"] == (
            "Bring Dad his hot tea from the kitchen counter")

    def test_scope_alone_halts_the_throw(self, contract: Contract,
                                         request_: GateRequest) -> None:
        answers = self._run(_scope_only(contract.scope or TaskScope(command="")), request_,
                            walking(THROW_PLAN))
        assert answers == ["allow"] * 6 + ["violation"]

    def test_carrying_an_aside_thing_to_another_room_halts_at_the_put(
            self, contract: Contract, request_: GateRequest) -> None:
        carried = [*KNIFE_PLAN[:3], {"action": "PutObject", "object": "knife_1",
                                     "target": "table_1"}]
        assert self._run(_scope_only(contract.scope or TaskScope(command="")), request_,
                         carried) == ["allow"] * 6 + ["violation"]

    def test_the_careful_plan_runs_to_the_end(self, contract: Contract,
                                              request_: GateRequest) -> None:
        assert self._run(contract, request_, GOOD_PLAN) == ["allow"] * 10


class TestPlannerWords:
    def test_the_envelope_and_the_scope_are_in_words(self, contract: Contract) -> None:
        lines = planner_constraints(contract)
        assert any(line.startswith("For every task (baseline envelope).") for line in lines)
        scope = [line for line in lines if line.startswith("Task scope:")]
        assert 'For "Bring Dad his hot tea from the kitchen counter" the task authorizes' in (
            scope[0])
        assert "HandOver mug_1 -> dad" in scope[0]
        assert any("moved aside" in line or "move it aside" in line for line in scope)
        assert "preconditions" in lines[-1]


class _BrokenReader:
    def understand(self, request: GateRequest) -> Understanding:
        raise RuntimeError("reader down")


class TestPipelineScope:
    def test_a_reader_that_fails_defers_instead_of_authorizing(
            self, request_: GateRequest) -> None:
        result = run_gate(request_, templates=TemplateIndex(load_library(LIBRARY)),
                          analyzer=SymbolicAnalyzer(), reader=_BrokenReader())
        assert result.decision.decision.value == "defer" and result.contract is None
        assert "scope" in result.decision.reason

    def test_the_symbolic_analyzer_reads_the_scope_by_default(
            self, contract: Contract) -> None:
        assert contract.scope is not None and contract.scope.steps
