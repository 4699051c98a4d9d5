"""Parse condition text into the immutable AST.

In: condition text (`grammar.lark`, an LALR(1) grammar run by Lark). Out: a `Formula`
(`app.domain.formula.nodes`) whose nodes carry their 1-based line and column. Fails with
`FormulaError` (line, column, and what was expected) on a syntax error, an unknown quantifier
domain or an action argument other than `@object`/`@target`. Parsing is pure, so results are
cached by text.
"""

from __future__ import annotations

from functools import cache, lru_cache
from importlib import resources
from typing import Any

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, VisitError

from app.domain.errors import FormulaError
from app.domain.formula.nodes import (
    QUANTIFIER_TYPES,
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
from app.domain.formula.vocabulary import ACTION_ARGUMENTS

_TOKEN_NAMES = {
    "IFF": "'<->'", "IMPLIES": "'->'", "OR": "'or'", "AND": "'and'", "NOT": "'not'",
    "FORALL": "'forall'", "EXISTS": "'exists'", "TRUE": "'true'", "FALSE": "'false'",
    "ROBOT": "'robot'", "EQ": "'=='", "NE": "'!='", "LE": "'<='", "GE": "'>='", "LT": "'<'",
    "GT": "'>'", "PLUS": "'+'", "MINUS": "'-'", "STAR": "'*'", "SLASH": "'/'",
    "LPAR": "'('", "RPAR": "')'", "COMMA": "','", "COLON": "':'", "DOT": "'.'",
    "NAME": "a name", "NUMBER": "a number", "STRING": "a string", "VARIABLE": "a $variable",
    "ACTION_ARG": "@object or @target", "ENTITY": "an #entity", "QUOTED_ENTITY": "an #entity",
    "$END": "the end of the condition",
}


def _unescape(body: str) -> str:
    out: list[str] = []
    chars = iter(body)
    for char in chars:
        out.append(next(chars, "\\") if char == "\\" else char)
    return "".join(out)


@v_args(meta=True)
class _ToAst(Transformer[Token, Formula]):
    """Turns Lark's parse tree into nodes, keeping each node's position."""

    @staticmethod
    def _pos(meta: Any) -> dict[str, int]:
        return {"line": getattr(meta, "line", 0), "column": getattr(meta, "column", 0)}

    def logic(self, meta: Any, children: list[Any]) -> Formula:
        left, op, right = children
        return Logic(str(op), left, right, **self._pos(meta))

    def not_(self, meta: Any, children: list[Any]) -> Formula:
        return Not(children[1], **self._pos(meta))

    def quantifier(self, meta: Any, children: list[Any]) -> Formula:
        kind, var, type_token, body = children
        if str(type_token) not in QUANTIFIER_TYPES:
            raise FormulaError(
                f"unknown quantifier domain '{type_token}'; expected one of "
                f"{', '.join(QUANTIFIER_TYPES)}",
                line=type_token.line,
                column=type_token.column,
            )
        return Quantifier(str(kind), str(var), str(type_token), body, **self._pos(meta))

    def compare(self, meta: Any, children: list[Any]) -> Formula:
        left, op, right = children
        return Compare(str(op), left, right, **self._pos(meta))

    def arith(self, meta: Any, children: list[Any]) -> Formula:
        left, op, right = children
        return Arith(str(op), left, right, **self._pos(meta))

    def neg(self, meta: Any, children: list[Any]) -> Formula:
        operand = children[1]
        if isinstance(operand, NumberLit):
            return NumberLit(-operand.value, **self._pos(meta))
        return Neg(operand, **self._pos(meta))

    def true(self, meta: Any, children: list[Any]) -> Formula:
        return BoolConst(True, **self._pos(meta))

    def false(self, meta: Any, children: list[Any]) -> Formula:
        return BoolConst(False, **self._pos(meta))

    def number(self, meta: Any, children: list[Any]) -> Formula:
        return NumberLit(float(children[0]), **self._pos(meta))

    def string(self, meta: Any, children: list[Any]) -> Formula:
        return StringLit(_unescape(str(children[0])[1:-1]), **self._pos(meta))

    def variable(self, meta: Any, children: list[Any]) -> Formula:
        return VarRef(str(children[0])[1:], **self._pos(meta))

    def action_arg(self, meta: Any, children: list[Any]) -> Formula:
        name = str(children[0])[1:]
        if name not in ACTION_ARGUMENTS:
            raise FormulaError(
                f"unknown action argument '@{name}'; expected @object or @target",
                line=getattr(meta, "line", 0),
                column=getattr(meta, "column", 0),
            )
        return ActionArg(name, **self._pos(meta))

    def robot(self, meta: Any, children: list[Any]) -> Formula:
        return RobotConst(**self._pos(meta))

    def entity(self, meta: Any, children: list[Any]) -> Formula:
        return EntityRef(str(children[0])[1:], **self._pos(meta))

    def quoted_entity(self, meta: Any, children: list[Any]) -> Formula:
        return EntityRef(_unescape(str(children[0])[2:-1]), **self._pos(meta))

    def apply(self, meta: Any, children: list[Any]) -> Formula:
        name, *args = children
        return Apply(str(name), tuple(arg for arg in args if arg is not None), **self._pos(meta))

    def bound(self, meta: Any, children: list[Any]) -> Formula:
        return BoundVar(str(children[0]), **self._pos(meta))


@cache
def _lark() -> Lark:
    grammar = resources.files(__package__).joinpath("grammar.lark").read_text(encoding="utf-8")
    return Lark(
        grammar, parser="lalr", lexer="basic", propagate_positions=True, maybe_placeholders=False
    )


def _expected(names: set[str] | frozenset[str] | None) -> str:
    readable = sorted({_TOKEN_NAMES.get(name, name) for name in names or ()})
    return ", ".join(readable) if readable else "nothing more"


def _syntax_error(error: UnexpectedInput, text: str) -> FormulaError:
    line = getattr(error, "line", None)
    column = getattr(error, "column", None)
    if isinstance(error, UnexpectedCharacters):
        found = f"character {text[error.pos_in_stream or 0]!r}"
        expected = _expected(error.allowed)
    elif isinstance(error, UnexpectedEOF):
        found = "end of condition"
        expected = _expected(set(error.expected))
    else:
        token = getattr(error, "token", None)
        is_end = token is None or token.type == "$END"
        found = "end of condition" if is_end else f"{str(token)!r}"
        expected = _expected(getattr(error, "expected", None))
        if is_end:
            line, column = _end_position(text)
    if not isinstance(line, int) or line < 1:
        line, column = _end_position(text)
    return FormulaError(
        f"syntax error at line {line}, column {column}: unexpected {found}; "
        f"expected {expected}",
        line=line,
        column=column,
    )


def _end_position(text: str) -> tuple[int, int]:
    lines = text.split("\n")
    return len(lines), len(lines[-1]) + 1


@lru_cache(maxsize=4096)
def parse(text: str) -> Formula:
    """Parse one condition.

    Args:
        text: the condition, e.g. `"hot($obj) -> not near($obj, $person)"`.

    Returns:
        The formula's AST (immutable; positions are 1-based line/column).

    Raises:
        FormulaError: on a syntax error (with line, column and what was expected), an unknown
            quantifier domain, or an action argument other than `@object`/`@target`.
    """
    if not text.strip():
        raise FormulaError("empty condition", line=1, column=1)
    try:
        tree = _lark().parse(text)
    except UnexpectedInput as error:
        raise _syntax_error(error, text) from None
    try:
        result: Formula = _ToAst().transform(tree)
    except VisitError as error:
        if isinstance(error.orig_exc, FormulaError):
            raise error.orig_exc from None
        raise
    return result
