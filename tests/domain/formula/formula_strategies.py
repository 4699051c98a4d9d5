"""Hypothesis strategies: random well-typed formulas and random partial states over them.

Numbers are small dyadic values and divisors are non-zero powers of two, so float arithmetic in
the evaluator is exact and agrees with Z3's real arithmetic.
"""

from __future__ import annotations

import random
from collections.abc import Callable

from hypothesis import strategies as st

from app.domain.formula import (
    VOCABULARY,
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
    TableFacts,
    Unknown,
    VarRef,
)
from app.domain.formula.facts import FactValue

ENTITIES = {
    "o1": "object",
    "o2": "object",
    "o3": "object",
    "p1": "person",
    "p2": "person",
    "kitchen": "room",
    "hall": "room",
}
STRINGS = ("water", "bleach", "", "adult", "child")
NUMBERS = (0.0, 0.5, 1.0, 1.5, 2.0, 3.0, -1.0)
DIVISORS = (1.0, 2.0, 4.0, 0.5)
_KIND_OF = {
    "robot": ("robot",),
    "object": ("object",),
    "person": ("person",),
    "room": ("room",),
    "entity": ("robot", "object", "person"),
    "entity or room": ("robot", "object", "person", "room"),
}

Scope = tuple[tuple[str, str], ...]


def _ids(kind: str) -> list[str]:
    kinds = _KIND_OF[kind]
    found = [entity for entity, type_name in ENTITIES.items() if type_name in kinds]
    return (["robot"] if "robot" in kinds else []) + found


def _symbols(result: str) -> list[str]:
    return sorted(name for name, symbol in VOCABULARY.items() if symbol.result == result)


def entity_term(
    draw: Callable[..., object], kind: str, scope: Scope, *, guard: bool, odd_ids: bool
) -> Formula:
    choices: list[Formula] = [EntityRef(entity) for entity in _ids(kind)]
    if kind in ("robot", "entity"):
        choices.append(RobotConst())
    choices += [BoundVar(name) for name, type_name in scope if type_name in _KIND_OF[kind]]
    if guard and kind in ("entity", "object", "person"):
        choices += [ActionArg("object"), ActionArg("target")]
    if odd_ids:
        choices.append(EntityRef('Mug|+01.2|"x"\\'))
    return draw(st.sampled_from(choices))  # type: ignore[return-value]


@st.composite
def terms(
    draw: st.DrawFn,
    type_name: str,
    depth: int,
    scope: Scope = (),
    guard: bool = False,
    odd: bool = False,
) -> Formula:
    """A random well-typed term of a type ('bool', 'number', 'string' or an entity kind)."""

    def sub(kind: str, deeper: int = 1, new_scope: Scope = scope) -> Formula:
        return draw(terms(kind, max(depth - deeper, 0), new_scope, guard, odd))

    if type_name in _KIND_OF:
        return entity_term(draw, type_name, scope, guard=guard, odd_ids=odd)
    if type_name == "string":
        if depth > 0 and draw(st.booleans()):
            return application(draw, "string", sub)
        pool = (*STRINGS, 'say "hi"\\n') if odd else STRINGS
        return StringLit(draw(st.sampled_from(pool)))
    if type_name == "number":
        options = ["literal", "apply"] + (["arith", "neg", "divide"] if depth > 0 else [])
        choice = draw(st.sampled_from(options))
        if choice == "literal":
            return NumberLit(draw(st.sampled_from(NUMBERS + ((1e-7, 2.5e20) if odd else ()))))
        if choice == "apply":
            return application(draw, "number", sub)
        if choice == "neg":
            return Neg(application(draw, "number", sub))
        if choice == "divide":
            return Arith("/", sub("number"), NumberLit(draw(st.sampled_from(DIVISORS))))
        return Arith(draw(st.sampled_from("+-*")), sub("number"), sub("number"))
    options = ["const", "apply", "apply"]
    if depth > 0:
        options += [
            "not",
            "logic",
            "logic",
            "compare_number",
            "compare_string",
            "compare_entity",
            "quantifier",
        ]
    if odd:
        options.append("variable")
    choice = draw(st.sampled_from(options))
    if choice == "const":
        return BoolConst(draw(st.booleans()))
    if choice == "variable":
        return VarRef(draw(st.sampled_from(("obj", "min_distance"))))
    if choice == "apply":
        return application(draw, "bool", sub)
    if choice == "not":
        return Not(sub("bool"))
    if choice == "logic":
        return Logic(draw(st.sampled_from(("and", "or", "->", "<->"))), sub("bool"), sub("bool"))
    if choice == "compare_number":
        op = draw(st.sampled_from(("==", "!=", "<", "<=", ">", ">=")))
        return Compare(op, sub("number"), sub("number"))
    if choice == "compare_string":
        return Compare(draw(st.sampled_from(("==", "!="))), sub("string"), sub("string"))
    if choice == "compare_entity":
        kind = draw(st.sampled_from(("entity", "object", "person")))
        return Compare(draw(st.sampled_from(("==", "!="))), sub(kind), sub(kind))
    kind = draw(st.sampled_from(("person", "object", "room")))
    var = f"x{len(scope)}"
    return Quantifier(
        draw(st.sampled_from(("forall", "exists"))),
        var,
        kind,
        sub("bool", new_scope=(*scope, (var, kind))),
    )


