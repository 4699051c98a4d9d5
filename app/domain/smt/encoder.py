"""Encode a condition over a state into a Z3 formula whose free variables are the unknown facts.

In: a `Formula`, a `Facts` state, optionally the guarded action's arguments and the types of any
value-typed `$vars` left unsubstituted. Out: an `Encoding`: the Z3 `BoolRef`, side assumptions
(an unknown `@object` ranges over the state's entities) and the free variables by name. Known
facts become constants; every `Unknown` fact becomes a free variable named by its key (Bool, Real
or String by the symbol's result type; the same key is the same variable); quantifiers are
expanded over the finite domains. Fails with `FormulaError` on an unsubstituted entity variable
or an untyped `$var`, and `ValueError` when a state gives a fact a value of the wrong kind or one
key two sorts.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, TypeAlias

import z3

from app.domain.errors import FormulaError
from app.domain.formula.facts import ActionArgs, Facts, FactValue, Unknown
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
from app.domain.formula.vocabulary import VOCABULARY

_ENTITY_DOMAINS = ("robot", "object", "person", "room")
_VALUE_SORTS = ("bool", "number", "string")


@dataclass(frozen=True, slots=True)
class Encoding:
    """A condition as Z3 sees it."""

    expr: z3.BoolRef
    assumptions: tuple[z3.BoolRef, ...] = ()
    unknowns: Mapping[str, z3.ExprRef] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class _Choice:
    """An entity the state leaves open: a String variable equal to one of `ids`."""

    var: z3.SeqRef
    ids: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class _Text:
    """A string known at encoding time (kept in Python so it can index facts exactly)."""

    value: str


# An encoded sub-formula: an entity id (str), an open entity (_Choice), a known string (_Text) or
# a Z3 expression. Spelled Any because z3 ships no type information.
Term: TypeAlias = Any


def _number(value: float) -> z3.ArithRef:
    # The shortest decimal that rounds to the float: readable, and ordered like the floats.
    return z3.RealVal(Fraction(repr(float(value))))


class _Encoder:
    def __init__(
        self,
        facts: Facts,
        action_args: ActionArgs | None,
        variable_types: Mapping[str, str],
    ) -> None:
        self.facts = facts
        self.action_args = action_args
        self.variable_types = variable_types
        self.unknowns: dict[str, z3.ExprRef] = {}
        self.assumptions: list[z3.BoolRef] = []
        self.choices: dict[str, _Choice] = {}

    def free(self, key: str, type_name: str) -> z3.ExprRef:
        constructor = {"bool": z3.Bool, "number": z3.Real, "string": z3.String}[type_name]
        var: z3.ExprRef = constructor(key)
        known = self.unknowns.setdefault(key, var)
        if not known.sort().eq(var.sort()):
            raise ValueError(f"unknown {key!r} is used with two sorts")
        return known

    def fact(self, symbol: str, args: tuple[str, ...], result: str) -> Term:
        value: FactValue = self.facts.value(symbol, args)
        if isinstance(value, Unknown):
            return self.free(value.key, result)
        if result == "bool" and isinstance(value, bool):
            return z3.BoolVal(value)
        if result == "number" and isinstance(value, int | float) and not isinstance(value, bool):
            return _number(value)
        if result == "string" and isinstance(value, str):
            return _Text(value)
        raise ValueError(f"{symbol}{args} has value {value!r}, expected a {result}")

    def action_arg(self, name: str) -> Term:
        given = None if self.action_args is None else self.action_args.get(name)
        if given is not None:
            return given
        if name not in self.choices:
            ids = tuple(
                entity for kind in _ENTITY_DOMAINS for entity in self.facts.domain(kind)
            ) or (ROBOT_ID,)
            choice = _Choice(z3.String(f"@{name}"), ids)
            self.unknowns[f"@{name}"] = choice.var
            self.assumptions.append(z3.Or([choice.var == z3.StringVal(i) for i in ids]))
            self.choices[name] = choice
        return self.choices[name]

    def variable(self, node: VarRef) -> Term:
        type_name = self.variable_types.get(node.name)
        if type_name not in _VALUE_SORTS:
            raise FormulaError(
                f"${node.name} must be substituted before encoding"
                + ("" if type_name is None else f" (an entity variable of type {type_name})"),
                line=node.line,
                column=node.column,
            )
        return self.free(f"${node.name}", type_name)

    def encode(self, node: Formula, env: Mapping[str, str]) -> Term:
        if isinstance(node, BoolConst):
            return z3.BoolVal(node.value)
        if isinstance(node, NumberLit):
            return _number(node.value)
        if isinstance(node, StringLit):
            return _Text(node.value)
        if isinstance(node, EntityRef):
            return node.id
        if isinstance(node, RobotConst):
            return ROBOT_ID
        if isinstance(node, BoundVar):
            if node.name not in env:
                raise FormulaError(
                    f"unbound variable '{node.name}'", line=node.line, column=node.column
                )
            return env[node.name]
        if isinstance(node, ActionArg):
            return self.action_arg(node.name)
        if isinstance(node, VarRef):
            return self.variable(node)
        if isinstance(node, Apply):
            return self.apply(node, env)
        if isinstance(node, Not):
            return z3.Not(self.boolean(node.operand, env))
        if isinstance(node, Neg):
            return -self.arith(node.operand, env)
        if isinstance(node, Logic):
            left, right = self.boolean(node.left, env), self.boolean(node.right, env)
            if node.op == "and":
                return z3.And(left, right)
            if node.op == "or":
                return z3.Or(left, right)
            if node.op == "->":
                return z3.Implies(left, right)
            return left == right
        if isinstance(node, Arith):
            return self.arithmetic(node, env)
        if isinstance(node, Compare):
            return self.compare(node, env)
        if isinstance(node, Quantifier):
            parts = [
                self.boolean(node.body, {**env, node.var: entity})
                for entity in self.facts.domain(node.type)
            ]
            return z3.And(parts) if node.kind == "forall" else z3.Or(parts)
        raise TypeError(f"not a formula node: {node!r}")

    def boolean(self, node: Formula, env: Mapping[str, str]) -> z3.BoolRef:
        term = self.encode(node, env)
        if not isinstance(term, z3.BoolRef):
            raise FormulaError(f"expected a condition, got {term!r}", line=node.line,
                               column=node.column)
        return term

    def arith(self, node: Formula, env: Mapping[str, str]) -> z3.ArithRef:
        term = self.encode(node, env)
        if not isinstance(term, z3.ArithRef):
            raise FormulaError(f"expected a number, got {term!r}", line=node.line,
                               column=node.column)
        return term

    def arithmetic(self, node: Arith, env: Mapping[str, str]) -> z3.ArithRef:
        left, right = self.arith(node.left, env), self.arith(node.right, env)
        if node.op == "+":
            return left + right
        if node.op == "-":
            return left - right
        if node.op == "*":
            return left * right
        return left / right

    def compare(self, node: Compare, env: Mapping[str, str]) -> z3.BoolRef:
        left, right = self.encode(node.left, env), self.encode(node.right, env)
        if node.op in ("==", "!="):
            equal = _equal(left, right)
            return equal if node.op == "==" else z3.Not(equal)
        if not isinstance(left, z3.ArithRef) or not isinstance(right, z3.ArithRef):
            raise FormulaError(f"'{node.op}' compares numbers only", line=node.line,
                               column=node.column)
        ordered = {"<": left < right, "<=": left <= right, ">": left > right, ">=": left >= right}
        return ordered[node.op]

    def apply(self, node: Apply, env: Mapping[str, str]) -> Term:
        symbol = VOCABULARY.get(node.name)
        if symbol is None:
            raise FormulaError(f"unknown predicate or function '{node.name}'",
                               line=node.line, column=node.column)
        alternatives: list[list[tuple[z3.BoolRef | None, str]]] = []
        opaque = False
        for arg in (self.encode(arg, env) for arg in node.args):
            if isinstance(arg, str):
                alternatives.append([(None, arg)])
            elif isinstance(arg, _Text):
                alternatives.append([(None, arg.value)])
            elif isinstance(arg, _Choice):
                alternatives.append([(arg.var == z3.StringVal(i), i) for i in arg.ids])
            else:
                opaque = True
                alternatives.append([(None, str(arg))])
        if opaque:
            # An argument only the solver knows (an unknown string): its own free unknown, keyed
            # by the argument expressions so repeated uses stay one variable.
            key = f"{node.name}({','.join(alt[0][1] for alt in alternatives)})"
            return self.free(key, symbol.result)
        combos = list(itertools.product(*alternatives))
        result = self.fact(node.name, tuple(i for _, i in combos[-1]), symbol.result)
        for combo in reversed(combos[:-1]):
            guards = [guard for guard, _ in combo if guard is not None]
            value = self.fact(node.name, tuple(i for _, i in combo), symbol.result)
            result = z3.If(z3.And(guards), _as_z3(value), _as_z3(result))
        return result


def _as_z3(term: Term) -> z3.ExprRef:
    if isinstance(term, _Text):
        return z3.StringVal(term.value)
    if isinstance(term, str):
        return z3.StringVal(term)
    if isinstance(term, _Choice):
        return term.var
    return term


def _equal(left: Term, right: Term) -> z3.BoolRef:
    if isinstance(left, str | _Text) and isinstance(right, str | _Text):
        plain = [t.value if isinstance(t, _Text) else t for t in (left, right)]
        return z3.BoolVal(plain[0] == plain[1])
    result: z3.BoolRef = _as_z3(left) == _as_z3(right)
    return result


def encode(
    formula: Formula,
    facts: Facts,
    action_args: ActionArgs | None = None,
    *,
    variable_types: Mapping[str, str] | None = None,
) -> Encoding:
    """Encode a condition over a state for Z3.

    Args:
        formula: a checked condition, normally substituted.
        facts: the state; its unknown facts become free variables named by `Unknown.key`.
        action_args: the guarded action's `object`/`target` ids; a missing one is a free entity
            ranging over the state's entities.
        variable_types: types of value-typed `$vars` left in the formula (free `$name`
            variables).

    Returns:
        The `Encoding` (expression, assumptions, free variables by name).

    Raises:
        FormulaError: an entity `$var` left unsubstituted or an untyped `$var`.
        ValueError: a fact whose value has the wrong kind for its symbol.
    """
    encoder = _Encoder(facts, action_args, variable_types or {})
    expr = encoder.boolean(formula, {})
    return Encoding(expr, tuple(encoder.assumptions), dict(encoder.unknowns))
