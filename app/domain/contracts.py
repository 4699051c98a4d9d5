"""Stage 4, Contract Compilation: the Task Safety Contract of an authorized task.

In: the bound hazards from Stage 2, the baseline envelope (templates that apply to every task) and
the task's scope (`scope.py`). Out: a `Contract` = (invariants, guards, aborts, scope): the union of
the matched and baseline templates' conditions with their variables substituted on the parsed
formulas (not by text replacement), defaults filled, deduplicated by (condition id, bindings), and
every formula type-checked against the vocabulary after substitution; conditions of the envelope are
marked `envelope`. A contract stored before scopes existed has `scope` None: its plans are not
checked against a scope. It also renders the contract as plain planning constraints (envelope,
matched conditions, scope), so a planner can be told the rules before it writes a plan.
Fails: `FormulaError` if a template's condition does not parse or check (a library defect: the
gate must not authorize on it).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping

from pydantic import BaseModel, ConfigDict

from app.domain.binding import BindingValue, BoundHazard, BoundTemplate
from app.domain.formula import EntityRef, check, parse, render, substitute
from app.domain.models import ConditionKind, TemplateCondition, VariableType
from app.domain.scope import TaskScope, scope_lines
from app.domain.world.action_specs import ACTION_SPECS

_ENTITY_TYPES = {"object", "person", "room", "robot", "entity"}


class ContractCondition(BaseModel):
    """One bound condition of a contract."""

    model_config = ConfigDict(frozen=True)

    id: str
    kind: ConditionKind
    formula: str
    description: str
    action: str | None = None
    template_id: str
    template_version: int
    bindings: dict[str, BindingValue]
    envelope: bool = False
    """From a template that applies to every task (the baseline envelope)."""


class Contract(BaseModel):
    """A Task Safety Contract: what must always hold, what must hold before which action, and
    what halts execution at once."""

    model_config = ConfigDict(frozen=True)

    invariants: tuple[ContractCondition, ...] = ()
    guards: tuple[ContractCondition, ...] = ()
    aborts: tuple[ContractCondition, ...] = ()
    template_versions: dict[str, int] = {}
    scope: TaskScope | None = None
    """What the task authorizes; None for a contract compiled before scopes (or inline)."""

    @property
    def conditions(self) -> tuple[ContractCondition, ...]:
        return (*self.invariants, *self.guards, *self.aborts)

    def __len__(self) -> int:
        return len(self.invariants) + len(self.guards) + len(self.aborts)


def compile_contract(bound: Iterable[BoundHazard],
                     baseline: Iterable[BoundTemplate] = (),
                     scope: TaskScope | None = None) -> Contract:
    """Compile the contract for an authorized task from its bound hazards.

    Args:
        bound: every bound hazard with its matched templates.
        baseline: templates that apply to every task (the baseline envelope), already bound.
        scope: the task's scope, stored with the contract.

    Returns:
        The deduplicated, type-checked contract.

    Raises:
        FormulaError: a template condition does not parse or type-check once bound.
    """
    by_kind: dict[ConditionKind, dict[tuple[str, str], ContractCondition]] = {
        kind: {} for kind in ConditionKind
    }
    versions: dict[str, int] = {}
    envelope = list(baseline)
    matches = [*(m for hazard in bound for m in hazard.matches), *envelope]
    always = {id(m) for m in envelope}
    for match in matches:
        versions[match.template.id] = match.template.version
        for kind, condition in match.template.conditions():
            compiled = _bind_condition(match, kind, condition, envelope=id(match) in always)
            key = (compiled.id, render_bindings(compiled.bindings))
            by_kind[kind].setdefault(key, compiled)
    return Contract(
        invariants=tuple(by_kind[ConditionKind.INVARIANT].values()),
        guards=tuple(by_kind[ConditionKind.GUARD].values()),
        aborts=tuple(by_kind[ConditionKind.ABORT].values()),
        template_versions=versions,
        scope=scope,
    )


def _bind_condition(
    match: BoundTemplate, kind: ConditionKind, condition: TemplateCondition, *, envelope: bool
) -> ContractCondition:
    template = match.template
    variable_types = {v.name: v.type.value for v in template.variables}
    formula = parse(condition.formula)
    check(formula, variable_types, allow_action_args=kind is ConditionKind.GUARD)
    used = _used_bindings(condition.formula, match.bindings)
    substituted = substitute(formula, _as_terms(used, variable_types))
    check(substituted, {}, allow_action_args=kind is ConditionKind.GUARD)
    return ContractCondition(
        id=f"{template.id}.{condition.id}",
        kind=kind,
        formula=render(substituted),
        description=condition.description,
        action=condition.action,
        template_id=template.id,
        template_version=template.version,
        bindings=used,
        envelope=envelope,
    )


def _used_bindings(
    formula_text: str, bindings: Mapping[str, BindingValue]
) -> dict[str, BindingValue]:
    """Only the bindings the condition mentions, so the dedup key ignores irrelevant ones."""
    return {
        name: value
        for name, value in bindings.items()
        if re.search(rf"\${re.escape(name)}\b", formula_text)
    }


def _as_terms(
    bindings: Mapping[str, BindingValue], variable_types: Mapping[str, str]
) -> dict[str, object]:
    terms: dict[str, object] = {}
    for name, value in bindings.items():
        if variable_types.get(name) in _ENTITY_TYPES and isinstance(value, str):
            terms[name] = EntityRef(value)
        elif variable_types.get(name) == VariableType.NUMBER.value and not isinstance(value, bool):
            terms[name] = float(value)
        else:
            terms[name] = value
    return terms


def render_bindings(bindings: Mapping[str, BindingValue]) -> str:
    """A stable text form of bindings, e.g. `obj=mug_1,person=person_1`."""
    return ",".join(f"{k}={bindings[k]}" for k in sorted(bindings))


def planner_constraints(contract: Contract) -> list[str]:
    """The contract in plain words, one constraint a line, ready for a planner's prompt.

    Each condition's line says when the rule applies (in every state; just before every step
    of a named action, with what that action does; or as a stop condition), the rule in words,
    the concrete entities and values it is about, and the exact condition with its id, so a
    planner can both follow it and match a `/verify` violation back to it. The baseline
    envelope's conditions come first, each marked as holding for every task; the task's scope
    (what the command authorizes) follows the conditions.

    Args:
        contract: a compiled contract.

    Returns:
        Sentences naming the concrete entities each condition is about, the scope in words
        (when the contract has one), then one closing note on preconditions and unknown facts.
    """
    lines: list[str] = []
    for envelope in (True, False):
        mark = "For every task (baseline envelope). " if envelope else ""
        for condition in contract.invariants:
            if condition.envelope is envelope:
                lines.append(f"{mark}In every state, from start to finish: "
                             f"{_sentence(condition)}")
        for condition in contract.guards:
            if condition.envelope is envelope:
                lines.append(f"{mark}{_guard_scope(condition.action)}: {_sentence(condition)}")
        for condition in contract.aborts:
            if condition.envelope is envelope:
                lines.append(f"{mark}Never let this happen (execution halts at once): "
                             f"{_sentence(condition)}")
    if contract.scope is not None:
        lines.extend(f"Task scope: {line}" for line in scope_lines(contract.scope))
    lines.append(
        "Every step must also meet its action's own preconditions (be next to what it picks "
        "up, hold what it puts down or hands over). A fact the scene does not state counts "
        "against the plan: if a rule depends on it, make the plan safe whatever its value."
    )
    return lines


def _guard_scope(action: str | None) -> str:
    if not action:
        return "Just before every step"
    spec = ACTION_SPECS.get(action)
    what = f" ({spec.summary})" if spec is not None else ""
    return f"Just before every {action} step{what}"


def _sentence(condition: ContractCondition) -> str:
    text = condition.description.strip().rstrip(".")
    # Entities by their ids (what a plan names); other values with the variable they set.
    entities = [str(v) for _, v in sorted(condition.bindings.items())
                if isinstance(v, str) and f"#{v}" in condition.formula]
    values = [f"{k} = {v}" for k, v in sorted(condition.bindings.items())
              if str(v) not in entities]
    about = "; ".join(part for part in (", ".join(entities), ", ".join(values)) if part)
    where = f" Applies to: {about}." if about else ""
    arguments = [f"@{name} is that step's {name}" for name in ("object", "target")
                 if f"@{name}" in condition.formula]
    args = f", where {' and '.join(arguments)}" if arguments else ""
    return f"{text}.{where} Condition: {condition.formula}{args} [{condition.id}]"