def application(draw: st.DrawFn, result: str, sub: Callable[..., Formula]) -> Formula:
    name = draw(st.sampled_from(_symbols(result)))
    return Apply(name, tuple(sub(arg) for arg in VOCABULARY[name].args))


def formulas(
    depth: int = 3, *, guard: bool = False, odd: bool = False
) -> st.SearchStrategy[Formula]:
    """Random bool formulas; `odd` adds awkward ids, strings, numbers and `$vars` (for render)."""
    return terms("bool", depth, (), guard, odd)


def _key_space() -> list[tuple[str, tuple[str, ...], str]]:
    space: list[tuple[str, tuple[str, ...], str]] = []
    for name, symbol in VOCABULARY.items():
        arg_lists: list[tuple[str, ...]] = [()]
        for arg in symbol.args:
            values = list(STRINGS) if arg == "string" else _ids(arg)
            arg_lists = [(*prefix, value) for prefix in arg_lists for value in values]
        space += [(name, args, symbol.result) for args in arg_lists]
    return space


KEY_SPACE = _key_space()


def random_state(seed: int, unknown_ratio: float) -> TableFacts:
    """A state over ENTITIES where each fact is unknown with the given probability; some unknown
    bool facts share one key, as an effect copying an unknown would make them."""
    rng = random.Random(seed)
    table: dict[tuple[str, tuple[str, ...]], FactValue] = {}
    for name, args, result in KEY_SPACE:
        if rng.random() < unknown_ratio:
            if result == "bool" and rng.random() < 0.2:
                table[(name, args)] = Unknown("shared_flag")
            continue
        if result == "bool":
            table[(name, args)] = rng.random() < 0.5
        elif result == "number":
            table[(name, args)] = rng.choice(NUMBERS)
        else:
            table[(name, args)] = rng.choice(STRINGS)
    return TableFacts(ENTITIES, table)


@st.composite
def partial_states(draw: st.DrawFn) -> TableFacts:
    """A random state with a random share of unknown facts."""
    ratio = draw(st.sampled_from((0.0, 0.1, 0.3, 0.6, 1.0)))
    return random_state(draw(st.integers(0, 2**32)), ratio)


@st.composite
def action_args(draw: st.DrawFn) -> dict[str, str | None] | None:
    """None, or `object`/`target` each an entity id or missing."""
    if draw(st.booleans()):
        return None
    pick = st.one_of(st.none(), st.sampled_from(["robot", *ENTITIES]))
    return {"object": draw(pick), "target": draw(pick)}
