"""A small linear temporal logic over finite traces (LTLf), for the SELP-style baseline.

In: a formula string over atomic propositions (lower-case names), with `!`, `&`, `|`, `->`,
parentheses and the temporal operators `G` (always), `F` (eventually), `X` (strong next) and
`U` (until); a trace is a sequence of sets of the propositions true at each step.
Out: `parse(text) -> Formula`, and `Formula.holds(trace, at=0) -> bool` with the usual finite
semantics (`X` is false at the last step, `G` holds on the empty suffix).
Precedence, loosest first: `->` (right-assoc), `|`, `&`, `U`, then the unary operators.
Fails: `LtlSyntaxError` on a formula that does not parse.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

Trace = Sequence[frozenset[str]]

_TOKEN = re.compile(r"\s*(->|[!&|()]|[A-Za-z_][A-Za-z0-9_]*)")
_UNARY = {"!", "G", "F", "X"}


class LtlSyntaxError(ValueError):
    """A formula that is not well formed."""


@dataclass(frozen=True)
class Formula:
    """A node of the formula tree: an operator with its operands, or an atom (`op == "atom"`)."""

    op: str
    args: tuple[Formula, ...] = ()
    atom: str = ""

    def atoms(self) -> frozenset[str]:
        """Every atomic proposition the formula mentions."""
        if self.op == "atom":
            return frozenset({self.atom})
        return frozenset().union(*(a.atoms() for a in self.args))

    def holds(self, trace: Trace, at: int = 0) -> bool:
        """Whether the formula holds at position `at` of the finite trace."""
        n = len(trace)
        if self.op == "atom":
            return at < n and self.atom in trace[at]
        if self.op == "true":
            return True
        first = self.args[0]
        if self.op == "!":
            return not first.holds(trace, at)
        if self.op == "&":
            return first.holds(trace, at) and self.args[1].holds(trace, at)
        if self.op == "|":
            return first.holds(trace, at) or self.args[1].holds(trace, at)
        if self.op == "->":
            return (not first.holds(trace, at)) or self.args[1].holds(trace, at)
        if self.op == "X":
            return at + 1 < n and first.holds(trace, at + 1)
        if self.op == "G":
            return all(first.holds(trace, i) for i in range(at, n))
        if self.op == "F":
            return any(first.holds(trace, i) for i in range(at, n))
        if self.op == "U":
            for i in range(at, n):
                if self.args[1].holds(trace, i):
                    return True
                if not first.holds(trace, i):
                    return False
            return False
        raise LtlSyntaxError(f"unknown operator {self.op!r}")


def _tokens(text: str) -> list[str]:
    tokens: list[str] = []
    position = 0
    stripped = text.rstrip()
    while position < len(stripped):
        match = _TOKEN.match(stripped, position)
        if match is None:
            raise LtlSyntaxError(f"unexpected character at {position} in {text!r}")
        tokens.append(match.group(1))
        position = match.end()
    return tokens


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.tokens = _tokens(text)
        self.position = 0

    def peek(self) -> str | None:
        return self.tokens[self.position] if self.position < len(self.tokens) else None

    def take(self) -> str:
        token = self.peek()
        if token is None:
            raise LtlSyntaxError(f"unexpected end of {self.text!r}")
        self.position += 1
        return token

    def implication(self) -> Formula:
        left = self.binary("|", self.conjunction)
        if self.peek() == "->":
            self.take()
            return Formula("->", (left, self.implication()))
        return left

    def conjunction(self) -> Formula:
        return self.binary("&", self.until)

    def until(self) -> Formula:
        return self.binary("U", self.unary)

    def binary(self, op: str, operand: Callable[[], Formula]) -> Formula:
        left = operand()
        while self.peek() == op:
            self.take()
            left = Formula(op, (left, operand()))
        return left

    def unary(self) -> Formula:
        token = self.take()
        if token in _UNARY:
            return Formula(token, (self.unary(),))
        if token == "(":
            inner = self.implication()
            if self.take() != ")":
                raise LtlSyntaxError(f"missing ')' in {self.text!r}")
            return inner
        if token == "true":
            return Formula("true")
        if token in {")", "&", "|", "->", "U"}:
            raise LtlSyntaxError(f"unexpected {token!r} in {self.text!r}")
        return Formula("atom", atom=token)



def parse(text: str) -> Formula:
    """Parse an LTLf formula.

    Args:
        text: e.g. "G !(act_pour & liquid & powered_appliance)".

    Returns:
        The formula tree.

    Raises:
        LtlSyntaxError: on a malformed formula or trailing input.
    """
    parser = _Parser(text)
    formula = parser.implication()
    if parser.peek() is not None:
        raise LtlSyntaxError(f"unexpected {parser.peek()!r} in {text!r}")
    return formula
