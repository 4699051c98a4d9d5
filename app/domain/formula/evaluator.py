"""The fast three-valued evaluator: a formula compiled once into nested Python closures.

In: a substituted `Formula` (no `$vars` left). Out: a `CompiledFormula`, called as
`compiled(facts, action_args=None) -> True | False | None`, where None means unknown. Kleene
logic: an `Unknown` fact makes every comparison, arithmetic and predicate over it unknown; `and`
is False as soon as one side is False (even if the other is unknown), `or` True as soon as one
side is True; quantifiers expand over `facts.domain(type)`; a missing `@object`/`@target` and a
division by zero are unknown. Fails at compile time with `FormulaError` on a `$var` that was never
substituted; evaluation itself never raises for a well-typed formula.

Why closures: they are built once per contract and then run on every monitored action, so work
that does not depend on the state (constant arguments, fact-key tuples, constant sub-formulas) is
done at compile time and evaluation is a handful of Python calls per node. The connectives and
look-ups live in `closures.py`; this module dispatches on nodes and builds the quantifier loops,
the hottest code (the outermost one inlines its body's connective and first look-up).
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from app.domain.errors import FormulaError
from app.domain.formula.closures import (
    Compiled,
    Connective,
    Env,
    conjunction,
    constant,
    disjunction,
    implication,
    lookup_constant,
    lookup_env,
    lookup_general,
    lookup_pair,
    negate,
    strict,
)
from app.domain.formula.facts import ActionArgs, Facts, Unknown
from app.domain.formula.nodes import (
    ROBOT_ID,
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

_COMPARE: dict[str, Callable[[Any, Any], bool]] = {
    "==": operator.eq, "!=": operator.ne, "<": operator.lt,
    "<=": operator.le, ">": operator.gt, ">=": operator.ge,
}


def _divide(left: float, right: float) -> float | None:
    return None if right == 0 else left / right


_ARITH: dict[str, Callable[[Any, Any], Any]] = {
    "+": operator.add, "-": operator.sub, "*": operator.mul, "/": _divide,
}


def _apply(node: Apply, scope: Mapping[str, int], negated: bool = False) -> Compiled:
    parts = [_compile(arg, scope) for arg in node.args]
    slots = [scope.get(arg.name) if isinstance(arg, BoundVar) else None for arg in node.args]
    constants = [part.constant for part in parts if part.is_constant]
    if len(constants) == len(parts):
        if any(value is None for value in constants):
            return constant(None)
        key = tuple(value for value in constants if isinstance(value, str))
        if len(key) == len(parts):
            return lookup_constant(node.name, key, negated)
    if slots == list(range(len(scope))):
        # The argument tuple is the environment itself: no tuple to build per evaluation.
        return lookup_env(node.name, negated)
    if len(parts) == 2 and slots[0] is not None and isinstance(parts[1].constant, str):
        return lookup_pair(node.name, slots[0], parts[1].constant, True, negated)
    if len(parts) == 2 and slots[1] is not None and isinstance(parts[0].constant, str):
        return lookup_pair(node.name, slots[1], parts[0].constant, False, negated)
    return lookup_general(node.name, [part.code for part in parts], negated)


def _logic(node: Logic, scope: Mapping[str, int]) -> Compiled:
    left, right = _compile(node.left, scope), _compile(node.right, scope)
    if node.op == "and":
        return conjunction(left, right)
    if node.op == "or":
        return disjunction(left, right)
    if node.op == "->":
        return implication(left, right)
    return strict(left, right, operator.eq)


def _quantifier(node: Quantifier, scope: Mapping[str, int]) -> Compiled:
    body = _compile(node.body, {**scope, node.var: len(scope)})
    type_name = node.type
    universal = node.kind == "forall"
    if body.is_constant:
        value, empty = body.constant, universal

        def constant_body(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
            return value if facts.domain(type_name) else empty

        return Compiled(constant_body)
    stop, result = (False, True) if universal else (True, False)
    if body.connective is not None and not scope:
        return _outermost_connective(type_name, body.connective, stop, result)
    code = body.code

    def quantified(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        unknown = False
        for entity in facts.domain(type_name):
            value = code(facts, args, (*env, entity))
            if value is stop:
                return stop
            if value is None:
                unknown = True
        return None if unknown else result

    return Compiled(quantified)


def _outermost_connective(
    type_name: str, body: Connective, stop: bool, result: bool
) -> Compiled:
    """The outermost quantifier over a binary connective, with the connective inlined and the
    one-element environments rebuilt only when the domain changes (both save a call or an
    allocation per entity, which is most of the cost of a quantifier). When the first operand
    is a fact look-up it is read straight from the state inside the loop, its keys built once
    per domain too."""
    first, second, otherwise = body.first, body.second, body.otherwise
    first_decides, first_gives = body.first_decides, body.first_gives
    second_decides, second_gives = body.second_decides, body.second_gives
    lookup = body.first_lookup
    read_inline = lookup is not None
    name, negated = (lookup.name, lookup.negated) if lookup is not None else ("", False)
    unknown_class = Unknown
    memo: list[tuple[Sequence[str] | None, tuple[tuple[Env, Env], ...]]] = [(None, ())]

    def outermost(facts: Facts, args: ActionArgs | None = None, env: Env = ()) -> object:
        domain = facts.domain(type_name)
        seen, pairs = memo[0]
        if seen is not domain and seen != domain:
            pairs = tuple(((entity,), lookup.key((entity,)) if lookup is not None else ())
                          for entity in domain)
            memo[0] = (domain, pairs)
        value_of = facts.value
        unknown = False
        for one, key in pairs:
            if read_inline:
                a: object = value_of(name, key)
                if a.__class__ is unknown_class:
                    a = None
                elif negated:
                    a = not a
            else:
                a = first(facts, args, one)
            if a is first_decides:
                value: object = first_gives
            else:
                b = second(facts, args, one)
                if b is second_decides:
                    value = second_gives
                elif a is None or b is None:
                    unknown = True
                    continue
                else:
                    value = otherwise
            if value is stop:
                return stop
        return None if unknown else result

    return Compiled(outermost)


def _compile(node: Formula, scope: Mapping[str, int]) -> Compiled:
    if isinstance(node, BoolConst | NumberLit | StringLit):
        return constant(node.value)
    if isinstance(node, EntityRef):
        return constant(node.id)
    if isinstance(node, RobotConst):
        return constant(ROBOT_ID)
    if isinstance(node, BoundVar):
        if node.name not in scope:
            raise FormulaError(
                f"unbound variable '{node.name}'", line=node.line, column=node.column
            )
        slot = scope[node.name]
        return Compiled(lambda facts, args, env: env[slot])
    if isinstance(node, ActionArg):
        name = node.name
        return Compiled(lambda facts, args, env: None if args is None else args.get(name))
    if isinstance(node, VarRef):
        raise FormulaError(
            f"template variable ${node.name} was not substituted before compiling",
            line=node.line,
            column=node.column,
        )
    if isinstance(node, Apply):
        return _apply(node, scope)
    if isinstance(node, Not):
        if isinstance(node.operand, Apply):
            return _apply(node.operand, scope, negated=True)
        return negate(_compile(node.operand, scope))
    if isinstance(node, Neg):
        return strict(constant(0.0), _compile(node.operand, scope), operator.sub)
    if isinstance(node, Logic):
        return _logic(node, scope)
    if isinstance(node, Compare):
        left, right = _compile(node.left, scope), _compile(node.right, scope)
        return strict(left, right, _COMPARE[node.op])
    if isinstance(node, Arith):
        left, right = _compile(node.left, scope), _compile(node.right, scope)
        return strict(left, right, _ARITH[node.op])
    if isinstance(node, Quantifier):
        return _quantifier(node, scope)
    raise TypeError(f"not a formula node: {node!r}")


class CompiledFormula:
    """A condition ready to evaluate: `compiled(facts, action_args=None) -> bool | None`.

    Each instance gets its own subclass whose `__call__` is the compiled closure itself: calling
    the instance then costs one Python call instead of two, which matters when a monitor
    evaluates every condition of a contract on every action.
    """

    __slots__ = ("formula",)
    formula: Formula

    def __new__(cls, formula: Formula) -> CompiledFormula:
        code = _compile(formula, {}).code
        direct = type(cls.__name__, (cls,), {"__slots__": (), "__call__": staticmethod(code)})
        instance: CompiledFormula = object.__new__(direct)
        instance.formula = formula
        return instance

    def __call__(self, facts: Facts, action_args: ActionArgs | None = None) -> bool | None:
        """Evaluate in a state: True, False, or None when the state does not decide it."""
        raise NotImplementedError  # replaced per instance in __new__

    def __repr__(self) -> str:
        return f"CompiledFormula({self.formula!r})"


def compile_formula(formula: Formula) -> CompiledFormula:
    """Compile a substituted condition once for repeated three-valued evaluation.

    Args:
        formula: a parsed (and normally checked and substituted) condition.

    Returns:
        A callable `(facts, action_args=None) -> True | False | None` (None = unknown).

    Raises:
        FormulaError: if a `$var` was left unsubstituted or a bare identifier is unbound.
    """
    return CompiledFormula(formula)
