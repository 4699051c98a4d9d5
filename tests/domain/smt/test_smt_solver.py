"""The solver facade: proofs, satisfiability, counterexamples, unknown outcomes."""

from __future__ import annotations

import z3

from app.domain.formula import TableFacts, parse
from app.domain.smt import (
    Outcome,
    Satisfiability,
    encode,
    encode_symbolic,
    prove,
    satisfiable,
    valid,
)

STATE = TableFacts({"mug": "object", "ann": "person"}, {("hot", ("mug",)): True})
VARIABLES = {"obj": "object", "person": "person", "min_distance": "number"}


class TestProve:
    def test_holds_for_every_value_of_unknowns(self) -> None:
        assert prove(encode(parse("lidded(#mug) or not lidded(#mug)"), STATE)).holds

    def test_violated_with_counterexample_of_python_values(self) -> None:
        result = prove(encode(parse("not hot(#mug) or distance(robot, #ann) > 1"), STATE))
        assert result.outcome is Outcome.VIOLATED
        assert isinstance(result.counterexample["distance(robot,ann)"], float)
        assert result.counterexample["distance(robot,ann)"] <= 1

    def test_counterexample_satisfies_the_negation(self) -> None:
        result = prove(encode(parse("lidded(#mug) and wet(#mug)"), STATE))
        assert result.counterexample["lidded(mug)"] is False or result.counterexample[
            "wet(mug)"] is False

    def test_assumptions_are_taken_as_given(self) -> None:
        claim = encode(parse("lidded(#mug)"), STATE)
        assert prove(claim, assumptions=[encode(parse("lidded(#mug)"), STATE)]).holds

    def test_several_claims_must_all_hold(self) -> None:
        claims = [encode(parse("hot(#mug)"), STATE), encode(parse("wet(#mug)"), STATE)]
        assert prove(claims).outcome is Outcome.VIOLATED

    def test_solver_unknown_is_its_own_outcome_and_not_holds(self) -> None:
        x, y = z3.Ints("x y")
        hard = z3.ForAll([x], z3.Exists([y], x * x * x + y * y * x == 7 * y + x * y * y + 3))
        result = prove(hard, timeout_ms=1)
        assert result.outcome in (Outcome.UNKNOWN, Outcome.VIOLATED)
        assert not result.holds


class TestSatisfiable:
    def test_sat_with_witness(self) -> None:
        result = satisfiable(encode(parse("wet(#mug) and not lidded(#mug)"), STATE))
        assert result.sat
        assert result.model == {"lidded(mug)": False, "wet(mug)": True}

    def test_unsat(self) -> None:
        result = satisfiable(encode(parse("wet(#mug) and not wet(#mug)"), STATE))
        assert result.outcome is Satisfiability.UNSAT

    def test_valid_is_prove(self) -> None:
        assert valid(encode(parse("hot(#mug)"), STATE)).holds


class TestSymbolic:
    def test_template_invariants_jointly_satisfiable(self) -> None:
        invariants = [
            encode_symbolic(parse(text), VARIABLES)
            for text in ("holding(robot, $obj) and hot($obj) -> "
                         "distance(robot, $person) >= $min_distance",
                         "forall p: person . distance(robot, p) >= 0")
        ]
        assert satisfiable(invariants).sat

    def test_contradictory_invariants_unsat(self) -> None:
        invariants = [encode_symbolic(parse(text), VARIABLES)
                      for text in ("hot($obj)", "forall o: object . not hot(o)")]
        assert satisfiable(invariants).outcome is Satisfiability.UNSAT

    def test_abort_that_always_fires_is_valid(self) -> None:
        abort = encode_symbolic(parse("hot($obj) or not hot($obj)"), VARIABLES)
        assert valid(abort).holds

    def test_reasonable_abort_is_not_valid(self) -> None:
        abort = encode_symbolic(parse("wet($obj) and near($obj, $person)"), VARIABLES)
        assert valid(abort).outcome is Outcome.VIOLATED

    def test_default_value_is_substituted(self) -> None:
        formula = parse("$min_distance > 1")
        assert not satisfiable(
            encode_symbolic(formula, VARIABLES, defaults={"min_distance": 0.5})
        ).sat
        assert satisfiable(encode_symbolic(formula, VARIABLES)).sat

    def test_guard_with_open_action_argument_is_satisfiable(self) -> None:
        guard = encode_symbolic(parse("@object != $obj or not hot($obj)"), VARIABLES)
        assert satisfiable(guard).sat

    def test_variables_are_distinct_entities(self) -> None:
        formula = parse("$obj == $other")
        assert not satisfiable(
            encode_symbolic(formula, {"obj": "object", "other": "object"})
        ).sat
