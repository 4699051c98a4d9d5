"""Parsing condition text into the AST, and refusing bad text with a position."""

from __future__ import annotations

import pytest

from app.domain.errors import FormulaError
from app.domain.formula import (
    ActionArg,
    Apply,
    Arith,
    BoolConst,
    BoundVar,
    Compare,
    EntityRef,
    Logic,
    Neg,
    Not,
    NumberLit,
    Quantifier,
    RobotConst,
    StringLit,
    VarRef,
    parse,
)


class TestParse:
    def test_template_invariant_parses_with_implication_loosest(self) -> None:
        formula = parse(
            "holding(robot, $obj) and hot($obj) -> distance(robot, $person) >= $min_distance"
        )
        assert formula == Logic(
            "->",
            Logic(
                "and",
                Apply("holding", (RobotConst(), VarRef("obj"))),
                Apply("hot", (VarRef("obj"),)),
            ),
            Compare(
                ">=", Apply("distance", (RobotConst(), VarRef("person"))), VarRef("min_distance")
            ),
        )

    def test_implication_is_right_associative(self) -> None:
        assert parse("a -> b -> c") == Logic(
            "->", BoundVar("a"), Logic("->", BoundVar("b"), BoundVar("c"))
        )

    def test_and_binds_tighter_than_or_and_not_tighter_than_and(self) -> None:
        assert parse("not a and b or c") == Logic(
            "or", Logic("and", Not(BoundVar("a")), BoundVar("b")), BoundVar("c")
        )

    def test_iff_is_loosest_connective(self) -> None:
        assert parse("a -> b <-> c") == Logic(
            "<->", Logic("->", BoundVar("a"), BoundVar("b")), BoundVar("c")
        )

    def test_arithmetic_precedence_and_unary_minus(self) -> None:
        assert parse("1 + 2 * -x") == Arith(
            "+", NumberLit(1.0), Arith("*", NumberLit(2.0), Neg(BoundVar("x")))
        )

    def test_minus_on_a_literal_folds_into_the_literal(self) -> None:
        assert parse("x > -0.5") == Compare(">", BoundVar("x"), NumberLit(-0.5))

    def test_quantifier_body_extends_as_far_right_as_possible(self) -> None:
        assert parse("a and forall p: person . b or c") == Logic(
            "and",
            BoundVar("a"),
            Quantifier("forall", "p", "person", Logic("or", BoundVar("b"), BoundVar("c"))),
        )

    def test_parentheses_end_a_quantifier_body(self) -> None:
        assert parse("(exists o: object . b) or c") == Logic(
            "or", Quantifier("exists", "o", "object", BoundVar("b")), BoundVar("c")
        )

    def test_literals_constants_and_action_arguments(self) -> None:
        formula = parse('@object != #mug_1 or contains(@target, "bleach") or true')
        assert formula == Logic(
            "or",
            Logic(
                "or",
                Compare("!=", ActionArg("object"), EntityRef("mug_1")),
                Apply("contains", (ActionArg("target"), StringLit("bleach"))),
            ),
            BoolConst(True),
        )

    def test_quoted_entity_and_escaped_string(self) -> None:
        formula = parse('#"Mug|+01.2|+00.9" == #"a\\"b" and "x\\\\y" == "q"')
        assert formula == Logic(
            "and",
            Compare("==", EntityRef("Mug|+01.2|+00.9"), EntityRef('a"b')),
            Compare("==", StringLit("x\\y"), StringLit("q")),
        )

    def test_keyword_prefixed_names_are_identifiers(self) -> None:
        assert parse("nothing and orange") == Logic("and", BoundVar("nothing"), BoundVar("orange"))

    def test_nodes_carry_line_and_column(self) -> None:
        formula = parse("true and\n  hot(#mug_1)")
        assert isinstance(formula, Logic)
        assert (formula.right.line, formula.right.column) == (2, 3)


class TestParseErrors:
    def test_missing_closing_parenthesis_reports_end_and_expectation(self) -> None:
        with pytest.raises(FormulaError) as caught:
            parse("hot($obj")
        assert (caught.value.line, caught.value.column) == (1, 9)
        assert "')'" in caught.value.detail

    def test_keyword_where_operand_expected(self) -> None:
        with pytest.raises(FormulaError) as caught:
            parse("hot($obj) and and wet($obj)")
        assert (caught.value.line, caught.value.column) == (1, 15)
        assert "unexpected 'and'" in caught.value.detail

    def test_unknown_character_on_second_line(self) -> None:
        with pytest.raises(FormulaError) as caught:
            parse("hot($obj)\n  ? wet($obj)")
        assert (caught.value.line, caught.value.column) == (2, 3)

    def test_chained_comparison_is_refused(self) -> None:
        with pytest.raises(FormulaError, match="unexpected '=='"):
            parse("a == b == c")

    def test_unknown_quantifier_domain(self) -> None:
        with pytest.raises(FormulaError, match="'peson'") as caught:
            parse("forall p: peson . asleep(p)")
        assert caught.value.column == 11

    def test_unknown_action_argument(self) -> None:
        with pytest.raises(FormulaError, match="@obj"):
            parse("hot(@obj)")

    def test_empty_condition(self) -> None:
        with pytest.raises(FormulaError, match="empty"):
            parse("   ")
