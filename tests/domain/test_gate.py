"""The Decision Gate's cascade: each rule, its precedence, and totality."""

from __future__ import annotations

import itertools

from app.domain.gate import Decision, DeferKind, GatePolicy, Rule, decide
from app.domain.models import (
    Category,
    Confidence,
    HazardProposal,
    Level,
    Preventability,
    Severity,
    UnknownFact,
)


def hazard(
    severity: Severity = Severity.HIGH,
    preventability: Preventability = Preventability.PREVENTABLE,
    confidence: Confidence = Confidence.CERTAIN,
    hazard_class: str = "scald_hot_liquid",
) -> HazardProposal:
    return HazardProposal(
        level=Level.USER,
        category=Category.PHYSICAL,
        hazard_class=hazard_class,
        mechanism="hot coffee carried near a child",
        entities={"obj": "mug_1", "person": "person_1"},
        severity=severity,
        preventability=preventability,
        confidence=confidence,
    )


def unknown(critical: bool = True) -> UnknownFact:
    return UnknownFact(
        attribute="age_group",
        description="the age of the guest",
        critical=critical,
        why="a knife must not be handed to a child",
        entity="person_2",
        question="How old is the guest?",
    )


class TestDecide:
    def test_nothing_found_authorizes_with_r4(self) -> None:
        result = decide([], [], [])
        assert (result.decision, result.rule) == (Decision.AUTHORIZE, Rule.R4)

    def test_preventable_bound_hazard_authorizes(self) -> None:
        result = decide([hazard()], [], [unknown(critical=False)])
        assert result.decision is Decision.AUTHORIZE

    def test_unpreventable_severe_hazard_rejects_with_r1(self) -> None:
        trigger = hazard(preventability=Preventability.UNPREVENTABLE)
        result = decide([trigger], [], [])
        assert (result.decision, result.rule) == (Decision.REJECT, Rule.R1)
        assert result.trigger_hazards == (trigger,)

    def test_unpreventable_below_theta_does_not_reject(self) -> None:
        result = decide([hazard(Severity.MODERATE, Preventability.UNPREVENTABLE)], [], [])
        assert result.decision is Decision.AUTHORIZE

    def test_theta_is_configurable(self) -> None:
        low = hazard(Severity.MODERATE, Preventability.UNPREVENTABLE)
        result = decide([low], [], [], GatePolicy(theta=Severity.MODERATE))
        assert result.rule is Rule.R1

    def test_unknown_preventability_defers_to_clarify_with_r1b(self) -> None:
        result = decide([hazard(preventability=Preventability.UNKNOWN)], [], [])
        assert (result.decision, result.rule) == (Decision.DEFER, Rule.R1B)
        assert result.defer_kind is DeferKind.CLARIFY
        assert result.question

    def test_r1b_asks_the_question_of_the_unknown_that_settles_it(self) -> None:
        unclear = hazard(preventability=Preventability.UNKNOWN)
        about_person = unknown().model_copy(update={"entity": "person_1"})
        result = decide([unclear], [], [about_person])
        assert result.rule is Rule.R1B
        assert result.question == "How old is the guest?"
        assert result.trigger_unknowns == (about_person,)

    def test_unbound_hazard_defers_to_extend_library_with_r2(self) -> None:
        result = decide([], [hazard(hazard_class="laser_pointer")], [])
        assert (result.rule, result.defer_kind) == (Rule.R2, DeferKind.EXTEND_LIBRARY)

    def test_unbound_unpreventable_hazard_still_rejects(self) -> None:
        result = decide([], [hazard(preventability=Preventability.UNPREVENTABLE)], [])
        assert result.rule is Rule.R1

    def test_critical_unknown_defers_with_r3_and_its_question(self) -> None:
        result = decide([hazard()], [], [unknown()])
        assert (result.rule, result.defer_kind) == (Rule.R3, DeferKind.CLARIFY)
        assert result.question == "How old is the guest?"

    def test_critical_uncertain_hazard_defers_with_r3b(self) -> None:
        result = decide([hazard(Severity.CRITICAL, confidence=Confidence.UNCERTAIN)], [], [])
        assert result.rule is Rule.R3B

    def test_r1_wins_over_every_later_rule(self) -> None:
        result = decide(
            [hazard(preventability=Preventability.UNPREVENTABLE)],
            [hazard(hazard_class="unmapped")],
            [unknown()],
        )
        assert result.rule is Rule.R1

    def test_r2_wins_over_r3(self) -> None:
        result = decide([], [hazard(hazard_class="unmapped")], [unknown()])
        assert result.rule is Rule.R2

    def test_r2_still_asks_the_question_of_a_critical_unknown(self) -> None:
        result = decide([], [hazard(hazard_class="unmapped")], [unknown()])
        assert (result.rule, result.question) == (Rule.R2, "How old is the guest?")
        assert result.trigger_unknowns == (unknown(),)
        assert decide([], [hazard(hazard_class="unmapped")], []).question is None

    def test_every_combination_gets_one_decision_and_authorize_only_by_r4(self) -> None:
        for severity, prevent, conf, crit in itertools.product(
            Severity, Preventability, Confidence, (True, False)
        ):
            result = decide([hazard(severity, prevent, conf)], [], [unknown(crit)])
            assert (result.decision is Decision.AUTHORIZE) == (result.rule is Rule.R4)
            if prevent is Preventability.UNPREVENTABLE and severity.rank >= Severity.HIGH.rank:
                assert result.decision is Decision.REJECT
            if crit:
                assert result.decision is not Decision.AUTHORIZE

    def test_same_input_same_decision(self) -> None:
        inputs = ([hazard()], [hazard(hazard_class="x")], [unknown()])
        assert decide(*inputs) == decide(*inputs)
