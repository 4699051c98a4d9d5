"""Rewriting and inspecting formulas on the AST: substitution and the symbols a formula uses.

In: a `Formula` and, for `substitute`, bindings from `$var` names (without `$`) to values: an
`EntityRef` for an entity, or a plain bool, int/float or str. Out: a new `Formula` (the input is
immutable and untouched) or sets of names. A str binds to an entity constant when the variable is
an entity variable (declared so in `variables`, or, without declarations, used where the
vocabulary expects an entity or compared with one), and to a string literal otherwise. Fails with
`FormulaError` for a binding of a type no literal can hold (positioned at the variable).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace

from app.domain.errors import FormulaError
from app.domain.formula.nodes import (
    ActionArg,
    Apply,
    Arith,
    BoolConst,
    BoundVar,
    Compare,
    EntityRef,
    Formula,
    Logic,
    Neg,
    Not,
    NumberLit,
    Quantifier,
    RobotConst,
    StringLit,
    VarRef,
    children,
)
from app.domain.formula.vocabulary import VOCABULARY

_ENTITY_TYPES = frozenset({"robot", "object", "person", "room", "entity"})


def _walk(node: Formula) -> list[Formula]:
    found = [node]
    stack = list(children(node))
    while stack:
        current = stack.pop()
        found.append(current)
        stack.extend(children(current))
    return found


def symbols_used(formula: Formula) -> frozenset[str]:
    """The names of every predicate and function the formula applies."""
    return frozenset(node.name for node in _walk(formula) if isinstance(node, Apply))


def variables_used(formula: Formula) -> frozenset[str]:
    """The template variables (`$name`, returned without `$`) the formula still mentions."""
    return frozenset(node.name for node in _walk(formula) if isinstance(node, VarRef))


def uses_action_args(formula: Formula) -> bool:
    """Whether the formula names `@object` or `@target` (so only a guard may hold it)."""
    return any(isinstance(node, ActionArg) for node in _walk(formula))


def _is_entity_expression(node: Formula) -> bool:
    return isinstance(node, EntityRef | RobotConst | ActionArg | BoundVar)


def entity_variables(formula: Formula) -> frozenset[str]:
    """Variables whose use shows they denote entities: vocabulary entity positions, or `==`/`!=`
    against an entity expression."""
    found: set[str] = set()
    for node in _walk(formula):
        if isinstance(node, Apply) and node.name in VOCABULARY:
            for arg, expected in zip(node.args, VOCABULARY[node.name].args, strict=False):
                if isinstance(arg, VarRef) and expected in _ENTITY_TYPES:
                    found.add(arg.name)
        elif isinstance(node, Compare):
            for mine, other in ((node.left, node.right), (node.right, node.left)):
                if isinstance(mine, VarRef) and _is_entity_expression(other):
                    found.add(mine.name)
    return frozenset(found)


def _literal(node: VarRef, value: object, as_entity: bool) -> Formula:
    line, column = node.line, node.column
    if isinstance(value, EntityRef):
        return EntityRef(value.id, line=line, column=column)
    if isinstance(value, ActionArg):
        # A variable bound at evaluation time, like a guard's `@object` (see the analyzer's
        # judge, which evaluates one compiled condition under many bindings).
        return ActionArg(value.name, line=line, column=column)
    if isinstance(value, bool):
        return BoolConst(value, line=line, column=column)
    if isinstance(value, int | float):
        if not math.isfinite(value):
            raise FormulaError(
                f"${node.name} cannot be bound to {value!r}", line=line, column=column
            )
        return NumberLit(float(value), line=line, column=column)
    if isinstance(value, str):
        if as_entity:
            return EntityRef(value, line=line, column=column)
        return StringLit(value, line=line, column=column)
    raise FormulaError(
        f"${node.name} cannot be bound to a {type(value).__name__}; use an EntityRef, "
        "a number, a string or a bool",
        line=line,
        column=column,
    )


def substitute(
    formula: Formula,
    bindings: Mapping[str, object],
    *,
    variables: Mapping[str, str] | None = None,
) -> Formula:
    """Replace template variables by constants.

    Args:
        formula: the condition.
        bindings: `$var` name (without `$`) to an `EntityRef`, bool, number or str, or an
            `ActionArg` whose value the evaluator reads from its arguments at evaluation time.
            Variables without a binding are left in place.
        variables: the declared variable types; when given, a str bound to an entity-typed
            variable becomes an entity constant. Without it, usage decides.

    Returns:
        The substituted formula (a literal's unary minus is folded into the literal).

    Raises:
        FormulaError: a binding value no literal can hold.
    """
    if variables is not None:
        entity_names = frozenset(
            name for name, type_name in variables.items() if type_name in _ENTITY_TYPES
        )
    else:
        entity_names = entity_variables(formula)
    return _substitute(formula, bindings, entity_names)


def _substitute(node: Formula, bindings: Mapping[str, object], entities: frozenset[str]) -> Formula:
    if isinstance(node, VarRef):
        if node.name not in bindings:
            return node
        return _literal(node, bindings[node.name], node.name in entities)
    if isinstance(node, Apply):
        return replace(node, args=tuple(_substitute(arg, bindings, entities) for arg in node.args))
    if isinstance(node, Neg):
        operand = _substitute(node.operand, bindings, entities)
        if isinstance(operand, NumberLit):
            return NumberLit(-operand.value, line=node.line, column=node.column)
        return replace(node, operand=operand)
    if isinstance(node, Not):
        return replace(node, operand=_substitute(node.operand, bindings, entities))
    if isinstance(node, Logic | Compare | Arith):
        return replace(
            node,
            left=_substitute(node.left, bindings, entities),
            right=_substitute(node.right, bindings, entities),
        )
    if isinstance(node, Quantifier):
        return replace(node, body=_substitute(node.body, bindings, entities))
    return node

