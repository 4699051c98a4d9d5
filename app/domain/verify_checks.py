"""What Stage 5 checks, prepared once per verification: the contract's conditions and the
action model's preconditions as parsed, type-checked, compiled `Check`s.

In: a `Contract` (formulas already substituted: entity constants, `robot`, `@object`/`@target`
in guards). Out: `ContractChecks`: the checks every state must pass (invariants must hold, aborts
must not), the guards of each canonical action, and each action's preconditions (compiled once
per process). Guards name their action canonically; an alias is canonicalised, and a guard with
no action guards every action.
Fails: `FormulaError` with `field` set to the condition (`contract.guards[2].formula`).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from functools import cache, lru_cache

from app.domain.contracts import Contract, ContractCondition
from app.domain.errors import FormulaError
from app.domain.formula import CompiledFormula, Formula, check, compile_formula, parse
from app.domain.world import ACTION_SPECS, canonical_action
from app.domain.world.preconditions import compiled_precondition


class CheckKind(StrEnum):
    """Which of the paper's conditions (or the action model's preconditions, or the task's
    scope) a check is."""

    INVARIANT = "invariant"
    GUARD = "guard"
    ABORT = "abort"
    PRECONDITION = "precondition"
    SCOPE = "scope"


@dataclass(frozen=True, slots=True)
class Check:
    """One condition ready to check. `key` is unique within a verification; `condition_id` is
    what reports show (a template's condition bound twice shares its id)."""

    key: str
    kind: CheckKind
    condition_id: str
    text: str
    description: str
    formula: Formula
    compiled: CompiledFormula
    action: str | None = None

    @property
    def must_hold(self) -> bool:
        """True for what must hold; False for an abort, which must never hold."""
        return self.kind is not CheckKind.ABORT


@lru_cache(maxsize=4096)
def _compiled(text: str, guard: bool) -> CompiledFormula:
    """A contract formula parsed, checked and compiled; cached because a planner's repair
    attempts verify the same contract again and again."""
    formula = parse(text)
    check(formula, {}, allow_action_args=guard)
    return compile_formula(formula)


def _contract_check(condition: ContractCondition, kind: CheckKind, index: int) -> Check:
    where = f"contract.{kind.value}s[{index}].formula"
    try:
        compiled = _compiled(condition.formula, kind is CheckKind.GUARD)
    except FormulaError as error:
        raise FormulaError(f"{condition.id}: {error.detail}", line=error.line,
                           column=error.column, field=where) from error
    action = None
    if kind is CheckKind.GUARD and condition.action and condition.action != "*":
        action = canonical_action(condition.action) or condition.action
    return Check(key=f"{kind.value}[{index}]", kind=kind, condition_id=condition.id,
                 text=condition.formula, description=condition.description,
                 formula=compiled.formula,
                 compiled=compiled, action=action)


@cache
def _preconditions(action: str) -> tuple[Check, ...]:
    spec = ACTION_SPECS.get(action)
    if spec is None:
        return ()
    checks = []
    for number, precondition in enumerate(spec.preconditions, start=1):
        compiled = compiled_precondition(precondition.formula)
        condition_id = f"precondition.{action}.{number}"
        checks.append(Check(key=condition_id, kind=CheckKind.PRECONDITION,
                            condition_id=condition_id, text=precondition.formula,
                            description=precondition.description, formula=compiled.formula,
                            compiled=compiled, action=action))
    return tuple(checks)


class ContractChecks:
    """A contract's checks, indexed by when they apply."""

    __slots__ = ("_every_action", "_guards", "every_state")

    def __init__(self, invariants: tuple[Check, ...], guards: tuple[Check, ...],
                 aborts: tuple[Check, ...]) -> None:
        self.every_state: tuple[Check, ...] = (*invariants, *aborts)
        self._every_action = tuple(g for g in guards if g.action is None)
        by_action: dict[str, list[Check]] = {}
        for guard in guards:
            if guard.action is not None:
                by_action.setdefault(guard.action, []).append(guard)
        self._guards = {name: (*found, *self._every_action) for name, found in by_action.items()}

    def guards_for(self, action: str) -> tuple[Check, ...]:
        """The guards that must hold just before an action (canonical name)."""
        return self._guards.get(action, self._every_action)

    def preconditions_for(self, action: str) -> tuple[Check, ...]:
        """The action model's preconditions of an action (canonical name)."""
        return _preconditions(action)

    @staticmethod
    def preconditions_of(action: str) -> tuple[Check, ...]:
        """As `preconditions_for`, without a contract at hand."""
        return _preconditions(action)


def contract_checks(contract: Contract) -> ContractChecks:
    """Parse, type-check and compile every condition of a contract.

    Args:
        contract: the Task Safety Contract.

    Returns:
        The checks, indexed by when they apply.

    Raises:
        FormulaError: a condition does not parse or type-check (its field names it).
    """
    def build(conditions: tuple[ContractCondition, ...], kind: CheckKind) -> tuple[Check, ...]:
        return tuple(_contract_check(c, kind, i) for i, c in enumerate(conditions))

    return ContractChecks(build(contract.invariants, CheckKind.INVARIANT),
                          build(contract.guards, CheckKind.GUARD),
                          build(contract.aborts, CheckKind.ABORT))
