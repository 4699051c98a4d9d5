"""Repair: the nearest plan to a failing one that Stage 5 proves keeps the contract.

In: the failing plan (steps in the wire shape), the `Contract`, the initial state (a `WorldState`
or the request / initial state it is built from), the solver budget per proof and a `RepairBudget`.
Out: a `Repair`: the repaired plan with the edits that made it (kinds in `repair_edits.py`) and
the Stage 5 verdict that proved it, or no plan and the reason.

How: a best-first search over edited plans, in order of the number of edits. Each candidate is
screened (`screen.py`: Stage 5's checks, evaluator first, one shared Z3 prover for what the
evaluator leaves unknown) from the first step it changes; where it fails, the next edits are
proposed there. A candidate that passes the screen is verified with `verify_plan` (Z3, every
value of the unknowns) and returned only if that passes. Candidates come up in order of edits,
so no plan the edit rules reach with fewer edits passes (within the budget, all were screened).
Budget (`RepairBudget`): at most `max_edits` edits (default 4), `max_screens` candidates
screened (300) and `max_proofs` Stage 5 runs (3); the screens share one solver budget of
`timeout_ms`, and each proof has its own. Measured by `bench/repairs.py` and
`bench/perf/verify_plan.py`. Fails closed: a spent budget, a Z3 `unknown` or a timeout never
yields a plan; only a plan Stage 5 passed is returned. A repair keeps the contract; it does not
promise the command's goal (the reference plan does that: `reference.py`).
Fails: never raises for a plan it cannot repair; `FormulaError` if the contract is broken.
"""

from __future__ import annotations

import heapq
import itertools
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from app.domain.contracts import Contract
from app.domain.models import GateRequest, InitialState
from app.domain.planning.repair_edits import Edit, EditProposer
from app.domain.planning.screen import Screen, Trace
from app.domain.smt.trace import TraceProver
from app.domain.verify import VerificationResult, verify_plan
from app.domain.world import WorldState, state_from_request

Step = Mapping[str, Any]

__all__ = ["Edit", "Repair", "RepairBudget", "repair_plan"]


@dataclass(frozen=True, slots=True)
class RepairBudget:
    """How far the repair search may go."""

    max_edits: int = 4
    max_screens: int = 300
    max_proofs: int = 3

    def describe(self) -> str:
        """The budget in words, for reasons and docs."""
        return (f"at most {self.max_edits} edits, {self.max_screens} candidate plans screened, "
                f"{self.max_proofs} Stage 5 proofs")


DEFAULT_BUDGET = RepairBudget()


@dataclass(frozen=True, slots=True)
class Repair:
    """A proved repair (`plan` with its `edits` and `verification`), or None and why."""

    plan: tuple[Step, ...] | None
    edits: tuple[Edit, ...]
    reason: str
    screened: int
    proofs: int
    verification: VerificationResult | None = None


@dataclass(frozen=True, slots=True)
class _Node:
    plan: tuple[Step, ...]
    edits: tuple[Edit, ...]
    prefix: Trace | None
    """The trace of the steps before the first one this node's last edit changed."""


def _key(plan: Sequence[Step]) -> str:
    return json.dumps(list(plan), sort_keys=True, default=str)


