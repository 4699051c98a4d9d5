"""A fast, conservative check of a plan against a contract, to steer the repair search.

In: a contract, the initial `WorldState`, a plan (steps in the wire shape) and optionally the
trace of a prefix already screened (the states before its steps), so an edit at step j is
screened from step j on. Out: a `Screened`: the first place the plan fails (`Failure`: the step,
the phase `before` / `after` / `end` / `aside`, the condition) or none, and the trace so far.
Same checks as Stage 5 (guards and preconditions before each step, invariants and aborts after
it, the task's scope, the guards on `Finish` at the end): the compiled three-valued evaluator
decides first, and an instance it leaves unknown goes to one Z3 `TraceProver` shared by every
plan the search screens (its answers are cached by the facts a claim reads, so edited plans
that revisit a state cost nothing); anything but a proof fails the screen. Passing the screen is
still not what is handed out: a screened plan is always verified by `verify_plan` first.
Fails: never; a step that does not parse is a failure at that step.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from app.domain.contracts import Contract
from app.domain.errors import PlanError
from app.domain.planning.task import FINISH_ARGS
from app.domain.scope_check import ScopeMatcher, plan_departures
from app.domain.smt import Outcome
from app.domain.smt.trace import TraceProver
from app.domain.verify_checks import Check, contract_checks
from app.domain.world import Action, WorldState, canonical_action, parse_action
from app.domain.world import step as next_state

Step = Mapping[str, Any]


@dataclass(frozen=True, slots=True)
class Failure:
    """Where a plan first fails the screen.

    `step` is the plan index concerned (`len(plan)` for the end of the task); `phase` is
    `before` (a guard, precondition, scope rule or parse error at that step), `after` (an
    invariant or abort in the state the step leaves), `end` (a guard on `Finish`) or `aside`
    (something picked up at `step` outside the task and not put back in the same room).
    """

    step: int
    phase: str
    condition: str


@dataclass(frozen=True, slots=True)
class Trace:
    """A screened prefix: the parsed actions and the states before each (and after the last)."""

    actions: tuple[Action, ...]
    states: tuple[WorldState, ...]

    def cut(self, length: int) -> Trace:
        """The first `length` steps of the trace (an edit at step `length` keeps them)."""
        length = min(length, len(self.actions))
        return Trace(self.actions[:length], self.states[:length + 1])


@dataclass(frozen=True, slots=True)
class Screened:
    """The screen's verdict on a plan."""

    failure: Failure | None
    trace: Trace

    @property
    def ok(self) -> bool:
        return self.failure is None


class Screen:
    """A contract and a start, ready to screen plans within one solver budget."""

    def __init__(self, contract: Contract, initial: WorldState, *, timeout_ms: int) -> None:
        self.checks = contract_checks(contract)
        self.scope = None if contract.scope is None else ScopeMatcher(contract.scope)
        self.initial = initial
        self.prover = TraceProver(timeout_ms)

    def _first_failure(self, checks: tuple[Check, ...], state: WorldState,
                       args: dict[str, str | None] | None) -> Check | None:
        for check in checks:
            value = check.compiled(state, args)
            if value is check.must_hold:
                continue
            if value is None and self.prover.prove(
                    check.key, check.formula, state, args,
                    must_hold=check.must_hold).outcome is Outcome.HOLDS:
                continue
            return check
        return None

    def replay(self, plan: Sequence[Step], steps: int) -> Trace | None:
        """The trace of the plan's first `steps` steps, stepped without checking them (for a
        prefix Stage 5 has already passed); None if a step does not parse."""
        actions: list[Action] = []
        states = [self.initial]
        try:
            for index in range(min(steps, len(plan))):
                action = parse_action(plan[index], step=index, state=states[-1])
                actions.append(action)
                states.append(next_state(states[-1], action))
        except PlanError:
            return None
        return Trace(tuple(actions), tuple(states))

    def start_breaks_contract(self) -> bool:
        """Whether the initial state already breaks an invariant or an abort."""
        return self._after_failure(self.initial) is not None

    def screen(self, plan: Sequence[Step], prefix: Trace | None = None) -> Screened:
        """Screen a plan, reusing a prefix already screened (its steps must be the plan's).

        Args:
            plan: the steps.
            prefix: a trace of the plan's first steps, or None to start from the start.

        Returns:
            The first failure (or none) and the trace up to it.
        """
        trace = prefix or Trace((), (self.initial,))
        actions, states = list(trace.actions), list(trace.states)
        for index in range(len(actions), len(plan)):
            state = states[-1]
            failure, action = self._before(plan[index], index, state)
            if action is None or failure is not None:
                return Screened(failure, Trace(tuple(actions), tuple(states)))
            after = next_state(state, action)
            actions.append(action)
            states.append(after)
            condition = self._after_failure(after)
            if condition is not None:
                return Screened(Failure(index, "after", condition),
                                Trace(tuple(actions), tuple(states)))
        done = Trace(tuple(actions), tuple(states))
        return Screened(self._end_failure(plan, done), done)

    def _before(self, raw: Step, index: int, state: WorldState
                ) -> tuple[Failure | None, Action | None]:
        try:
            action = parse_action(raw, step=index, state=state)
        except PlanError:
            return Failure(index, "before", "parse"), None
        checks = self.checks
        if self._first_failure(checks.preconditions_for(action.name), state,
                               action.args) is not None:
            return Failure(index, "before", "precondition"), action
        guard = self._first_failure(checks.guards_for(action.name), state, action.args)
        if guard is not None:
            return Failure(index, "before", guard.condition_id), action
        departure = None if self.scope is None else self.scope.departure(action, state, index)
        if departure is not None:
            return Failure(index, "before", departure.condition_id), action
        return None, action

    def _after_failure(self, state: WorldState) -> str | None:
        failed = self._first_failure(self.checks.every_state, state, None)
        return None if failed is None else failed.condition_id

    def _end_failure(self, plan: Sequence[Step], trace: Trace) -> Failure | None:
        last = plan[-1].get("action") if plan else None
        if not (isinstance(last, str) and canonical_action(last) == "Finish"):
            guard = self._first_failure(self.checks.guards_for("Finish"), trace.states[-1],
                                        FINISH_ARGS)
            if guard is not None:
                return Failure(len(plan), "end", guard.condition_id)
        if self.scope is None:
            return None
        steps = [(i, a, trace.states[i]) for i, a in enumerate(trace.actions)]
        aside = [d for d in plan_departures(self.scope, steps, complete=True)
                 if d.rule == "aside"]
        return Failure(aside[0].step, "aside", aside[0].condition_id) if aside else None
