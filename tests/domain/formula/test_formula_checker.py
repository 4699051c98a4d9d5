"""Static checking: every kind of error, each positioned at its offending node."""

from __future__ import annotations

import pytest

from app.domain.errors import FormulaError
from app.domain.formula import check, infer_type, parse

VARIABLES = {
    "obj": "object",
    "person": "person",
    "kitchen": "room",
    "min_distance": "number",
    "substance": "string",
    "who": "entity",
}


def _error(text: str, *, guard: bool = False) -> FormulaError:
    with pytest.raises(FormulaError) as caught:
        check(parse(text), VARIABLES, allow_action_args=guard)
    return caught.value


class TestCheck:
    def test_well_typed_template_conditions_pass(self) -> None:
        for text in (
            "holding(robot, $obj) and hot($obj) and not lidded($obj) "
            "-> distance(robot, $person) >= $min_distance",
            "forall p: person . near(robot, p) -> speed(robot) <= 0.3 * max_speed(robot)",
            "exists o: object . holding($person, o) and contains(o, $substance)",
            'contents($obj) == "bleach" <-> toxic($obj)',
            "in_room($who, $kitchen) and near($who, $obj)",
        ):
            check(parse(text), VARIABLES)

    def test_guard_may_use_action_arguments(self) -> None:
        check(parse("@object != $obj or not hot(@object)"), VARIABLES, allow_action_args=True)

    def test_typo_predicate_is_refused_with_position_and_suggestion(self) -> None:
        error = _error("hot($obj) and\n    hott($obj)")
        assert (error.line, error.column) == (2, 5)
        assert "unknown predicate or function 'hott'" in error.detail
        assert "did you mean 'hot'?" in error.detail

    def test_unknown_symbol_without_close_match_has_no_suggestion(self) -> None:
        assert "did you mean" not in _error("zzzqqq($obj)").detail

    def test_wrong_arity(self) -> None:
        error = _error("true and near($obj)")
        assert "'near' takes 2 argument(s)" in error.detail
        assert error.column == 10

    def test_wrong_argument_type_person_for_object(self) -> None:
        error = _error("hot($person)")
        assert "argument 1 of 'hot' must be object, got person" in error.detail
        assert error.column == 5

    def test_room_is_not_an_entity(self) -> None:
        assert "must be entity, got room" in _error("near($kitchen, robot)").detail

    def test_entity_typed_expression_accepted_where_object_expected(self) -> None:
        check(parse("hot($who)"), VARIABLES)

    def test_undeclared_template_variable_with_suggestion(self) -> None:
        error = _error("hot($ojb)")
        assert "undeclared template variable $ojb" in error.detail
        assert "did you mean '$obj'?" in error.detail

    def test_free_bare_identifier(self) -> None:
        error = _error("forall p: person . near(p, mug)")
        assert "unbound variable 'mug'" in error.detail
        assert error.column == 28

    def test_quantified_variable_is_out_of_scope_after_parentheses(self) -> None:
        assert (
            "unbound variable 'p'" in _error("(forall p: person . asleep(p)) and child(p)").detail
        )

    def test_action_argument_outside_guard(self) -> None:
        assert "@object may only be used in a guard" in _error("hot(@object)").detail

    def test_comparing_number_with_string(self) -> None:
        error = _error('true and mass_kg($obj) == "heavy"')
        assert "cannot compare number with string" in error.detail
        assert error.column == 10

    def test_comparing_object_with_person(self) -> None:
        assert "cannot compare object with person" in _error("$obj == $person").detail

    def test_ordering_strings(self) -> None:
        assert "compares numbers only" in _error('contents($obj) < "z"').detail

    def test_non_bool_at_top_level(self) -> None:
        assert "a condition must be bool, got number" in _error("mass_kg($obj) + 1").detail

    def test_non_bool_operand_of_connective(self) -> None:
        assert "right side of 'and' must be bool, got number" in _error("true and 1").detail

    def test_arithmetic_on_bool(self) -> None:
        assert "must be number, got bool" in _error("hot($obj) + 1 > 2").detail


class TestInferType:
    def test_infers_function_result_type(self) -> None:
        assert infer_type(parse("contents($obj)"), VARIABLES) == "string"

    def test_action_argument_is_an_entity_of_any_kind(self) -> None:
        assert infer_type(parse("@target"), VARIABLES) == "entity or room"

    def test_action_argument_may_be_compared_with_a_room(self) -> None:
        check(parse("@target != $kitchen"), VARIABLES, allow_action_args=True)

    def test_bound_room_constant_fits_a_room_argument(self) -> None:
        check(parse('in_room(robot, #"hallway")'), {})

    def test_a_room_still_cannot_stand_for_an_object(self) -> None:
        assert "must be object" in _error("hot($kitchen)").detail
