"""A contract's conditions compiled once for monitoring, and their three-valued evaluation.

In: a `Contract` (Stage 4). Out: a `CompiledContract` whose invariants, aborts and guards (grouped
by the canonical action they guard) are ready-to-run `CompiledFormula`s, with the task's scope
indexed for checking (`scope`, None for a contract without one), and `first_failure`, which
evaluates a group of conditions in a state and names the one that fails, if any.

Fail closed: a guard or an invariant fails unless it is *true*; an abort fails unless it is
*false*. An unknown result is therefore a failure, marked `established=False`, and
`unknown_facts` names the facts the state left undetermined so the violation can say what the
runtime must observe. A definite failure is preferred over an unknown one when both occur.
Fails: `FormulaError` (an `InvalidInput`) at compile time when a condition does not parse or
type-check, or a guard names an action that does not exist: such a contract cannot be monitored.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from app.domain.contracts import Contract, ContractCondition, render_bindings
from app.domain.errors import FormulaError
from app.domain.formula import (
    ActionArgs,
    CompiledFormula,
    Facts,
    FactValue,
    Unknown,
    check,
    compile_formula,
    parse,
)
from app.domain.models import ConditionKind
from app.domain.scope_check import ScopeMatcher
from app.domain.world import canonical_action

MAX_UNKNOWN_FACTS = 8


@dataclass(frozen=True, slots=True)
class CompiledCondition:
    """One contract condition with its compiled formula.

    `key` tells apart conditions that share an id but differ in their bindings (one template
    bound to several objects), for the per-condition counts of the summary.
    """

    condition: ContractCondition
    formula: CompiledFormula
    key: str

    @property
    def kind(self) -> str:
        """`invariant`, `guard` or `abort`."""
        return self.condition.kind.value


@dataclass(frozen=True, slots=True)
class Failure:
    """A condition that did not pass: definitely (`established`) or because of unknown facts."""

    compiled: CompiledCondition
    established: bool
    unknown_facts: tuple[str, ...] = ()


class _RecordingFacts:
    """A `Facts` that notes every unknown it hands out (used only to explain a failure)."""

    def __init__(self, inner: Facts) -> None:
        self._inner = inner
        self.unknown: dict[str, None] = {}

    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        found = self._inner.value(symbol, args)
        if isinstance(found, Unknown):
            self.unknown.setdefault(found.key)
        return found

    def domain(self, type_name: str) -> Sequence[str]:
        return self._inner.domain(type_name)

    def entity_type(self, entity_id: str) -> str | None:
        return self._inner.entity_type(entity_id)


def unknown_facts(
    compiled: CompiledFormula, facts: Facts, args: ActionArgs | None = None
) -> tuple[str, ...]:
    """The undetermined facts an evaluation reads, in reading order (at most a few)."""
    recorder = _RecordingFacts(facts)
    compiled(recorder, args)
    return tuple(recorder.unknown)[:MAX_UNKNOWN_FACTS]


def _compile(condition: ContractCondition) -> CompiledCondition:
    try:
        parsed = parse(condition.formula)
        check(parsed, {}, allow_action_args=condition.kind is ConditionKind.GUARD)
        formula = compile_formula(parsed)
    except FormulaError as error:
        raise FormulaError(
            f"condition {condition.id} cannot be monitored: {error.detail}",
            line=error.line, column=error.column, field="contract",
        ) from error
    bindings = render_bindings(condition.bindings)
    key = f"{condition.id}[{bindings}]" if bindings else condition.id
    return CompiledCondition(condition, formula, key)


class CompiledContract:
    """A contract ready to monitor; immutable, so sessions of one contract may share it."""

    __slots__ = ("_guards", "_universal_guards", "aborts", "contract", "invariants", "scope")

    def __init__(self, contract: Contract) -> None:
        """Compile every condition once.

        Args:
            contract: the Task Safety Contract.

        Raises:
            FormulaError: a condition does not parse or check, or a guard's action is unknown.
        """
        self.contract = contract
        self.scope = None if contract.scope is None else ScopeMatcher(contract.scope)
        self.invariants = tuple(_compile(c) for c in contract.invariants)
        self.aborts = tuple(_compile(c) for c in contract.aborts)
        by_action: dict[str, list[CompiledCondition]] = {}
        universal: list[CompiledCondition] = []
        for condition in contract.guards:
            compiled = _compile(condition)
            if condition.action is None:
                universal.append(compiled)  # a guard naming no action guards every action
                continue
            name = canonical_action(condition.action)
            if name is None:
                raise FormulaError(
                    f"guard {condition.id} names an unknown action {condition.action!r}",
                    field="contract",
                )
            by_action.setdefault(name, []).append(compiled)
        self._universal_guards = tuple(universal)
        self._guards: Mapping[str, tuple[CompiledCondition, ...]] = {
            name: (*universal, *guards) for name, guards in by_action.items()
        }

    def guards_for(self, action: str) -> tuple[CompiledCondition, ...]:
        """The guards to check before an action of this canonical name."""
        return self._guards.get(action, self._universal_guards)

    @property
    def conditions(self) -> tuple[CompiledCondition, ...]:
        """Every compiled condition: invariants, guards (each once), aborts."""
        guards = {id(g): g for group in self._guards.values() for g in group}
        guards.update({id(g): g for g in self._universal_guards})
        return (*self.invariants, *guards.values(), *self.aborts)

    def __len__(self) -> int:
        return len(self.contract)


def first_failure(
    conditions: tuple[CompiledCondition, ...],
    facts: Facts,
    args: ActionArgs | None,
    *,
    must_be: bool,
) -> Failure | None:
    """Evaluate every condition of a group and report the one that fails, if any.

    Args:
        conditions: the group (all evaluated, so the counts of checks are exact).
        facts: the state.
        args: the guarded action's `@object`/`@target`, or None outside guards.
        must_be: True for guards and invariants, False for aborts.

    Returns:
        None when every condition has the required value; else the first definite failure, or
        failing that the first condition the state leaves unknown (with the facts it lacked).
    """
    unknown: CompiledCondition | None = None
    for compiled in conditions:
        value = compiled.formula(facts, args)
        if value is must_be:
            continue
        if value is None:
            if unknown is None:
                unknown = compiled
            continue
        return Failure(compiled, established=True)
    if unknown is None:
        return None
    return Failure(unknown, established=False,
                   unknown_facts=unknown_facts(unknown.formula, facts, args))
