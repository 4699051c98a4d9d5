"""The trace prover: one solver for a whole trace, a cache keyed by what the encoder read."""

from __future__ import annotations

from app.domain.formula import FactValue, TableFacts, Unknown, parse
from app.domain.smt import Outcome
from app.domain.smt.trace import TraceProver

ENTITIES = {"mug": "object", "ann": "person"}


def _state(**facts: FactValue) -> TableFacts:
    return TableFacts(ENTITIES, {(name, ("mug",)): value for name, value in facts.items()})


class TestTraceProver:
    def test_same_reads_in_another_state_are_answered_from_the_cache(self) -> None:
        prover = TraceProver(5000)
        formula = parse("lidded(#mug) or not lidded(#mug)")
        first = prover.prove("c", formula, _state(hot=True))
        second = prover.prove("c", formula, _state(hot=False))
        assert first.outcome is second.outcome is Outcome.HOLDS
        assert (prover.solver_calls, prover.cache_hits) == (1, 1)

    def test_a_changed_read_is_proved_again(self) -> None:
        prover = TraceProver(5000)
        formula = parse("hot(#mug) -> lidded(#mug)")
        assert prover.prove("c", formula, _state(hot=False)).outcome is Outcome.HOLDS
        broken = prover.prove("c", formula, _state(hot=True))
        assert broken.outcome is Outcome.VIOLATED
        assert broken.counterexample == {"hot(mug)": True, "lidded(mug)": False}
        assert broken.free == ("lidded(mug)",)
        assert prover.solver_calls == 2

    def test_an_unknown_under_another_key_is_named_by_its_fact(self) -> None:
        prover = TraceProver(5000)
        state = _state(hot=Unknown("is_on(stove)@2"))
        proof = prover.prove("c", parse("not hot(#mug)"), state)
        assert proof.counterexample == {"hot(mug)": True}

    def test_abort_is_violated_when_it_can_hold(self) -> None:
        prover = TraceProver(5000)
        proof = prover.prove("a", parse("wet(#mug)"), _state(), must_hold=False)
        assert proof.outcome is Outcome.VIOLATED
        assert proof.counterexample == {"wet(mug)": True}

    def test_unknown_numbers_are_not_negative(self) -> None:
        prover = TraceProver(5000)
        assert prover.prove("n", parse("mass_kg(#mug) >= 0"), _state()).outcome is Outcome.HOLDS

    def test_spent_budget_is_unknown(self) -> None:
        proof = TraceProver(0).prove("c", parse("lidded(#mug)"), _state())
        assert proof.outcome is Outcome.UNKNOWN and proof.detail.startswith("timeout")
