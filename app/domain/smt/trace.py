"""Prove conditions state by state along a plan's trace, with one incremental Z3 solver.

In: condition instances, each a checked, substituted `Formula`, one state of the trace s0..sL (any
`Facts`), optionally the guarded action's arguments, and whether the condition must hold
(invariant, guard, precondition) or must never hold (abort). Out: a `TraceProof`: HOLDS,
VIOLATED with a counterexample in terms of that state's facts (known values as they are, unknown
ones as the solver chose them), or UNKNOWN with the reason (a solver `unknown`, a Z3 error, or
the time budget spent). UNKNOWN never means "holds".

Why it is fast: one solver serves the whole trace, each claim is checked inside push/pop, and a
claim is only encoded once per distinct input. The encoder is deterministic in the values it
reads, so when a state gives the same values to the facts an earlier encoding of the same claim
read, the encoding (and the answer) is the same: the cache key is those values. Background
axioms on unknowns (an age group is one of five words, a distance is not negative) are asserted
once per unknown, outside push/pop; they only exclude impossible values.
Fails: `FormulaError` or `ValueError` from `encode` on a malformed formula or state.
"""

from __future__ import annotations

import time
from collections.abc import Hashable, Mapping, Sequence
from dataclasses import dataclass, field

import z3

from app.domain.formula.facts import ActionArgs, Facts, FactValue, Unknown, Value, fact_key
from app.domain.formula.nodes import Formula
from app.domain.smt.encoder import encode
from app.domain.smt.solver import Outcome, _python_value

FactRead = tuple[str, tuple[str, ...]]

_WORDS: dict[str, tuple[str, ...]] = {
    "age_group": ("infant", "child", "teen", "adult", "older_adult"),
    "mobility": ("independent", "assisted", "wheelchair", "bedridden"),
    "cognitive_state": ("typical", "impaired", "asleep", "intoxicated"),
}
_NON_NEGATIVE = frozenset({"mass_kg", "distance", "speed", "max_speed", "payload", "load_kg"})
_DOMAIN_TYPES = ("robot", "object", "person", "room")


@dataclass(frozen=True, slots=True)
class TraceProof:
    """The answer for one condition instance.

    `counterexample` maps fact names (`hot(mug_1)`) to values that break the claim; `free` names
    those the solver chose because the state left them unknown.
    """

    outcome: Outcome
    counterexample: Mapping[str, Value] = field(default_factory=dict)
    free: tuple[str, ...] = ()
    detail: str = ""


class _RecordingFacts:
    """A state that remembers every fact read through it, in first-read order."""

    __slots__ = ("inner", "reads")

    def __init__(self, inner: Facts) -> None:
        self.inner = inner
        self.reads: dict[FactRead, FactValue] = {}

    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        found = self.inner.value(symbol, args)
        self.reads.setdefault((symbol, args), found)
        return found

    def domain(self, type_name: str) -> Sequence[str]:
        return self.inner.domain(type_name)

    def entity_type(self, entity_id: str) -> str | None:
        return self.inner.entity_type(entity_id)


def _axiom(symbol: str, var: z3.ExprRef) -> z3.BoolRef | None:
    words = _WORDS.get(symbol)
    if words is not None and z3.is_string(var):
        return z3.Or([var == z3.StringVal(word) for word in words])
    if symbol in _NON_NEGATIVE and z3.is_arith(var):
        return var >= 0
    return None


