"""Encoding formulas over partial states into Z3."""

from __future__ import annotations

import pytest
import z3

from app.domain.errors import FormulaError
from app.domain.formula import TableFacts, Unknown, parse, substitute
from app.domain.smt import Outcome, encode, prove

STATE = TableFacts(
    {"mug": "object", "ann": "person", "bob": "person", "kitchen": "room"},
    {
        ("hot", ("mug",)): True,
        ("distance", ("robot", "ann")): 0.3,
        ("contents", ("mug",)): "coffee",
        ("is_on", ("mug",)): Unknown("burner_on"),
        ("hot", ("ann",)): Unknown("burner_on"),
    },
)


class TestEncode:
    def test_known_facts_become_constants(self) -> None:
        encoding = encode(parse("hot(#mug) and distance(robot, #ann) < 0.5"), STATE)
        assert encoding.unknowns == {}
        assert z3.is_true(z3.simplify(encoding.expr))

    def test_unknown_fact_becomes_free_variable_named_by_key(self) -> None:
        encoding = encode(parse("lidded(#mug) or wet(#mug)"), STATE)
        assert set(encoding.unknowns) == {"lidded(mug)", "wet(mug)"}
        assert all(z3.is_bool(var) for var in encoding.unknowns.values())

    def test_sort_follows_symbol_result_type(self) -> None:
        encoding = encode(parse('mass_kg(#mug) > 1 and age_group(#bob) == "adult"'), STATE)
        assert z3.is_real(encoding.unknowns["mass_kg(mug)"])
        assert z3.is_string(encoding.unknowns["age_group(bob)"])

    def test_same_key_is_same_variable(self) -> None:
        encoding = encode(parse("is_on(#mug) and not hot(#ann)"), STATE)
        assert list(encoding.unknowns) == ["burner_on"]
        assert prove(z3.Not(encoding.expr)).outcome is Outcome.HOLDS

    def test_quantifier_expands_over_domain(self) -> None:
        encoding = encode(parse("forall p: person . asleep(p)"), STATE)
        assert set(encoding.unknowns) == {"asleep(ann)", "asleep(bob)"}

    def test_missing_action_argument_ranges_over_entities(self) -> None:
        encoding = encode(parse("hot(@object)"), STATE)
        assert "@object" in encoding.unknowns
        assert len(encoding.assumptions) == 1
        assert prove(encoding).outcome is Outcome.VIOLATED

    def test_given_action_argument_is_concrete(self) -> None:
        encoding = encode(parse("hot(@object)"), STATE, {"object": "mug"})
        assert prove(encoding).outcome is Outcome.HOLDS

    def test_unknown_string_argument_gets_its_own_unknown(self) -> None:
        encoding = encode(parse("contains(#mug, contents(#ann))"), STATE)
        assert any(key.startswith("contains(mug,") for key in encoding.unknowns)

    def test_known_string_argument_indexes_the_fact(self) -> None:
        encoding = encode(parse("contains(#mug, contents(#mug))"), STATE)
        assert "contains(mug,coffee)" in encoding.unknowns

    def test_value_variable_left_free_when_typed(self) -> None:
        formula = parse("distance(robot, #ann) >= $min_distance")
        encoding = encode(formula, STATE, variable_types={"min_distance": "number"})
        assert z3.is_real(encoding.unknowns["$min_distance"])

    def test_entity_variable_must_be_substituted(self) -> None:
        with pytest.raises(FormulaError, match=r"\$obj must be substituted"):
            encode(parse("hot($obj)"), STATE, variable_types={"obj": "object"})

    def test_wrong_kind_of_value_is_refused(self) -> None:
        bad = TableFacts({"mug": "object"}, {("hot", ("mug",)): 3.0})
        with pytest.raises(ValueError, match="expected a bool"):
            encode(parse("hot(#mug)"), bad)

    def test_substituted_template_condition(self) -> None:
        formula = substitute(parse("hot($obj) -> distance(robot, $p) >= 0.5"),
                             {"obj": "mug", "p": "ann"})
        result = prove(encode(formula, STATE))
        assert result.outcome is Outcome.VIOLATED
