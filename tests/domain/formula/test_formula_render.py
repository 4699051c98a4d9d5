"""Canonical rendering: re-parsing the rendered text gives an equal formula."""

from __future__ import annotations

from formula_strategies import formulas
from hypothesis import given, settings

from app.domain.formula import Formula, parse, render


class TestRender:
    def test_minimal_parentheses(self) -> None:
        assert render(parse("((a and b)) or (c -> d)")) == "a and b or (c -> d)"

    def test_right_associative_implication_keeps_left_grouping(self) -> None:
        assert render(parse("(a -> b) -> c")) == "(a -> b) -> c"
        assert render(parse("a -> (b -> c)")) == "a -> b -> c"

    def test_trailing_quantifier_needs_no_parentheses(self) -> None:
        assert render(parse("a and (forall p: person . b)")) == "a and forall p: person . b"

    def test_leading_quantifier_is_parenthesised(self) -> None:
        assert render(parse("(forall p: person . b) and a")) == "(forall p: person . b) and a"

    def test_negative_literal_and_subtraction(self) -> None:
        assert render(parse("x - (-3)")) == "x - -3.0"

    def test_quoted_entity_and_escaped_string(self) -> None:
        assert render(parse('#"a|b" == #c and "q\\"x" == "y"')) == '#"a|b" == #c and "q\\"x" == "y"'

    @settings(max_examples=600, deadline=None)
    @given(formulas(depth=4, guard=True, odd=True))
    def test_round_trip(self, formula: Formula) -> None:
        assert parse(render(formula)) == formula
