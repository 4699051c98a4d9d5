"""Stage 3, the Decision Gate: the paper's rule cascade, first match wins.

In: the bound hazards and unbound hazards from Stage 2, the unknowns from Stage 1, and a policy
(theta, the severity from which a hazard counts as severe; default high).
Out: a `GateDecision` (authorize, defer or reject), the rule that fired, what triggered it and,
for a clarify deferral, one plain question.
Fails: never. `decide` is pure and total: every input gets exactly one decision, and the only way
to `authorize` is that no earlier rule matched.

    R1   unpreventable and severity >= theta            -> reject
    R1b  preventability unknown and severity >= theta   -> defer (clarify)
    R2   any hazard with no template (or without the
         entities its template binds)                   -> defer (extend_library), asking the
                                                           question of a critical unknown if any
    R3   any critical unknown                           -> defer (clarify)
    R3b  severity critical and confidence uncertain     -> defer (clarify)
    R4   otherwise                                      -> authorize
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum

from pydantic import BaseModel, ConfigDict

from app.domain.models import (
    Confidence,
    HazardProposal,
    Preventability,
    Severity,
    UnknownFact,
)


class Decision(StrEnum):
    AUTHORIZE = "authorize"
    DEFER = "defer"
    REJECT = "reject"


class Rule(StrEnum):
    R1 = "R1"
    R1B = "R1b"
    R2 = "R2"
    R3 = "R3"
    R3B = "R3b"
    R4 = "R4"


class DeferKind(StrEnum):
    CLARIFY = "clarify"
    EXTEND_LIBRARY = "extend_library"


@dataclass(frozen=True, slots=True)
class GatePolicy:
    """Tunable gate parameters. `theta` is the severity from which R1/R1b apply."""

    theta: Severity = Severity.HIGH


DEFAULT_POLICY = GatePolicy()


class GateDecision(BaseModel):
    """The gate's verdict with its reasons."""

    model_config = ConfigDict(frozen=True)

    decision: Decision
    rule: Rule
    defer_kind: DeferKind | None = None
    question: str | None = None
    trigger_hazards: tuple[HazardProposal, ...] = ()
    trigger_unknowns: tuple[UnknownFact, ...] = ()
    reason: str


def decide(
    bound: Sequence[HazardProposal],
    unbound: Sequence[HazardProposal],
    unknowns: Sequence[UnknownFact],
    policy: GatePolicy = DEFAULT_POLICY,
    *,
    entities_missing: Sequence[HazardProposal] = (),
) -> GateDecision:
    """Run the cascade R1, R1b, R2, R3, R3b, R4 and return the first rule that matches.

    Args:
        bound: hazards that matched a template of the library.
        unbound: hazards with no template (they still count for R1/R1b: a severe hazard is
            severe whether or not we have a template for it).
        unknowns: what Stage 1 found it does not know.
        policy: theta and friends.
        entities_missing: the unbound hazards whose class has templates but which lack the
            entities those templates bind (R2 then says so rather than "no template").

    Returns:
        The decision, the rule that fired, and its triggers.
    """
    hazards = [*bound, *unbound]
    severe = [h for h in hazards if h.severity.rank >= policy.theta.rank]

    unpreventable = [h for h in severe if h.preventability is Preventability.UNPREVENTABLE]
    if unpreventable:
        return GateDecision(
            decision=Decision.REJECT,
            rule=Rule.R1,
            trigger_hazards=tuple(unpreventable),
            reason=_reason("cannot be prevented by any contract", unpreventable),
        )

    unclear = [h for h in severe if h.preventability is Preventability.UNKNOWN]
    if unclear:
        return GateDecision(
            decision=Decision.DEFER,
            rule=Rule.R1B,
            defer_kind=DeferKind.CLARIFY,
            question=_question_about_hazard(unclear[0], unknowns),
            trigger_hazards=tuple(unclear),
            trigger_unknowns=tuple(_unknowns_about(unclear[0], unknowns)),
            reason=_reason("may or may not be preventable", unclear),
        )

    critical_unknowns = [u for u in unknowns if u.critical]
    if unbound:
        # The library gap decides, but a question another finding raised (an ensemble's
        # symbolic member, say) is still asked rather than lost behind it.
        return GateDecision(
            decision=Decision.DEFER,
            rule=Rule.R2,
            defer_kind=DeferKind.EXTEND_LIBRARY,
            question=_question_about_unknown(critical_unknowns[0]) if critical_unknowns
            else None,
            trigger_hazards=tuple(unbound),
            trigger_unknowns=tuple(critical_unknowns),
            reason=_reason("has a template but not the scene entities it binds"
                           if unbound[0] in entities_missing
                           else "has no template in the library", list(unbound)),
        )

    if critical_unknowns:
        return GateDecision(
            decision=Decision.DEFER,
            rule=Rule.R3,
            defer_kind=DeferKind.CLARIFY,
            question=_question_about_unknown(critical_unknowns[0]),
            trigger_unknowns=tuple(critical_unknowns),
            reason="critical information is missing: "
            + "; ".join(u.description for u in critical_unknowns),
        )

    doubtful = [
        h
        for h in hazards
        if h.severity is Severity.CRITICAL and h.confidence is Confidence.UNCERTAIN
    ]
    if doubtful:
        return GateDecision(
            decision=Decision.DEFER,
            rule=Rule.R3B,
            defer_kind=DeferKind.CLARIFY,
            question=_question_about_hazard(doubtful[0], unknowns),
            trigger_hazards=tuple(doubtful),
            reason=_reason("is critical and the analysis is not certain of it", doubtful),
        )

    return GateDecision(
        decision=Decision.AUTHORIZE,
        rule=Rule.R4,
        reason="every hazard is bound to a template and nothing critical is unknown",
    )


def _reason(what: str, hazards: Sequence[HazardProposal]) -> str:
    first = hazards[0]
    more = f" (and {len(hazards) - 1} more)" if len(hazards) > 1 else ""
    return f"{first.hazard_class} {what}: {first.mechanism}{more}"


def _question_about_unknown(unknown: UnknownFact) -> str:
    if unknown.question:
        return unknown.question
    return f"Before I go ahead, I need to know {unknown.description.rstrip('.?')}. Can you tell me?"


def _unknowns_about(
    hazard: HazardProposal, unknowns: Sequence[UnknownFact]
) -> list[UnknownFact]:
    """The critical unknowns about an entity the hazard involves: what would settle it."""
    involved = set(hazard.entities.values())
    return [u for u in unknowns if u.critical and u.entity is not None and u.entity in involved]


def _question_about_hazard(hazard: HazardProposal, unknowns: Sequence[UnknownFact]) -> str:
    # A fact about the hazard's own entities settles it best; any other critical unknown of
    # the same analysis is still a better question than asking to confirm the hazard.
    settling = _unknowns_about(hazard, unknowns) or [u for u in unknowns if u.critical]
    if settling:
        return _question_about_unknown(settling[0])
    return (
        f"Before I do this: {hazard.mechanism.rstrip('.')}. "
        "Can you confirm how this should be handled safely, or should I not do it?"
    )
