"""The compiled three-valued evaluator (Kleene logic over possibly unknown facts)."""

from __future__ import annotations

import pytest

from app.domain.errors import FormulaError
from app.domain.formula import TableFacts, Unknown, compile_formula, parse

STATE = TableFacts(
    {"mug_1": "object", "knife_1": "object", "ann": "person", "bob": "person", "kitchen": "room"},
    {
        ("hot", ("mug_1",)): True,
        ("hot", ("knife_1",)): False,
        ("sharp", ("knife_1",)): True,
        ("sharp", ("mug_1",)): False,
        ("distance", ("robot", "ann")): 0.4,
        ("distance", ("robot", "bob")): 2.0,
        ("mass_kg", ("mug_1",)): 0.3,
        ("contents", ("mug_1",)): "coffee",
        ("child", ("ann",)): False,
        ("asleep", ("ann",)): Unknown("asleep(ann)"),
        # `child(bob)`, `lidded(mug_1)` and most others are absent: unknown.
    },
)


def _eval(text: str, action_args: dict[str, str | None] | None = None) -> bool | None:
    return compile_formula(parse(text))(STATE, action_args)


class TestKnownFacts:
    def test_predicate_and_comparison(self) -> None:
        assert _eval("hot(#mug_1) and distance(robot, #ann) < 0.5") is True
        assert _eval("hot(#knife_1)") is False

    def test_arithmetic(self) -> None:
        assert _eval("mass_kg(#mug_1) * 10 - 1 == 2") is True
        assert _eval("-mass_kg(#mug_1) < 0") is True

    def test_string_function(self) -> None:
        assert _eval('contents(#mug_1) == "coffee"') is True
        assert _eval('contents(#mug_1) != "coffee"') is False

    def test_entity_equality(self) -> None:
        assert _eval("#mug_1 == #mug_1 and robot != #ann") is True

    def test_implication_and_iff(self) -> None:
        assert _eval("hot(#knife_1) -> sharp(#mug_1)") is True
        assert _eval("hot(#mug_1) <-> sharp(#mug_1)") is False


class TestUnknownPropagation:
    def test_missing_fact_is_unknown(self) -> None:
        assert _eval("lidded(#mug_1)") is None
        assert _eval("not lidded(#mug_1)") is None

    def test_explicit_unknown_value_is_unknown(self) -> None:
        assert _eval("asleep(#ann)") is None

    def test_and_with_false_is_false_even_if_other_unknown(self) -> None:
        assert _eval("lidded(#mug_1) and hot(#knife_1)") is False
        assert _eval("hot(#knife_1) and lidded(#mug_1)") is False

    def test_and_with_true_and_unknown_is_unknown(self) -> None:
        assert _eval("hot(#mug_1) and lidded(#mug_1)") is None

    def test_or_with_true_is_true_even_if_other_unknown(self) -> None:
        assert _eval("lidded(#mug_1) or hot(#mug_1)") is True

    def test_or_with_false_and_unknown_is_unknown(self) -> None:
        assert _eval("lidded(#mug_1) or hot(#knife_1)") is None

    def test_implication_with_false_premise_is_true(self) -> None:
        assert _eval("hot(#knife_1) -> lidded(#mug_1)") is True

    def test_implication_with_true_premise_and_unknown_conclusion_is_unknown(self) -> None:
        assert _eval("hot(#mug_1) -> lidded(#mug_1)") is None

    def test_iff_with_unknown_is_unknown(self) -> None:
        assert _eval("hot(#mug_1) <-> lidded(#mug_1)") is None

    def test_comparison_and_arithmetic_on_unknown_are_unknown(self) -> None:
        assert _eval("mass_kg(#knife_1) + 1 > 0") is None

    def test_division_by_zero_is_unknown(self) -> None:
        assert _eval("mass_kg(#mug_1) / 0 > 1") is None

    def test_unknown_string_argument_makes_application_unknown(self) -> None:
        assert _eval("contains(#mug_1, contents(#knife_1))") is None


class TestQuantifiers:
    def test_forall_false_when_one_counterexample_known(self) -> None:
        assert _eval("forall p: person . distance(robot, p) > 1") is False

    def test_forall_unknown_when_no_counterexample_but_an_unknown(self) -> None:
        assert _eval("forall p: person . not child(p)") is None

    def test_exists_true_when_one_witness_known(self) -> None:
        assert _eval("exists o: object . sharp(o)") is True

    def test_exists_unknown_without_witness(self) -> None:
        assert _eval("exists p: person . child(p)") is None

    def test_nested_quantifiers_with_two_bound_arguments(self) -> None:
        assert _eval("exists p: person . exists o: object . distance(robot, p) < 1 and hot(o)")

    def test_empty_domain(self) -> None:
        empty = TableFacts({})
        assert compile_formula(parse("forall p: person . child(p)"))(empty) is True
        assert compile_formula(parse("exists p: person . child(p)"))(empty) is False

    def test_constant_body_still_depends_on_domain(self) -> None:
        formula = compile_formula(parse("exists r: room . true"))
        assert formula(STATE) is True
        assert formula(TableFacts({})) is False


class TestActionArguments:
    def test_bound_action_argument(self) -> None:
        assert _eval("@object == #mug_1 and hot(@object)", {"object": "mug_1"}) is True

    def test_missing_action_argument_is_unknown(self) -> None:
        assert _eval("hot(@object)") is None
        assert _eval("@target == #ann", {"object": "mug_1", "target": None}) is None


class TestCompileErrors:
    def test_unsubstituted_variable_is_refused_at_compile_time(self) -> None:
        with pytest.raises(FormulaError, match=r"\$obj was not substituted"):
            compile_formula(parse("hot($obj)"))


class TestQuantifierLoops:
    """The outermost quantifier over a connective runs an inlined loop; it must keep Kleene
    semantics and follow the domain when the state changes between calls."""

    BODY = "forall o: object . hot(o) -> not near(o, #ann)"

    def test_inlined_loop_false_true_and_unknown(self) -> None:
        formula = compile_formula(parse(self.BODY))
        near = TableFacts({"pan": "object"}, {("hot", ("pan",)): True,
                                              ("near", ("pan", "ann")): True})
        far = near.updated({("near", ("pan", "ann")): False})
        unsure = near.updated({("near", ("pan", "ann")): Unknown("near(pan,ann)")})
        assert (formula(near), formula(far), formula(unsure)) == (False, True, None)

    def test_domain_change_between_calls_is_followed(self) -> None:
        formula = compile_formula(parse("exists o: object . holding(robot, o) and sharp(o)"))
        with_knife = TableFacts({"knife": "object"}, {("holding", ("robot", "knife")): True,
                                                      ("sharp", ("knife",)): True})
        without = TableFacts({"cup": "object"}, {("holding", ("robot", "cup")): True,
                                                 ("sharp", ("cup",)): False})
        assert [formula(with_knife), formula(without), formula(with_knife)] == [True, False, True]

    def test_connective_body_over_empty_domain(self) -> None:
        assert compile_formula(parse(self.BODY))(TableFacts({})) is True

    def test_nested_quantifier_with_connective_body(self) -> None:
        formula = compile_formula(
            parse("forall p: person . exists o: object . hot(o) and distance(robot, p) < 5")
        )
        assert formula(STATE) is True
