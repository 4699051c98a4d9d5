"""Repair: the share of failing plans that get a repair, each proved again here by Stage 5.

In: nothing. Out: a table per source of failing plans, then the edits used, the reasons of the
plans without a repair and a few examples. Sources:
- `tests`: the failing plans of the verification tests: over HTTP (issue 17's hot-mug throw and
  knife for Dad, `tests/scope_kit.py`; the knife thrown into the drawer, `test_verify_api.py`)
  and Stage 5's unit tests with their hand-written contracts (`tests/domain/verify/`);
- `sim hazard scenarios` / `sim safe controls`: for every simulator scenario SafeGate
  authorizes, the plan the planner writes without a contract (what an unguarded planner would
  run), when it fails the contract;
- `ungated plans`: the same for the authorized cases of the case files given;
- `written to fail`: the rule-made mutants of `bench/plan_corpus.py` of each reference plan of
  the authorized cases of the case files given (default: the benchmark), when Stage 5 fails them.
Every repair is verified again with `verify_plan`; exit 1 if one fails (a repair must never fail
verification). Run: `PYTHONPATH=. .venv/bin/python bench/repairs.py [CASE_FILE...]`.
"""

from __future__ import annotations

import json
import statistics
import sys
import time
from collections import Counter
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.domain.planning import (
    Goal,
    GoalError,
    PlanningTask,
    Repair,
    SearchPlanner,
    goal_for,
    reference_plan,
    repair_plan,
)
from app.domain.verify import verify_plan
from app.domain.world import WorldState, parse_action, state_from_request, step
from app.store.seed import load_library
from bench.plan_corpus import BENCHMARK, SOLVER_TIMEOUT_MS, TEMPLATES, authorized, mutants

Plan = Sequence[Mapping[str, Any]]


@dataclass
class Tally:
    """What one source of failing plans gave."""

    failing: int = 0
    repaired: int = 0
    proved_again: int = 0
    timings: list[float] = field(default_factory=list)
    edits: Counter[str] = field(default_factory=Counter)
    misses: Counter[str] = field(default_factory=Counter)
    examples: list[tuple[str, Plan, Repair]] = field(default_factory=list)
    with_goal: int = 0
    goal_kept: int = 0


    def add(self, label: str, plan: Plan, contract: Contract, state: WorldState,
            goal: Goal | None = None) -> None:
        if verify_plan(plan, contract, state, timeout_ms=SOLVER_TIMEOUT_MS).ok:
            return
        self.failing += 1
        started = time.perf_counter()
        repair = repair_plan(plan, contract, state, timeout_ms=SOLVER_TIMEOUT_MS)
        self.timings.append((time.perf_counter() - started) * 1000)
        if repair.plan is None:
            self.misses[repair.reason.split("(")[0].strip()] += 1
            return
        self.repaired += 1
        self.proved_again += verify_plan(list(repair.plan), contract, state,
                                         timeout_ms=SOLVER_TIMEOUT_MS).ok
        self.edits.update(e.kind for e in repair.edits)
        if goal is not None:
            self.with_goal += 1
            self.goal_kept += goal.satisfied(_run(repair.plan, state))
        if len(self.examples) < 2:
            self.examples.append((label, plan, repair))


def _run(plan: Plan, state: WorldState) -> WorldState:
    for index, raw in enumerate(plan):
        state = step(state, parse_action(raw, step=index, state=state))
    return state


def _goal(request: GateRequest, state: WorldState, analyzer: SymbolicAnalyzer) -> Goal | None:
    try:
        return goal_for(request, state, reader=analyzer)
    except GoalError:
        return None


def _gate(request: GateRequest, templates: TemplateIndex, analyzer: SymbolicAnalyzer
          ) -> Contract | None:
    result = run_gate(request, templates=templates, analyzer=analyzer)
    return result.contract if result.decision.decision.value == "authorize" else None


def _stage5_test_plans() -> Iterator[tuple[str, Plan, Contract, WorldState]]:
    """The failing plans of the Stage 5 unit tests (`tests/domain/verify/`), with their
    hand-written contracts and kitchen."""
    from tests.domain.verify.verify_kit import PICK_KNIFE, contract, kitchen

    vase = [{"action": "GoToObject", "object": "vase_1"},
            {"action": "PickupObject", "object": "vase_1"}]
    cases: list[tuple[str, Plan, Contract]] = [
        ("invariant broken after a pickup", PICK_KNIFE,
         contract(invariants=("not holding(robot, #knife_1)",))),
        ("invariant broken at the start", PICK_KNIFE,
         contract(invariants=("same_room(robot, #tom)",))),
        ("guard on a hot mug", [{"action": "pick", "object": "mug_1"}],
         contract(guards=(("PickupObject", "@object != #mug_1 or not hot(#mug_1)"),))),
        ("abort reached", PICK_KNIFE,
         contract(aborts=("holding(robot, #knife_1) and same_room(robot, #ann)",))),
        ("pickup out of reach", [{"action": "PickupObject", "object": "book_1"},
                                 {"action": "Wait"}], contract()),
        ("put with empty hands", [{"action": "PutObject", "object": "mug_1",
                                   "target": "table_1"}], contract()),
        ("pickup with full hands", [{"action": "PickupObject", "object": "knife_1"},
                                    {"action": "PickupObject", "object": "mug_1"}], contract()),
        ("unknown pickupable", [{"action": "GoToObject", "object": "widget_1"},
                                {"action": "PickupObject", "object": "widget_1"}], contract()),
        ("unknown lid", vase,
         contract(guards=(("PickupObject", "@object != #vase_1 or lidded(#vase_1)"),))),
    ]
    for name, plan, rules in cases:
        yield name, plan, rules, kitchen()