class _RepairSearch:
    def __init__(self, contract: Contract, initial: WorldState, timeout_ms: int,
                 budget: RepairBudget) -> None:
        self.contract, self.initial = contract, initial
        self.timeout_ms, self.budget = timeout_ms, budget
        self.screen = Screen(contract, initial, timeout_ms=timeout_ms)
        scope = contract.scope
        self.task_targets = frozenset(
            () if scope is None else (s.target for s in scope.steps if s.target is not None))
        self.screens = 0
        self.proofs = 0
        self.seen: set[str] = set()
        self.frontier: list[tuple[int, int, _Node]] = []
        self.counter = itertools.count()

    def push(self, plan: tuple[Step, ...], edits: tuple[Edit, ...], prefix: Trace | None) -> None:
        key = _key(plan)
        if key in self.seen:
            return
        self.seen.add(key)
        # Fewest edits first; among equals, in the order the edits were proposed. A node is
        # screened only when it comes up, so siblings after a passing one cost nothing.
        heapq.heappush(self.frontier, (len(edits), next(self.counter),
                                       _Node(plan, edits, prefix)))

    def run(self, plan: tuple[Step, ...], checked: int) -> Repair:
        self.push(plan, (), self.screen.replay(plan, checked))
        while self.frontier and self.screens < self.budget.max_screens:
            _, _, node = heapq.heappop(self.frontier)
            self.screens += 1
            screened = self.screen.screen(node.plan, node.prefix)
            failure = screened.failure
            if failure is None:
                if not node.edits:
                    continue  # the plan as sent: Stage 5 already failed it
                proved = self.prove(node)
                if proved is not None:
                    return proved
                if self.proofs >= self.budget.max_proofs:
                    break
                continue
            if len(node.edits) >= self.budget.max_edits:
                continue
            proposer = EditProposer(node.plan, failure, screened.trace, self.initial,
                                    task_targets=self.task_targets)
            for candidate in proposer.candidates():
                self.push(candidate.plan, (*node.edits, candidate.edit),
                          screened.trace.cut(candidate.keep))
        return Repair(None, (), self.why_none(), self.screens, self.proofs)

    def prove(self, node: _Node) -> Repair | None:
        self.proofs += 1
        verdict = verify_plan(list(node.plan), self.contract, self.initial,
                              timeout_ms=self.timeout_ms, prover=self.proof_prover())
        if not verdict.ok:
            return None
        count = len(node.edits)
        return Repair(node.plan, node.edits,
                      f"{count} edit{'s' if count > 1 else ''}, proved by Stage 5",
                      self.screens, self.proofs, verdict)

    def proof_prover(self) -> TraceProver:
        """The screens' prover while it has budget left (its cached answers save the proof
        re-asking Z3 what the screens asked); else a fresh one with the full budget."""
        shared = self.screen.prover
        return TraceProver(self.timeout_ms) if shared.out_of_time else shared

    def why_none(self) -> str:
        spent = (self.screens >= self.budget.max_screens
                 or self.proofs >= self.budget.max_proofs)
        what = "the search budget was spent" if spent else "no edit sequence passes"
        return (f"no repair found: {what} ({self.screens} candidates screened, "
                f"{self.proofs} Stage 5 proofs; budget: {self.budget.describe()})")


def repair_plan(
    plan: Sequence[Step],
    contract: Contract,
    initial_state: WorldState | GateRequest | InitialState,
    *,
    timeout_ms: int,
    budget: RepairBudget = DEFAULT_BUDGET,
    failed: VerificationResult | None = None,
) -> Repair:
    """The nearest plan (fewest edits) that Stage 5 proves keeps the contract.

    Args:
        plan: the failing plan, as sent.
        contract: the Task Safety Contract.
        initial_state: the state the plan starts in (or the request that describes it).
        timeout_ms: the solver's budget for each Stage 5 proof.
        budget: how far the search may go.
        failed: Stage 5's verdict on this plan, if at hand: the steps before its first
            violation passed every check, so the search replays them instead of screening.

    Returns:
        The repair with its edits and proof, or no plan and the reason.

    Raises:
        FormulaError: a contract condition does not parse or type-check.
    """
    state = initial_state if isinstance(initial_state, WorldState) else state_from_request(
        initial_state)
    search = _RepairSearch(contract, state, timeout_ms, budget)
    if search.screen.start_breaks_contract():
        return Repair(None, (), "no repair: the starting state already breaks the contract",
                      0, 0)
    return search.run(tuple(plan), _checked_steps(failed))


def _checked_steps(failed: VerificationResult | None) -> int:
    """How many leading steps Stage 5 passed (0 when unknown)."""
    if failed is None or failed.ok:
        return 0
    firsts = [v.step for v in failed.violations] + [u.step for u in failed.undecided]
    return min(firsts, default=0)
