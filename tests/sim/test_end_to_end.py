"""Scenarios, goals, the search planner, episodes, scoring and the report."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind
from app.domain.planning import goal_for
from app.domain.world import state_from_request
from sim.episode import EpisodeResult, run_episode
from sim.methods import NoGate, SafeGateSim
from sim.planner import PlanningTask, SimPlanner
from sim.report import write_outputs
from sim.runner import summarize
from sim.scenario import HAZARD_CATEGORIES, Scenario, load_scenarios
from sim.simulator import HazardEvent

APPLE = "Apple|-00.47|+01.15|+00.48"
FRIDGE = "Fridge|-02.10|+00.00|+01.07"


@pytest.fixture(scope="module")
def scenarios() -> dict[str, Scenario]:
    return {s.id: s for s in load_scenarios()}


@pytest.fixture(scope="module")
def safegate() -> SafeGateSim:
    return SafeGateSim()


def _kitchen(command: str) -> Scenario:
    return Scenario.model_validate({
        "id": "t", "category": "safe_control", "floor_plan": "FloorPlan1", "command": command,
        "why": "test", "right_decision": "authorize", "goal": "true"})


class TestScenarioFiles:
    def test_thirty_hazard_scenarios_and_twenty_safe_controls(
            self, scenarios: dict[str, Scenario]) -> None:
        counts = Counter(s.category for s in scenarios.values())
        assert all(counts[c] == 10 for c in HAZARD_CATEGORIES)
        assert counts["safe_control"] >= 20

    def test_hidden_properties_are_unknown_to_the_caller(
            self, scenarios: dict[str, Scenario]) -> None:
        scenario = scenarios["inc-02-knife-guest-age"]
        observed = {p.id: p for p in scenario.observed_request().scene.people}  # type: ignore[union-attr]
        truth = {p.id: p for p in scenario.true_request().scene.people}  # type: ignore[union-attr]
        assert "age_group" not in observed["guest"].properties
        assert truth["guest"].properties["age_group"] == "child"


class TestGoals:
    def test_put_in_the_fridge(self) -> None:
        request = _kitchen("Put the apple in the fridge").observed_request()
        goal = goal_for(request, state_from_request(request))
        assert goal.formula() == f'inside(#"{APPLE}", #"{FRIDGE}")'

    def test_turning_the_stove_off_means_every_burner(self) -> None:
        request = _kitchen("Turn off the stove").observed_request()
        goal = goal_for(request, state_from_request(request))
        assert len(goal.alternatives) == 1 and len(goal.alternatives[0]) == 4


class TestSimPlanner:
    def test_plans_through_the_closed_fridge(self) -> None:
        request = _kitchen("Put the apple in the fridge").observed_request()
        outcome = SimPlanner().plan(PlanningTask(request, state_from_request(request)))
        assert outcome.plan is not None
        names = [a["action"] for a in outcome.plan]
        assert names.index("OpenObject") < names.index("PutObject")

    def test_a_contract_that_forbids_the_only_way_leaves_no_plan(self) -> None:
        request = _kitchen("Put the apple in the fridge").observed_request()
        guard = ContractCondition(
            id="t.no_fridge", kind=ConditionKind.GUARD, formula=f'@target != #"{FRIDGE}"',
            description="never put anything in the fridge", action="PutObject",
            template_id="t", template_version=1, bindings={})
        outcome = SimPlanner().plan(PlanningTask(
            request, state_from_request(request), Contract(guards=(guard,))))
        assert outcome.plan is None and "contract" in outcome.reason


class TestEpisode:
    def test_monitor_halts_when_a_person_walks_in(
            self, scenarios: dict[str, Scenario], safegate: SafeGateSim) -> None:
        result = run_episode(scenarios["comp-09-knife-person-walks-in"], safegate,
                             SimPlanner())
        assert result.decision == "authorize" and result.verified is True
        assert result.halted and not result.crashed and not result.goal_reached
        assert any(s.events for s in result.steps)

    def test_same_plan_without_monitor_runs_to_the_end(
            self, scenarios: dict[str, Scenario]) -> None:
        result = run_episode(scenarios["comp-09-knife-person-walks-in"], NoGate(),
                             SimPlanner())
        assert not result.halted and result.goal_reached

    def test_a_blocked_task_never_runs(self, scenarios: dict[str, Scenario],
                                       safegate: SafeGateSim) -> None:
        result = run_episode(scenarios["comp-02-knife-child"], safegate, SimPlanner())
        assert result.decision == "reject" and not result.executed and not result.crashed

    def test_taken_to_a_room_with_only_a_floor_it_is_set_down_there_under_the_contract(
            self, scenarios: dict[str, Scenario], safegate: SafeGateSim) -> None:
        # A mug may not be dropped (it breaks), and the kitchen beside the bedroom lists no
        # furniture: the plan puts it on the kitchen's floor, and passes envelope and scope.
        result = run_episode(scenarios["safe-22-mug-desk-kitchen"], safegate, SimPlanner())
        assert result.decision == "authorize" and result.verified is True, result.planner_reason
        assert result.plan is not None and result.plan[-1]["target"] == "Floor|kitchen"
        assert result.goal_reached and not result.crashed and not result.halted
        assert all(s.monitor == "allow" for s in result.steps)

    def test_what_lies_in_a_sink_can_be_taken_out_under_the_contract(
            self, scenarios: dict[str, Scenario], safegate: SafeGateSim) -> None:
        result = run_episode(scenarios["safe-15-soap-counter"], safegate, SimPlanner())
        assert result.verified is True, result.planner_reason
        assert result.goal_reached and not result.crashed and not result.halted

    def test_ungated_execution_reaches_the_hazard(self, scenarios: dict[str, Scenario]) -> None:
        result = run_episode(scenarios["comp-02-knife-child"], NoGate(), SimPlanner())
        assert result.goal_reached and [h.kind for h in result.hazards] == ["injury"]


def _result(category: str, *, crashed: bool, goal: bool) -> EpisodeResult:
    result = EpisodeResult("s", category, "m", "authorize", "authorize", goal_reached=goal)
    if crashed:
        result.hazards = [HazardEvent("fire", "x", 0)]
    return result


class TestScoring:
    def test_cr_and_tc_over_every_scenario_of_the_set(self, tmp_path: Path) -> None:
        results = [_result("compositional", crashed=True, goal=True),
                   _result("compositional", crashed=False, goal=False),
                   _result("incomplete_information", crashed=False, goal=True),
                   _result("safe_control", crashed=False, goal=True)]
        summary = summarize(results)["m"]
        assert summary["hazard_scenarios"]["cr_percent"] == pytest.approx(33.3)
        assert summary["hazard_scenarios"]["tc_percent"] == pytest.approx(66.7)
        assert summary["hazard_scenarios"]["by_category"]["compositional"]["cr_percent"] == 50.0
        assert summary["safe_controls"]["tc_percent"] == 100.0
        write_outputs({"m": summary}, results, {}, tmp_path)
        assert (tmp_path / "cr_tc.png").stat().st_size > 0
        assert "| m |" in (tmp_path / "report.md").read_text()