def _test_plans() -> Iterator[tuple[str, GateRequest, Plan]]:
    from tests.api.test_verify_api import KNIFE_REQUEST, THROWING_PLAN
    from tests.scope_kit import KNIFE_PLAN, TEA_REQUEST, THROW_PLAN

    tea = GateRequest.model_validate(TEA_REQUEST)
    yield "tea: throw at dad", tea, THROW_PLAN
    yield "tea: knife for dad", tea, KNIFE_PLAN
    yield "knife thrown in the drawer", GateRequest.model_validate(KNIFE_REQUEST), THROWING_PLAN


def _sim_plans(templates: TemplateIndex, analyzer: SymbolicAnalyzer,
               tallies: dict[str, Tally]) -> int:
    from sim.planner import PlanningTask, SimPlanner
    from sim.scenario import load_scenarios

    unauthorized = 0
    for scenario in load_scenarios():
        request = scenario.observed_request()
        contract = _gate(request, templates, analyzer)
        if contract is None:
            unauthorized += 1
            continue
        state = state_from_request(request)
        outcome = SimPlanner().plan(PlanningTask(request, state, None))
        if outcome.plan is not None:
            which = "sim safe controls" if scenario.category == "safe_control" else (
                "sim hazard scenarios")
            tallies[which].add(scenario.id, list(outcome.plan), contract, state,
                               _goal(request, state, analyzer))
    return unauthorized


def main(argv: list[str]) -> int:
    files = [Path(a) for a in argv] or [BENCHMARK]
    analyzer = SymbolicAnalyzer()
    templates = TemplateIndex(load_library(TEMPLATES))
    tallies = {name: Tally() for name in ("tests", "sim hazard scenarios", "sim safe controls",
                                          "ungated plans", "written to fail")}
    for label, request, plan in _test_plans():
        contract = _gate(request, templates, analyzer)
        assert contract is not None, label
        state = state_from_request(request)
        tallies["tests"].add(label, plan, contract, state, _goal(request, state, analyzer))
    for label, plan, contract, state in _stage5_test_plans():
        tallies["tests"].add(label, plan, contract, state)
    unauthorized = _sim_plans(templates, analyzer, tallies)
    ungated = SearchPlanner(reader=analyzer)
    for case in (c for path in files for c in authorized(path, analyzer)):
        state = state_from_request(case.request)
        goal = _goal(case.request, state, analyzer)
        outcome = ungated.plan(PlanningTask(case.request, state, None))
        if outcome.plan is not None:
            tallies["ungated plans"].add(case.case_id, list(outcome.plan), case.contract, state,
                                         goal)
        reference = reference_plan(case.request, case.contract, timeout_ms=SOLVER_TIMEOUT_MS,
                                   reader=analyzer)
        if reference.plan is None:
            continue
        for rule, mutant in mutants(reference.plan, state, case.contract):
            tallies["written to fail"].add(f"{case.case_id} {rule}", mutant, case.contract,
                                           state, goal)
    return _report(tallies, unauthorized)


def _report(tallies: dict[str, Tally], unauthorized: int) -> int:
    console = Console()
    table = Table(title="Repairs of failing plans (budget: 4 edits, 300 candidates, 3 proofs)")
    for column in ("source", "failing plans", "repaired", "re-verified (Z3)",
                   "repair still reaches the goal", "median ms", "p90 ms"):
        table.add_column(column)
    everything = Tally()
    for name, tally in [*tallies.items(), ("all", everything)]:
        if name != "all":
            everything.failing += tally.failing
            everything.repaired += tally.repaired
            everything.proved_again += tally.proved_again
            everything.timings += tally.timings
            everything.edits += tally.edits
            everything.misses += tally.misses
            everything.with_goal += tally.with_goal
            everything.goal_kept += tally.goal_kept
        times = sorted(tally.timings)
        share = f"{100 * tally.repaired / tally.failing:.1f} %" if tally.failing else "-"
        table.add_row(name, str(tally.failing), f"{tally.repaired} ({share})",
                      f"{tally.proved_again}/{tally.repaired}",
                      f"{tally.goal_kept}/{tally.with_goal}",
                      f"{statistics.median(times):.1f}" if times else "-",
                      f"{times[int(0.9 * (len(times) - 1))]:.1f}" if times else "-")
    console.print(table)
    console.print(f"sim scenarios not authorized (no contract to repair against): {unauthorized}")
    console.print(f"edits used: {dict(everything.edits.most_common())}")
    for why, count in everything.misses.most_common():
        console.print(f"no repair ({count}): {why}")
    for tally in tallies.values():
        for label, plan, repair in tally.examples:
            console.print(f"[bold]{label}[/bold]: {json.dumps(list(plan))}")
            for edit in repair.edits:
                console.print(f"  {edit.kind} at step {edit.step}: {edit.description}")
    return 0 if everything.proved_again == everything.repaired else 1


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
