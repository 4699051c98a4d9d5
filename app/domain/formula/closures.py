"""The building blocks of the compiled evaluator: Kleene connectives and fact look-ups as closures.

In: already-compiled operands (`Compiled`: code plus, when the state cannot change it, the
constant value) and, for look-ups, a symbol and how to form its argument tuple. Out: a new
`Compiled`. Unknown is None throughout. Constant operands are folded here, at compile time, so a
closure never re-derives what the formula alone decides. Nothing here raises at evaluation time
for well-typed input.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from app.domain.formula.facts import ActionArgs, Facts, Unknown

Env = tuple[str, ...]
Code = Callable[[Facts, ActionArgs | None, Env], Any]
"""A compiled node: (facts, action_args, bound-variable ids) -> value, or None when unknown."""

NOT_CONSTANT: Any = object()


@dataclass(frozen=True, slots=True)
class Lookup:
    """A fact look-up whose key depends only on bound variables (for inlining into loops)."""

    name: str
    slot: int
    fixed: str | None
    bound_first: bool
    negated: bool

    def key(self, env: Env) -> tuple[str, ...]:
        """The argument tuple in an environment."""
        if self.fixed is None:
            return env
        if self.bound_first:
            return (env[self.slot], self.fixed)
        return (self.fixed, env[self.slot])


class Connective:
    """How a binary Kleene connective decides, so a quantifier can inline it into its loop.

    `first` is evaluated; if it `is` `first_decides`, the value is `first_gives`. Otherwise
    `second` is evaluated; if it `is` `second_decides`, the value is `second_gives`; else the
    value is unknown if either side was, and `otherwise` if not.
    """

    __slots__ = ("first", "first_decides", "first_gives", "first_lookup", "otherwise", "second",
                 "second_decides", "second_gives")

    def __init__(self, first: Compiled, second: Compiled,
                 decides: tuple[bool, bool, bool, bool], otherwise: bool) -> None:
        self.first, self.second = first.code, second.code
        self.first_lookup = first.lookup
        self.first_decides, self.first_gives, self.second_decides, self.second_gives = decides
        self.otherwise = otherwise


class Compiled:
    """A node's code, its value when that does not depend on the state, and its connective."""

    __slots__ = ("code", "connective", "constant", "lookup")

    def __init__(
        self,
        code: Code,
        constant: object = NOT_CONSTANT,
        connective: Connective | None = None,
        lookup: Lookup | None = None,
    ) -> None:
        self.code = code
        self.constant = constant
        self.connective = connective
        self.lookup = lookup

    @property
    def is_constant(self) -> bool:
        return self.constant is not NOT_CONSTANT


