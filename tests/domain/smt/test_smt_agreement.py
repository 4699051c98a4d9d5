"""Property: the compiled evaluator and the Z3 encoding agree on random formulas and states.

When the evaluator gives a definite value, Z3 proves that value for every value of the unknown
facts; when nothing is unknown, the evaluator is definite and Z3 agrees with it.
"""

from __future__ import annotations

import z3
from formula_strategies import action_args, formulas, partial_states, random_state
from hypothesis import given, settings
from hypothesis import strategies as st

from app.domain.formula import Formula, TableFacts, compile_formula
from app.domain.smt import Encoding, Outcome, encode, prove


def _proves(encoding: Encoding, value: bool) -> Outcome:
    claim = encoding.expr if value else z3.Not(encoding.expr)
    negated = Encoding(claim, encoding.assumptions, encoding.unknowns)
    return prove(negated, timeout_ms=10_000).outcome


class TestEvaluatorAgreesWithZ3:
    @settings(max_examples=2000, deadline=None)
    @given(formulas(depth=3, guard=True), partial_states(), action_args())
    def test_definite_evaluation_is_proved(
        self, formula: Formula, state: TableFacts, args: dict[str, str | None] | None
    ) -> None:
        value = compile_formula(formula)(state, args)
        if value is not None:
            assert _proves(encode(formula, state, args), value) is Outcome.HOLDS

    @settings(max_examples=2000, deadline=None)
    @given(formulas(depth=3), st.integers(0, 2**32))
    def test_fully_known_state_gives_the_same_value(self, formula: Formula, seed: int) -> None:
        # No action arguments here: `@target` may name an entity of the wrong kind for a
        # predicate, whose fact is then unknown even in a state that lists every fact.
        state = random_state(seed, unknown_ratio=0.0)
        value = compile_formula(formula)(state)
        encoding = encode(formula, state)
        assert encoding.unknowns == {}
        assert value is not None
        assert _proves(encoding, value) is Outcome.HOLDS
