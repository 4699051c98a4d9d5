"""Stage 5, Static Plan Verification: does a plan keep the contract for every unknown fact?

In: a plan (steps in the wire shape, AI2-THOR/SMART-LLM names and aliases), a `Contract`, the
initial state (a `WorldState`, or the gate request / initial state to build it from) and a
solver time budget. Out: a `VerificationResult`: ok, or the violations, each with the step and
action, its kind (`invariant`, `guard`, `abort`, `precondition`, `scope`), the condition's id,
formula and description, and a counterexample (a scope violation has none, and quotes the words
of the command it departs from).

How: symbolic execution through the action model gives the trace s0..sL, in which a fact the
request did not give stays `Unknown` (a free Z3 variable). Every invariant must hold in every
state, every guard in the state before each action it guards, every action's preconditions
likewise, and no abort may hold in any state, for every value of the unknowns. The compiled
three-valued evaluator decides first; only a definite "fine" skips Z3 (an unknown or failing
instance always goes to the solver, which also gives the counterexample). Each condition is
reported at its first violating step; the trace stops at the first failed precondition (the
action would not run). A plan that does not end with `Finish` ends with it implicitly: guards on
`Finish` (what the task must not leave behind) are checked on the last state. A contract with a
scope also has every step checked against it (`scope_check.py`): each step outside the task is
a `scope` violation at the step that leaves the task. A solver `unknown` or a spent budget fails
the verification.
Fails: `PlanError` (step and field) for a step that is not an object, names an unknown action or
an id not in the state; `FormulaError` (field `contract...`) for a condition that does not parse.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from app.domain.contracts import Contract
from app.domain.errors import PlanError
from app.domain.formula import Value
from app.domain.models import GateRequest, InitialState
from app.domain.scope_check import Departure, ScopeMatcher, plan_departures
from app.domain.smt import Outcome
from app.domain.smt.trace import TraceProver
from app.domain.verify_checks import Check, CheckKind, ContractChecks, contract_checks
from app.domain.world import (
    Action,
    WorldState,
    canonical_action,
    parse_action,
    state_from_request,
    step,
)

__all__ = ["CheckKind", "Undecided", "VerificationResult", "Violation", "verify_plan"]


@dataclass(frozen=True, slots=True)
class Violation:
    """A condition the plan breaks (for at least one value of the unknowns).

    `step` is the index of the plan action concerned; `state` the index in s0..sL where the
    condition failed (`step` for what must hold before the action, `step + 1` after it; 0 with
    `action` None when the initial state already breaks an invariant or abort).
    """

    step: int
    state: int
    action: Mapping[str, Any] | None
    kind: CheckKind
    condition_id: str
    formula: str
    description: str
    counterexample: Mapping[str, Value] = field(default_factory=dict)
    free: tuple[str, ...] = ()
    quote: str | None = None
    """For a `scope` violation: the words of the command the step departs from."""

    @classmethod
    def of_departure(cls, departure: Departure) -> Violation:
        """A step outside the task's scope, as a violation."""
        return cls(step=departure.step, state=departure.step,
                   action=departure.action.to_wire(), kind=CheckKind.SCOPE,
                   condition_id=departure.condition_id, formula=departure.formula,
                   description=departure.description, quote=departure.quote)


@dataclass(frozen=True, slots=True)
class Undecided:
    """A condition instance the solver could not decide (counts as a failure)."""

    step: int
    state: int
    action: Mapping[str, Any] | None
    kind: CheckKind
    condition_id: str
    formula: str
    description: str
    detail: str


@dataclass(frozen=True, slots=True)
class VerificationResult:
    """The verdict: `ok` only when every condition instance was proved."""

    ok: bool
    violations: tuple[Violation, ...] = ()
    undecided: tuple[Undecided, ...] = ()
    states_checked: int = 0
    reason: str | None = None
    solver_calls: int = 0


class _Run:
    """The verdicts gathered along one trace."""

    def __init__(self, prover: TraceProver) -> None:
        self.prover = prover
        self.violations: list[Violation] = []
        self.undecided: list[Undecided] = []
        self.done: set[str] = set()

    def decide(self, check: Check, state: WorldState, *, step_index: int, state_index: int,
               action: Mapping[str, Any] | None, args: Mapping[str, str | None] | None) -> bool:
        """Check one instance; False if it was violated or undecided."""
        if check.key in self.done:
            return True
        fine = check.must_hold
        if check.compiled(state, args) is fine:
            return True
        proof = self.prover.prove(check.key, check.formula, state, args,
                                  must_hold=check.must_hold)
        if proof.outcome is Outcome.HOLDS:
            return True
        if proof.outcome is Outcome.VIOLATED:
            self.violations.append(Violation(
                step=step_index, state=state_index, action=action, kind=check.kind,
                condition_id=check.condition_id, formula=check.text,
                description=check.description, counterexample=proof.counterexample,
                free=proof.free))
        else:
            self.undecided.append(Undecided(
                step=step_index, state=state_index, action=action, kind=check.kind,
                condition_id=check.condition_id, formula=check.text,
                description=check.description, detail=proof.detail))
        if check.kind is not CheckKind.PRECONDITION:
            self.done.add(check.key)
        return False

    def state(self, checks: ContractChecks, state: WorldState, *, step_index: int,
              state_index: int, action: Mapping[str, Any] | None) -> None:
        for check in checks.every_state:
            self.decide(check, state, step_index=step_index, state_index=state_index,
                        action=action, args=None)


