"""Checking an action's preconditions in a state, through the condition language.

In: a `WorldState` and a parsed `Action`. Out: each precondition's three-valued result
(`evaluate_preconditions`) or the plain-word descriptions of those that do not hold
(`check_preconditions`); a precondition the state cannot decide counts as not holding (fail
closed) and says so. Formulas are parsed, type-checked and compiled once per process.
Fails: `FormulaError` only if a spec's formula is broken (a test guards against it).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from app.domain.formula import CompiledFormula, check, compile_formula, parse
from app.domain.world.action_specs import ACTION_SPECS, Precondition
from app.domain.world.actions import Action
from app.domain.world.state import WorldState


@dataclass(frozen=True, slots=True)
class PreconditionResult:
    """One precondition and its value in a state: True, False, or None when unknown."""

    precondition: Precondition
    holds: bool | None

    @property
    def failure(self) -> str:
        """What did not hold, in words."""
        if self.holds is None:
            return f"{self.precondition.description} (cannot be established in this state)"
        return self.precondition.description


@cache
def compiled_precondition(formula: str) -> CompiledFormula:
    """The parsed, checked and compiled formula of a precondition (cached by its text)."""
    parsed = parse(formula)
    check(parsed, {}, allow_action_args=True)
    return compile_formula(parsed)


def evaluate_preconditions(state: WorldState, action: Action) -> list[PreconditionResult]:
    """Every precondition of the action with its value in the state.

    Args:
        state: the state just before the action.
        action: the parsed action.

    Returns:
        One result per precondition, in the spec's order.
    """
    args = action.args
    return [
        PreconditionResult(p, compiled_precondition(p.formula)(state, args))
        for p in ACTION_SPECS[action.name].preconditions
    ]


def check_preconditions(state: WorldState, action: Action) -> list[str]:
    """The preconditions that do not hold (or cannot be established), in plain words.

    Args:
        state: the state just before the action.
        action: the parsed action.

    Returns:
        Descriptions of the failed preconditions; empty when the action may run.
    """
    return [r.failure for r in evaluate_preconditions(state, action) if r.holds is not True]
