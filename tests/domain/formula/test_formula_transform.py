"""Substitution of template variables on the AST, and the symbols a formula uses."""

from __future__ import annotations

import pytest

from app.domain.errors import FormulaError
from app.domain.formula import (
    BoolConst,
    EntityRef,
    NumberLit,
    StringLit,
    entity_variables,
    parse,
    render,
    substitute,
    symbols_used,
    uses_action_args,
    variables_used,
)

INVARIANT = "holding(robot, $obj) and hot($obj) -> distance(robot, $person) >= $min_distance"


class TestSubstitute:
    def test_entity_refs_and_number(self) -> None:
        result = substitute(
            parse(INVARIANT),
            {"obj": EntityRef("mug_1"), "person": EntityRef("ann"), "min_distance": 0.5},
        )
        assert render(result) == (
            "holding(robot, #mug_1) and hot(#mug_1) -> distance(robot, #ann) >= 0.5"
        )

    def test_str_for_entity_position_becomes_entity_constant(self) -> None:
        result = substitute(parse(INVARIANT), {"obj": "mug_1", "person": "ann"})
        assert "#mug_1" in render(result) and "#ann" in render(result)

    def test_str_for_string_position_becomes_string_literal(self) -> None:
        result = substitute(parse("contains($obj, $what)"), {"obj": "jug", "what": "bleach"})
        assert render(result) == 'contains(#jug, "bleach")'

    def test_declared_types_decide_over_usage(self) -> None:
        result = substitute(
            parse("$a == $b"), {"a": "x", "b": "y"}, variables={"a": "object", "b": "object"}
        )
        assert render(result) == "#x == #y"

    def test_str_compared_with_action_argument_is_entity(self) -> None:
        assert render(substitute(parse("@object != $obj"), {"obj": "Mug|1"})) == (
            '@object != #"Mug|1"'
        )

    def test_bool_binds_to_bool_constant(self) -> None:
        assert substitute(parse("$flag"), {"flag": True}) == BoolConst(True)

    def test_negated_variable_folds_into_literal(self) -> None:
        assert substitute(parse("-$d > 1"), {"d": 2}) == parse("-2 > 1")

    def test_unbound_variables_are_left_in_place(self) -> None:
        result = substitute(parse(INVARIANT), {"obj": "mug_1"})
        assert variables_used(result) == {"person", "min_distance"}

    def test_substitution_keeps_positions(self) -> None:
        result = substitute(parse("true and\n  $x > 1"), {"x": 3})
        assert result == parse("true and 3 > 1")
        literal = result.right.left  # type: ignore[union-attr]
        assert isinstance(literal, NumberLit)
        assert (literal.line, literal.column) == (2, 3)

    def test_does_not_rewrite_inside_string_literals(self) -> None:
        result = substitute(parse('contains($obj, "$obj")'), {"obj": "jug"})
        assert result.args[1] == StringLit("$obj")  # type: ignore[union-attr]

    def test_unsupported_binding_type_is_refused(self) -> None:
        with pytest.raises(FormulaError, match=r"\$obj cannot be bound"):
            substitute(parse("hot($obj)"), {"obj": ["mug"]})


class TestInspection:
    def test_symbols_used(self) -> None:
        assert symbols_used(parse(INVARIANT)) == {"holding", "hot", "distance"}

    def test_entity_variables_from_usage(self) -> None:
        assert entity_variables(parse(INVARIANT)) == {"obj", "person"}

    def test_uses_action_args(self) -> None:
        assert uses_action_args(parse("hot(@object)"))
        assert not uses_action_args(parse("hot($obj)"))
