"""The abstract syntax of the condition language: small immutable nodes.

In: built by `app.domain.formula.parser.parse` (or by hand in tests). Out: frozen, slotted
dataclasses that compare by structure only: `line`/`column` (1-based, 0 when the node was built
by code rather than parsed) are carried for error messages but excluded from equality and hashing,
so a rendered and re-parsed formula equals the original. Nothing here fails.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True, slots=True)
class _Node:
    """Where a node starts in the source text; not part of its identity (equality ignores it)."""

    line: int = field(default=0, compare=False, repr=False, kw_only=True)
    column: int = field(default=0, compare=False, repr=False, kw_only=True)


@dataclass(frozen=True, slots=True)
class BoolConst(_Node):
    """`true` or `false`."""

    value: bool


@dataclass(frozen=True, slots=True)
class NumberLit(_Node):
    """A number literal (always a float; a leading minus is folded in)."""

    value: float


@dataclass(frozen=True, slots=True)
class StringLit(_Node):
    """A double-quoted string literal such as `"bleach"`."""

    value: str


@dataclass(frozen=True, slots=True)
class VarRef(_Node):
    """A template variable `$name` (stored without the dollar)."""

    name: str


@dataclass(frozen=True, slots=True)
class ActionArg(_Node):
    """A guarded action's argument, `@object` or `@target` (stored without the at sign)."""

    name: str


@dataclass(frozen=True, slots=True)
class RobotConst(_Node):
    """The constant `robot`: the robot being gated (entity id `robot`)."""


@dataclass(frozen=True, slots=True)
class EntityRef(_Node):
    """An entity constant, `#mug_1` or `#"Mug|+01.2"`; also a binding value for `substitute`."""

    id: str


@dataclass(frozen=True, slots=True)
class BoundVar(_Node):
    """A bare identifier: a variable bound by an enclosing quantifier."""

    name: str


@dataclass(frozen=True, slots=True)
class Apply(_Node):
    """A vocabulary predicate or function applied to arguments, `near(robot, $person)`."""

    name: str
    args: tuple[Formula, ...]


@dataclass(frozen=True, slots=True)
class Not(_Node):
    """Logical negation."""

    operand: Formula


@dataclass(frozen=True, slots=True)
class Neg(_Node):
    """Arithmetic negation of a non-literal (a literal's minus is folded into the literal)."""

    operand: Formula


@dataclass(frozen=True, slots=True)
class Logic(_Node):
    """A binary connective: `op` is one of `and`, `or`, `->`, `<->`."""

    op: str
    left: Formula
    right: Formula


@dataclass(frozen=True, slots=True)
class Compare(_Node):
    """A comparison: `op` is one of `==`, `!=`, `<`, `<=`, `>`, `>=`."""

    op: str
    left: Formula
    right: Formula


@dataclass(frozen=True, slots=True)
class Arith(_Node):
    """Arithmetic over numbers: `op` is one of `+`, `-`, `*`, `/`."""

    op: str
    left: Formula
    right: Formula


@dataclass(frozen=True, slots=True)
class Quantifier(_Node):
    """`forall var: type . body` or `exists var: type . body` over a finite typed domain."""

    kind: str
    var: str
    type: str
    body: Formula


Formula = (
    BoolConst | NumberLit | StringLit | VarRef | ActionArg | RobotConst | EntityRef | BoundVar
    | Apply | Not | Neg | Logic | Compare | Arith | Quantifier
)
"""Any node: a whole condition is a Formula whose type is `bool`."""

LOGIC_OPS = ("and", "or", "->", "<->")
COMPARE_OPS = ("==", "!=", "<", "<=", ">", ">=")
ARITH_OPS = ("+", "-", "*", "/")
QUANTIFIER_KINDS = ("forall", "exists")
QUANTIFIER_TYPES = ("person", "object", "room")
ROBOT_ID = "robot"
"""The entity id of the constant `robot` in every state."""


def children(node: Formula) -> tuple[Formula, ...]:
    """The direct sub-formulas of a node, left to right."""
    if isinstance(node, Apply):
        return node.args
    if isinstance(node, Not | Neg):
        return (node.operand,)
    if isinstance(node, Logic | Compare | Arith):
        return (node.left, node.right)
    if isinstance(node, Quantifier):
        return (node.body,)
    return ()