def constant(value: object) -> Compiled:
    """A node whose value is fixed at compile time (None: unknown whatever the state)."""
    def code(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        return value

    return Compiled(code, value)


def negate(inner: Compiled) -> Compiled:
    """Kleene `not`."""
    if inner.is_constant:
        return constant(None if inner.constant is None else not inner.constant)
    operand = inner.code

    def negation(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        value = operand(facts, args, env)
        return None if value is None else not value

    return Compiled(negation)


def conjunction(left: Compiled, right: Compiled) -> Compiled:
    """Kleene `and`: False if either side is False, else unknown if either is unknown."""
    return _kleene(left, right, dominant=False)


def disjunction(left: Compiled, right: Compiled) -> Compiled:
    """Kleene `or`: True if either side is True, else unknown if either is unknown."""
    return _kleene(left, right, dominant=True)


def _kleene(left: Compiled, right: Compiled, *, dominant: bool) -> Compiled:
    """`and` (dominant False) or `or` (dominant True): the dominant value if either side has
    it, else unknown if either side is unknown, else the other value. A constant side folds
    away; a quantifier over the result reads its `Connective` to inline it."""
    other = not dominant
    if left.is_constant and right.is_constant:
        values = (left.constant, right.constant)
        return constant(dominant if dominant in values else None if None in values else other)
    if right.is_constant:
        left, right = right, left
    if left.is_constant:
        if left.constant is not None:
            return constant(dominant) if bool(left.constant) is dominant else right
        only = right.code

        def unknown_unless(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
            return dominant if only(facts, args, env) is dominant else None

        return Compiled(unknown_unless)
    return _decided_by_either(left, right, dominant, dominant, gives=dominant)


def implication(left: Compiled, right: Compiled) -> Compiled:
    """Kleene `->`: True if the premise is False or the conclusion True."""
    if left.is_constant or right.is_constant:
        return disjunction(negate(left), right)
    return _decided_by_either(left, right, False, True, gives=True)


def _decided_by_either(left: Compiled, right: Compiled, first_decides: bool,
                       second_decides: bool, *, gives: bool) -> Compiled:
    """Two non-constant sides: `gives` as soon as the first `is` `first_decides` or the second
    `is` `second_decides` (the second is not evaluated when the first decides), else unknown if
    either side is, else `not gives`. The `Connective` lets a quantifier inline it."""
    first, second = left.code, right.code
    otherwise = not gives

    def connective(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        a = first(facts, args, env)
        if a is first_decides:
            return gives
        b = second(facts, args, env)
        if b is second_decides:
            return gives
        return None if a is None or b is None else otherwise

    return Compiled(connective, connective=Connective(
        left, right, (first_decides, gives, second_decides, gives), otherwise))


def strict(left: Compiled, right: Compiled, op: Callable[[Any, Any], Any]) -> Compiled:
    """A binary operation that is unknown when either side is (comparison, arithmetic, iff)."""
    if left.is_constant and right.is_constant:
        a, b = left.constant, right.constant
        return constant(None if a is None or b is None else op(a, b))
    if (left.is_constant and left.constant is None) or (
        right.is_constant and right.constant is None
    ):
        return constant(None)
    if right.is_constant:
        fixed, first = right.constant, left.code

        def constant_right(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
            a = first(facts, args, env)
            return None if a is None else op(a, fixed)

        return Compiled(constant_right)
    if left.is_constant:
        fixed, second = left.constant, right.code

        def constant_left(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
            b = second(facts, args, env)
            return None if b is None else op(fixed, b)

        return Compiled(constant_left)
    first, second = left.code, right.code

    def both_sides(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        a = first(facts, args, env)
        if a is None:
            return None
        b = second(facts, args, env)
        return None if b is None else op(a, b)

    return Compiled(both_sides)


def lookup_constant(name: str, key: tuple[str, ...], negated: bool) -> Compiled:
    """A fact whose arguments are all known at compile time."""
    unknown = Unknown  # a closure cell reads faster than a module global
    def fixed_key(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        value = facts.value(name, key)
        if value.__class__ is unknown:
            return None
        return not value if negated else value

    return Compiled(fixed_key)


def lookup_env(name: str, negated: bool) -> Compiled:
    """A fact whose arguments are exactly the bound variables, in binding order."""
    unknown = Unknown  # a closure cell reads faster than a module global
    # Separate closures for the negated form: no per-call branch in the hottest code.
    if negated:
        def whole_env_negated(
            facts: Facts, args: ActionArgs | None = None, env: Env = ()
        ) -> object:
            value = facts.value(name, env)
            return None if value.__class__ is unknown else not value

        return Compiled(whole_env_negated, lookup=Lookup(name, 0, None, False, True))

    def whole_env(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        value = facts.value(name, env)
        return None if value.__class__ is unknown else value

    return Compiled(whole_env, lookup=Lookup(name, 0, None, False, False))


def lookup_pair(name: str, slot: int, fixed: str, bound_first: bool, negated: bool) -> Compiled:
    """A two-argument fact mixing a bound variable (by env slot) and a compile-time constant."""
    unknown = Unknown
    if bound_first:
        def bound_then_fixed(
            facts: Facts, args: ActionArgs | None = None, env: Env = ()
        ) -> object:
            value = facts.value(name, (env[slot], fixed))
            if value.__class__ is unknown:
                return None
            return not value if negated else value

        return Compiled(bound_then_fixed, lookup=Lookup(name, slot, fixed, True, negated))
    if negated:
        def fixed_then_bound_negated(
            facts: Facts, args: ActionArgs | None = None, env: Env = ()
        ) -> object:
            value = facts.value(name, (fixed, env[slot]))
            return None if value.__class__ is unknown else not value

        return Compiled(
            fixed_then_bound_negated, lookup=Lookup(name, slot, fixed, False, True)
        )

    def fixed_then_bound(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        value = facts.value(name, (fixed, env[slot]))
        return None if value.__class__ is unknown else value

    return Compiled(fixed_then_bound, lookup=Lookup(name, slot, fixed, False, False))


def lookup_general(name: str, parts: Sequence[Code], negated: bool) -> Compiled:
    """A fact whose arguments are computed at evaluation time (unknown if any is unknown)."""
    unknown = Unknown  # a closure cell reads faster than a module global
    codes = tuple(parts)
    if len(codes) == 1:
        return _computed_one(name, codes[0], negated)
    if len(codes) == 2:
        return _computed_two(name, codes[0], codes[1], negated)

    def computed_key(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        key = []
        for code in codes:
            part = code(facts, args, env)
            if part is None:
                return None
            key.append(part)
        value = facts.value(name, tuple(key))
        if value.__class__ is unknown:
            return None
        return not value if negated else value

    return Compiled(computed_key)


# One- and two-argument look-ups ("mass_kg(@object)", "near(p, @object)") are most of the
# computed ones: spelled out, they build no list and run no loop.
def _computed_one(name: str, only: Code, negated: bool) -> Compiled:
    unknown = Unknown

    def computed_one(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        part = only(facts, args, env)
        if part is None:
            return None
        value = facts.value(name, (part,))
        if value.__class__ is unknown:
            return None
        return not value if negated else value

    return Compiled(computed_one)


def _computed_two(name: str, first: Code, second: Code, negated: bool) -> Compiled:
    unknown = Unknown

    def computed_two(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        a = first(facts, args, env)
        if a is None:
            return None
        b = second(facts, args, env)
        if b is None:
            return None
        value = facts.value(name, (a, b))
        if value.__class__ is unknown:
            return None
        return not value if negated else value

    return Compiled(computed_two)
