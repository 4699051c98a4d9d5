"""A small facade over the Z3 solver: prove, check satisfiability, read counterexamples.

In: claims, each an `Encoding` (from `encode`) or a raw Z3 `BoolRef`, plus a timeout. Out:
`ProofResult` (HOLDS / VIOLATED with a counterexample / UNKNOWN) or `SatResult` (SAT with a
model / UNSAT / UNKNOWN). UNKNOWN covers a solver `unknown`, a timeout and a Z3 error; callers
must treat it as failure (it never means "holds"). Counterexamples map each free variable's name
(the unknown fact's key) to a Python bool, float or str.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import TypeAlias

import z3

from app.domain.formula.facts import Value
from app.domain.smt.encoder import Encoding

Claim: TypeAlias = Encoding | z3.BoolRef
DEFAULT_TIMEOUT_MS = 5000


class Outcome(StrEnum):
    """What a proof attempt established."""

    HOLDS = "holds"
    VIOLATED = "violated"
    UNKNOWN = "unknown"


class Satisfiability(StrEnum):
    """What a satisfiability check established."""

    SAT = "sat"
    UNSAT = "unsat"
    UNKNOWN = "unknown"


@dataclass(frozen=True, slots=True)
class ProofResult:
    """The outcome of `prove`; `counterexample` is filled when VIOLATED."""

    outcome: Outcome
    counterexample: Mapping[str, Value] = field(default_factory=dict)
    detail: str = ""

    @property
    def holds(self) -> bool:
        """True only when the claim was proved; VIOLATED and UNKNOWN are both False."""
        return self.outcome is Outcome.HOLDS


@dataclass(frozen=True, slots=True)
class SatResult:
    """The outcome of `satisfiable`; `model` is filled when SAT."""

    outcome: Satisfiability
    model: Mapping[str, Value] = field(default_factory=dict)
    detail: str = ""

    @property
    def sat(self) -> bool:
        """True only when a satisfying assignment was found."""
        return self.outcome is Satisfiability.SAT


def _as_list(claims: Claim | Iterable[Claim]) -> list[Claim]:
    if isinstance(claims, Encoding | z3.BoolRef):
        return [claims]
    return list(claims)


def _split(claims: list[Claim]) -> tuple[list[z3.BoolRef], list[z3.BoolRef], dict[str, z3.ExprRef]]:
    exprs: list[z3.BoolRef] = []
    assumptions: list[z3.BoolRef] = []
    variables: dict[str, z3.ExprRef] = {}
    for claim in claims:
        if isinstance(claim, Encoding):
            exprs.append(claim.expr)
            assumptions.extend(claim.assumptions)
            variables.update(claim.unknowns)
        else:
            exprs.append(claim)
    return exprs, assumptions, variables


def _python_value(value: z3.ExprRef) -> Value:
    if z3.is_true(value):
        return True
    if z3.is_false(value):
        return False
    if z3.is_rational_value(value):
        return float(value.as_fraction())
    if z3.is_algebraic_value(value):
        return float(value.approx(20).as_fraction())
    if z3.is_string_value(value):
        text: str = value.as_string()
        return text
    return str(value)


def _model(solver: z3.Solver, variables: Mapping[str, z3.ExprRef]) -> dict[str, Value]:
    model = solver.model()
    return {
        name: _python_value(model.eval(var, model_completion=True))
        for name, var in sorted(variables.items())
    }


def _check(
    goal: list[z3.BoolRef], timeout_ms: int
) -> tuple[z3.CheckSatResult | None, z3.Solver, str]:
    solver = z3.Solver()
    solver.set("timeout", int(timeout_ms))
    solver.add(*goal)
    try:
        result = solver.check()
    except z3.Z3Exception as error:
        return None, solver, f"z3 error: {error}"
    detail = solver.reason_unknown() if result == z3.unknown else ""
    return result, solver, detail


def prove(
    claims: Claim | Iterable[Claim],
    timeout_ms: int = DEFAULT_TIMEOUT_MS,
    *,
    assumptions: Iterable[Claim] = (),
) -> ProofResult:
    """Prove that all claims hold for every value of their free variables.

    Args:
        claims: encodings or Z3 conditions that must all hold.
        timeout_ms: the solver's time budget.
        assumptions: conditions taken as given (e.g. what the plan so far established).

    Returns:
        HOLDS, VIOLATED with a counterexample, or UNKNOWN (treat as failure).
    """
    exprs, side, variables = _split(_as_list(claims))
    premises, premise_side, premise_variables = _split(_as_list(list(assumptions)))
    goal = [*side, *premise_side, *premises, z3.Not(z3.And(exprs))]
    result, solver, detail = _check(goal, timeout_ms)
    if result == z3.unsat:
        return ProofResult(Outcome.HOLDS)
    if result == z3.sat:
        return ProofResult(
            Outcome.VIOLATED, _model(solver, {**premise_variables, **variables})
        )
    return ProofResult(Outcome.UNKNOWN, detail=detail or "solver gave up")


def valid(claims: Claim | Iterable[Claim], timeout_ms: int = DEFAULT_TIMEOUT_MS) -> ProofResult:
    """Whether the claims hold in every state (HOLDS), with a counterexample state if not."""
    return prove(claims, timeout_ms)


def satisfiable(
    claims: Claim | Iterable[Claim], timeout_ms: int = DEFAULT_TIMEOUT_MS
) -> SatResult:
    """Whether some values of the free variables make all claims true at once.

    Args:
        claims: encodings or Z3 conditions.
        timeout_ms: the solver's time budget.

    Returns:
        SAT with a witness model, UNSAT, or UNKNOWN (treat as failure).
    """
    exprs, side, variables = _split(_as_list(claims))
    result, solver, detail = _check([*side, *exprs], timeout_ms)
    if result == z3.sat:
        return SatResult(Satisfiability.SAT, _model(solver, variables))
    if result == z3.unsat:
        return SatResult(Satisfiability.UNSAT)
    return SatResult(Satisfiability.UNKNOWN, detail=detail or "solver gave up")