class TraceProver:
    """Proves condition instances over the states of one trace within one time budget."""

    def __init__(self, timeout_ms: int) -> None:
        """Start a solver whose checks together may take at most `timeout_ms` of wall time.

        Args:
            timeout_ms: the budget for every check of this trace, counted from now.
        """
        self._timeout_ms = timeout_ms
        self._deadline = time.monotonic() + timeout_ms / 1000
        self._solver = z3.Solver()
        self._axiomatized: set[str] = set()
        self._signatures: dict[Hashable, list[tuple[FactRead, ...]]] = {}
        self._answers: dict[Hashable, TraceProof] = {}
        self.solver_calls = 0
        self.cache_hits = 0

    @property
    def out_of_time(self) -> bool:
        """Whether the budget is spent (every later check would be UNKNOWN)."""
        return time.monotonic() >= self._deadline

    def prove(
        self,
        claim: Hashable,
        formula: Formula,
        facts: Facts,
        action_args: ActionArgs | None = None,
        *,
        must_hold: bool = True,
    ) -> TraceProof:
        """Whether a condition holds (or, for `must_hold=False`, fails) for every unknown value.

        Args:
            claim: identifies the condition (same claim, same formula) for the cache.
            formula: the condition, checked and substituted.
            facts: the state of the trace it is about.
            action_args: the guarded action's `object`/`target` ids.
            must_hold: True for invariants, guards and preconditions; False for aborts.

        Returns:
            HOLDS, VIOLATED with a counterexample, or UNKNOWN with the reason.
        """
        context = (tuple(sorted((action_args or {}).items())),
                   tuple(tuple(facts.domain(kind)) for kind in _DOMAIN_TYPES))
        for signature in self._signatures.get(claim, ()):
            key = (claim, must_hold, context, signature,
                   tuple(facts.value(symbol, args) for symbol, args in signature))
            cached = self._answers.get(key)
            if cached is not None:
                self.cache_hits += 1
                return cached
        if self.out_of_time:
            return TraceProof(Outcome.UNKNOWN, detail=self._timeout_detail())
        recorder = _RecordingFacts(facts)
        encoding = encode(formula, recorder, action_args)
        self._add_axioms(recorder.reads, encoding.unknowns)
        goal = z3.Not(encoding.expr) if must_hold else encoding.expr
        proof = self._check([*encoding.assumptions, goal], recorder.reads, encoding.unknowns)
        if proof.outcome is not Outcome.UNKNOWN:
            signature = tuple(recorder.reads)
            self._signatures.setdefault(claim, []).append(signature)
            key = (claim, must_hold, context, signature, tuple(recorder.reads.values()))
            self._answers[key] = proof
        return proof

    def _timeout_detail(self) -> str:
        return f"timeout: the solver budget of {self._timeout_ms} ms is spent"

    def _add_axioms(self, reads: Mapping[FactRead, FactValue],
                    variables: Mapping[str, z3.ExprRef]) -> None:
        for (symbol, _), value in reads.items():
            if not isinstance(value, Unknown) or value.key in self._axiomatized:
                continue
            self._axiomatized.add(value.key)
            var = variables.get(value.key)
            axiom = None if var is None else _axiom(symbol, var)
            if axiom is not None:
                self._solver.add(axiom)

    def _check(self, goal: list[z3.BoolRef], reads: Mapping[FactRead, FactValue],
               variables: Mapping[str, z3.ExprRef]) -> TraceProof:
        remaining_ms = int((self._deadline - time.monotonic()) * 1000)
        if remaining_ms <= 0:
            return TraceProof(Outcome.UNKNOWN, detail=self._timeout_detail())
        solver = self._solver
        solver.push()
        try:
            solver.set("timeout", remaining_ms)
            solver.add(*goal)
            self.solver_calls += 1
            result = solver.check()
            if result == z3.unsat:
                return TraceProof(Outcome.HOLDS)
            if result == z3.sat:
                return _counterexample(solver.model(), reads, variables)
            reason = solver.reason_unknown() or "solver gave up"
            if self.out_of_time or "timeout" in reason or "canceled" in reason:
                return TraceProof(Outcome.UNKNOWN, detail=self._timeout_detail())
            return TraceProof(Outcome.UNKNOWN, detail=f"solver unknown: {reason}")
        except z3.Z3Exception as error:
            return TraceProof(Outcome.UNKNOWN, detail=f"z3 error: {error}")
        finally:
            solver.pop()


def _counterexample(model: z3.ModelRef, reads: Mapping[FactRead, FactValue],
                    variables: Mapping[str, z3.ExprRef]) -> TraceProof:
    chosen = {key: _python_value(model.eval(var, model_completion=True))
              for key, var in variables.items()}
    values: dict[str, Value] = {}
    free: list[str] = []
    covered: set[str] = set()
    for (symbol, args), value in reads.items():
        name = fact_key(symbol, args)
        if isinstance(value, Unknown):
            covered.add(value.key)
            if value.key in chosen:
                values[name] = chosen[value.key]
                free.append(name)
        else:
            values[name] = value
    for key in sorted(set(chosen) - covered):
        values[key] = chosen[key]
        free.append(key)
    return TraceProof(Outcome.VIOLATED, values, tuple(free))