def verify_plan(
    plan: Sequence[object],
    contract: Contract,
    initial_state: WorldState | GateRequest | InitialState,
    *,
    timeout_ms: int,
    prover: TraceProver | None = None,
) -> VerificationResult:
    """Verify a plan against a contract from an initial state, for every value of its unknowns.

    Args:
        plan: the steps as sent, e.g. `[{"action": "pick", "object": "mug_1"}, ...]`.
        contract: the Task Safety Contract.
        initial_state: the state the plan starts in (or the request that describes it).
        timeout_ms: the solver's budget for the whole plan; spending it fails the verification.
        prover: a prover already used on this contract's checks (the repair search's), whose
            cached answers stand (they depend only on a claim and the facts it reads); its
            remaining budget then bounds this verification too. Default: a new one.

    Returns:
        The verdict with every violation (each condition at its first violating step) and every
        instance the solver could not decide.

    Raises:
        PlanError: a step that is not an object, an unknown action, or an id not in the state.
        FormulaError: a contract condition that does not parse or type-check.
    """
    checks = contract_checks(contract)
    state = initial_state if isinstance(initial_state, WorldState) else state_from_request(
        initial_state)
    run = _Run(prover if prover is not None else TraceProver(timeout_ms))
    run.state(checks, state, step_index=0, state_index=0, action=None)
    states = 1
    scoped: list[tuple[int, Action, WorldState]] = []
    for index, raw in enumerate(plan):
        parsed = _parse_step(raw, index, state)
        if isinstance(parsed, Violation):
            run.violations.append(parsed)
            break
        scoped.append((index, parsed, state))
        wire, args = parsed.to_wire(), parsed.args
        before_ok = True
        for check in (*checks.guards_for(parsed.name), *checks.preconditions_for(parsed.name)):
            decided = run.decide(check, state, step_index=index, state_index=index,
                                 action=wire, args=args)
            before_ok = before_ok and (decided or check.kind is not CheckKind.PRECONDITION)
        if not before_ok:
            break
        state = step(state, parsed)
        run.state(checks, state, step_index=index, state_index=index + 1, action=wire)
        states += 1
    complete = states == len(plan) + 1
    if contract.scope is not None:
        departures = plan_departures(ScopeMatcher(contract.scope), scoped, complete=complete)
        run.violations.extend(map(Violation.of_departure, departures))
        run.violations.sort(key=lambda v: v.step)  # stable: the order within a step is kept
    if complete and not _ends_with_finish(plan):
        # Every plan ends the task: what must hold at its end is checked on the last state.
        for check in checks.guards_for("Finish"):
            run.decide(check, state, step_index=len(plan), state_index=len(plan),
                       action={"action": "Finish"}, args={"object": None, "target": None})
    return _result(run, states, complete=complete)


def _ends_with_finish(plan: Sequence[object]) -> bool:
    last = plan[-1] if plan else None
    name = last.get("action") if isinstance(last, Mapping) else None
    return isinstance(name, str) and canonical_action(name) == "Finish"


def _result(run: _Run, states: int, *, complete: bool) -> VerificationResult:
    # `complete` is belt and braces: a trace cut short always carries a violation already.
    ok = complete and not run.violations and not run.undecided
    reason: str | None = None
    if run.undecided:
        first = run.undecided[0]
        reason = (f"could not decide {first.kind.value} {first.condition_id} at step "
                  f"{first.step}: {first.detail}")
    elif not run.violations:
        reason = None if complete else "the plan was not checked to its end"
    else:
        violation = run.violations[0]
        reason = (f"{len(run.violations)} violation(s); first: {violation.kind.value} "
                  f"{violation.condition_id} at step {violation.step}")
    return VerificationResult(ok=ok, violations=tuple(run.violations),
                              undecided=tuple(run.undecided), states_checked=states,
                              reason=reason, solver_calls=run.prover.solver_calls)


def _parse_step(raw: object, index: int, state: WorldState) -> Any:
    """The parsed action, or a precondition violation for a held-object step with empty hands."""
    if not isinstance(raw, Mapping):
        raise PlanError(f"step {index}: a step must be an object with an 'action'", step=index,
                        field=f"plan[{index}]")
    try:
        return parse_action(raw, step=index, state=state)
    except PlanError as error:
        empty_hand = _empty_hand_violation(raw, index, state, error)
        if empty_hand is None:
            raise
        return empty_hand


def _empty_hand_violation(raw: Mapping[str, object], index: int, state: WorldState,
                          error: PlanError) -> Violation | None:
    """SMART-LLM's `PutObject(receptacle)` with nothing held fails to parse for want of an
    object; that is the robot's empty gripper, a precondition violation, not a bad request."""
    name = raw.get("action")
    canonical = canonical_action(name) if isinstance(name, str) else None
    if canonical is None or state.robot.holding is not None:
        return None
    if not (error.field or "").endswith(".object"):
        return None
    holding = next((c for c in ContractChecks.preconditions_of(canonical)
                    if c.text == "holding(robot, @object)"), None)
    if holding is None:
        return None
    wire = {"action": canonical, **{k: v for k, v in raw.items() if k != "action"}}
    return Violation(step=index, state=index, action=wire, kind=CheckKind.PRECONDITION,
                     condition_id=holding.condition_id, formula=holding.text,
                     description=f"{holding.description} (the robot holds nothing)")
