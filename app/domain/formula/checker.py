"""Static checking of a parsed condition against the typed vocabulary.

In: a `Formula`, the template's variables (name without `$` -> type) and whether the formula is a
guard (only guards may name `@object`/`@target`). Out: nothing when the condition is well typed;
`infer_type` also answers the type of any sub-formula. Fails with `FormulaError` carrying the
line/column of the offending node for: an unknown predicate or function (with a "did you mean"
suggestion), a wrong number of arguments, an argument of the wrong type, an undeclared `$var`, a
free bare identifier, an action argument outside a guard, comparing incompatible types, ordering
non-numbers, and a condition that is not `bool` at the top.

Entity subtyping: `robot`, `object` and `person` are `entity`s. An expression typed only `entity`
(`@object`, an `#entity` constant after substitution) is accepted where a specific entity type is
expected, because its type is only known in a state; a definite mismatch (a person where an
object is expected, a room anywhere an entity is expected) is refused.
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping

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
from app.domain.formula.vocabulary import ALL_TYPES, VOCABULARY

_ENTITY_KINDS = frozenset({"robot", "object", "person", "entity"})
OPAQUE_ENTITY = "entity or room"
"""The type of an `#id` constant or an `@object`/`@target` argument: which kind of entity it
names is only known in a state, so it may stand wherever an entity or a room is expected."""
_ORDERED_OPS = frozenset({"<", "<=", ">", ">="})


def _fail(node: Formula, message: str) -> FormulaError:
    return FormulaError(
        f"{message} (line {node.line}, column {node.column})", line=node.line, column=node.column
    )


def _suggest(name: str, known: list[str], prefix: str = "") -> str:
    close = difflib.get_close_matches(name, known, n=1, cutoff=0.6)
    return f"; did you mean '{prefix}{close[0]}'?" if close else ""


def accepts(expected: str, actual: str) -> bool:
    """Whether an expression of type `actual` may stand where `expected` is required."""
    if expected == actual:
        return True
    if actual == OPAQUE_ENTITY:
        return expected in _ENTITY_KINDS or expected == "room"
    if expected == OPAQUE_ENTITY:
        return actual in _ENTITY_KINDS or actual == "room"
    if expected == "entity":
        return actual in _ENTITY_KINDS
    return expected in _ENTITY_KINDS and actual == "entity"


def comparable(left: str, right: str) -> bool:
    """Whether two types may be compared with `==`/`!=`."""
    return accepts(left, right) or accepts(right, left)


class _Checker:
    def __init__(self, variables: Mapping[str, str], allow_action_args: bool) -> None:
        self.variables = variables
        self.allow_action_args = allow_action_args

    def infer(self, node: Formula, scope: Mapping[str, str]) -> str:
        if isinstance(node, BoolConst):
            return "bool"
        if isinstance(node, NumberLit):
            return "number"
        if isinstance(node, StringLit):
            return "string"
        if isinstance(node, RobotConst):
            return "robot"
        if isinstance(node, EntityRef):
            return OPAQUE_ENTITY
        if isinstance(node, VarRef):
            return self._variable(node)
        if isinstance(node, ActionArg):
            if not self.allow_action_args:
                raise _fail(node, f"@{node.name} may only be used in a guard")
            return OPAQUE_ENTITY
        if isinstance(node, BoundVar):
            if node.name not in scope:
                hint = _suggest(node.name, list(scope))
                raise _fail(
                    node,
                    f"unbound variable '{node.name}' (bind it with forall/exists, or write "
                    f"${node.name} for a template variable){hint}",
                )
            return scope[node.name]
        if isinstance(node, Apply):
            return self._apply(node, scope)
        if isinstance(node, Not):
            self._expect(node.operand, "bool", scope, "the operand of 'not'")
            return "bool"
        if isinstance(node, Neg):
            self._expect(node.operand, "number", scope, "the operand of unary '-'")
            return "number"
        if isinstance(node, Logic):
            self._expect(node.left, "bool", scope, f"the left side of '{node.op}'")
            self._expect(node.right, "bool", scope, f"the right side of '{node.op}'")
            return "bool"
        if isinstance(node, Arith):
            self._expect(node.left, "number", scope, f"the left side of '{node.op}'")
            self._expect(node.right, "number", scope, f"the right side of '{node.op}'")
            return "number"
        if isinstance(node, Compare):
            return self._compare(node, scope)
        if isinstance(node, Quantifier):
            self._expect(node.body, "bool", {**scope, node.var: node.type}, "a quantifier's body")
            return "bool"
        raise TypeError(f"not a formula node: {node!r}")

    def _variable(self, node: VarRef) -> str:
        declared = self.variables.get(node.name)
        if declared is None:
            hint = _suggest(node.name, list(self.variables), prefix="$")
            raise _fail(node, f"undeclared template variable ${node.name}{hint}")
        if declared not in ALL_TYPES:
            raise _fail(node, f"template variable ${node.name} has unknown type '{declared}'")
        return declared

    def _apply(self, node: Apply, scope: Mapping[str, str]) -> str:
        symbol = VOCABULARY.get(node.name)
        if symbol is None:
            hint = _suggest(node.name, list(VOCABULARY))
            raise _fail(node, f"unknown predicate or function '{node.name}'{hint}")
        if len(node.args) != symbol.arity:
            raise _fail(
                node,
                f"'{node.name}' takes {symbol.arity} argument(s) "
                f"({', '.join(symbol.args)}), got {len(node.args)}",
            )
        for position, (arg, expected) in enumerate(zip(node.args, symbol.args, strict=True), 1):
            actual = self.infer(arg, scope)
            if not accepts(expected, actual):
                raise _fail(
                    arg,
                    f"argument {position} of '{node.name}' must be {expected}, got {actual}",
                )
        return symbol.result

    def _compare(self, node: Compare, scope: Mapping[str, str]) -> str:
        left = self.infer(node.left, scope)
        right = self.infer(node.right, scope)
        if not comparable(left, right):
            raise _fail(node, f"cannot compare {left} with {right} using '{node.op}'")
        if node.op in _ORDERED_OPS and (left != "number" or right != "number"):
            raise _fail(node, f"'{node.op}' compares numbers only, got {left} and {right}")
        return "bool"

    def _expect(self, node: Formula, expected: str, scope: Mapping[str, str], what: str) -> None:
        actual = self.infer(node, scope)
        if actual != expected:
            raise _fail(node, f"{what} must be {expected}, got {actual}")


def check(
    formula: Formula, variables: Mapping[str, str], *, allow_action_args: bool = False
) -> None:
    """Type-check a condition.

    Args:
        formula: the parsed condition.
        variables: the template's variables, name (without `$`) to type.
        allow_action_args: True when checking a guard, which may name `@object`/`@target`.

    Raises:
        FormulaError: the first problem found, with the offending node's line and column.
    """
    actual = _Checker(variables, allow_action_args).infer(formula, {})
    if actual != "bool":
        raise _fail(formula, f"a condition must be bool, got {actual}")


def infer_type(
    formula: Formula,
    variables: Mapping[str, str],
    *,
    allow_action_args: bool = True,
    scope: Mapping[str, str] | None = None,
) -> str:
    """The type of a (sub-)formula; raises `FormulaError` where `check` would."""
    return _Checker(variables, allow_action_args).infer(formula, scope or {})

