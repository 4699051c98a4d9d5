"""Canonical text for a formula: `parse(render(f)) == f` for every formula.

In: a `Formula`. Out: its text with single spaces around binary operators and the fewest
parentheses the grammar's precedence allows (a quantifier is parenthesised unless it is the last
thing in its connective context, since its body extends to the right). Fails with `FormulaError`
on a number that has no literal (infinity, NaN).
"""

from __future__ import annotations

import math
import re

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
)

# Binding strength, loosest first; mirrors grammar.lark.
_QUANTIFIER, _IFF, _IMPLIES, _OR, _AND, _NOT, _COMPARE, _SUM, _PRODUCT, _UNARY, _ATOM = range(11)
_LOGIC_LEVEL = {"<->": _IFF, "->": _IMPLIES, "or": _OR, "and": _AND}
_PLAIN_ID = re.compile(r"[A-Za-z0-9_]+")


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _number(value: float) -> str:
    if not math.isfinite(value):
        raise FormulaError(f"the number {value!r} has no literal")
    return repr(float(value))


def _level(node: Formula) -> int:
    if isinstance(node, Quantifier):
        return _QUANTIFIER
    if isinstance(node, Logic):
        return _LOGIC_LEVEL[node.op]
    if isinstance(node, Not):
        return _NOT
    if isinstance(node, Compare):
        return _COMPARE
    if isinstance(node, Arith):
        return _SUM if node.op in "+-" else _PRODUCT
    if isinstance(node, Neg) or (isinstance(node, NumberLit) and math.copysign(1, node.value) < 0):
        return _UNARY
    return _ATOM


def _child(node: Formula, minimum: int, last: bool) -> str:
    """Render a child that must bind at least as tightly as `minimum`.

    `last` says nothing follows it before the enclosing context ends, so a quantifier there may
    go without parentheses when the context accepts a quantifier at all (connective operands).
    """
    level = _level(node)
    quantifier_allowed = last and minimum <= _NOT
    if not quantifier_allowed if level == _QUANTIFIER else level < minimum:
        return f"({_render(node, last=True)})"
    return _render(node, last=last)


def _render(node: Formula, last: bool) -> str:
    if isinstance(node, BoolConst):
        return "true" if node.value else "false"
    if isinstance(node, NumberLit):
        return _number(node.value)
    if isinstance(node, StringLit):
        return _quote(node.value)
    if isinstance(node, VarRef):
        return f"${node.name}"
    if isinstance(node, ActionArg):
        return f"@{node.name}"
    if isinstance(node, RobotConst):
        return "robot"
    if isinstance(node, EntityRef):
        return f"#{node.id}" if _PLAIN_ID.fullmatch(node.id) else f"#{_quote(node.id)}"
    if isinstance(node, BoundVar):
        return node.name
    if isinstance(node, Apply):
        return f"{node.name}({', '.join(_render(arg, last=True) for arg in node.args)})"
    if isinstance(node, Not):
        return f"not {_child(node.operand, _NOT, last)}"
    if isinstance(node, Neg):
        return f"-{_child(node.operand, _UNARY, last)}"
    if isinstance(node, Quantifier):
        return f"{node.kind} {node.var}: {node.type} . {_render(node.body, last=True)}"
    if isinstance(node, Logic):
        level = _LOGIC_LEVEL[node.op]
        right_assoc = node.op == "->"
        left = _child(node.left, level + 1 if right_assoc else level, last=False)
        right = _child(node.right, level if right_assoc else level + 1, last)
        return f"{left} {node.op} {right}"
    if isinstance(node, Compare):
        left = _child(node.left, _SUM, last=False)
        return f"{left} {node.op} {_child(node.right, _SUM, last)}"
    if isinstance(node, Arith):
        level = _level(node)
        left = _child(node.left, level, last=False)
        return f"{left} {node.op} {_child(node.right, level + 1, last)}"
    raise TypeError(f"not a formula node: {node!r}")


def render(formula: Formula) -> str:
    """The canonical text of a formula; re-parsing it gives an equal formula.

    Args:
        formula: any formula node.

    Returns:
        Its text, e.g. `hot(#mug_1) and not lidded(#mug_1) -> near(robot, #p1)`.

    Raises:
        FormulaError: a number literal that is infinite or NaN.
    """
    return _render(formula, last=True)
