"""API models (`XRequest`/`XResponse`) and the mapping from domain results to them.

The gate's answer follows `shared/spec/gate-request.md`; fields are only ever added, never renamed.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from app.domain.binding import BindingResult
from app.domain.contracts import Contract, ContractCondition, planner_constraints
from app.domain.gate import Decision, DeferKind, Rule
from app.domain.models import (
    Category,
    ConditionKind,
    Confidence,
    HazardProposal,
    Level,
    Preventability,
    Severity,
    UnknownFact,
)
from app.domain.template_validation import suggest_template
from app.services.gate import Decided
from app.store.records import ContractRecord, ContractStatus


class HazardOut(BaseModel):
    """A hazard Stage 1 found, with the template that bound it (or why none did)."""

    level: Level = Field(description="Where it comes from: the task, the deployment, the user.")
    category: Category
    hazard_class: str = Field(description="From the shared taxonomy, e.g. `thermal_burn`.")
    mechanism: str = Field(description="How harm would come about, in words.")
    severity: Severity
    preventability: Preventability = Field(
        description="Whether some way of doing the task avoids it (then the contract forbids "
                    "the other ways).")
    confidence: Confidence
    template_id: str | None = Field(description="The template that bound it; null: unbound.")
    template_ids: list[str] = Field(default_factory=list)
    bindings: dict[str, Any] = Field(description="Template variables to scene ids, e.g. "
                                                 '`{"obj": "mug_1", "person": "p1"}`.')
    unbound_reason: str | None = None


class UnknownOut(BaseModel):
    """A fact the gate needed and did not have; a critical one is never authorized around."""

    attribute: str
    description: str
    critical: bool
    why: str
    entity: str | None = None


class ReferencePlanOut(BaseModel):
    """A plan for the authorized command, proved by Stage 5 to keep its contract."""

    plan: list[dict[str, Any]]
    goal: str | None
    reason: str


class GateResponse(BaseModel):
    """The answer to POST /gate: the decision, the rule that fired, and why."""

    request_id: str = Field(description="The audit record's id (`GET /gate/{request_id}`).")
    decision: Decision
    rule: Rule = Field(description="The Decision Gate rule that fired (R1, R1b, R2, R3, R3b, "
                                   "R4; see `docs/api/gate.md`).")
    defer_kind: DeferKind | None = Field(
        description="For a deferral: `clarify` (answer `question`) or `extend_library` (a "
                    "curator must add a template).")
    question: str | None
    reason: str
    hazards: list[HazardOut]
    unknowns: list[UnknownOut]
    triggers: list[str] = Field(description="The hazards and unknowns that decided it.")
    contract_id: str | None = Field(description="For `authorize`: the Task Safety Contract.")
    analyzer: str
    parent_request_id: str | None = None
    timings_ms: dict[str, float] = Field(default_factory=dict)
    suggested_templates: list[dict[str, Any]] = Field(default_factory=list)
    reference_plan: ReferencePlanOut | None = None
    """Only with `?reference_plan=true` on an authorize: a plan that provably keeps the contract."""
    reference_plan_reason: str | None = None
    """With `?reference_plan=true`, why `reference_plan` is null (not authorized, none found)."""


def _reference(decided: Decided) -> tuple[ReferencePlanOut | None, str | None]:
    reference = decided.reference
    if reference is None:
        return None, None
    if reference.plan is None:
        return None, reference.reason
    return ReferencePlanOut(plan=[dict(step) for step in reference.plan], goal=reference.goal,
                            reason=reference.reason), None


def hazards_out(binding: BindingResult) -> list[HazardOut]:
    out: list[HazardOut] = []
    for bound in binding.bound:
        first = bound.matches[0]
        out.append(
            _hazard(
                bound.proposal,
                template_id=first.template.id,
                template_ids=[m.template.id for m in bound.matches],
                bindings=dict(first.bindings),
            )
        )
    for unbound in binding.unbound:
        out.append(
            _hazard(
                unbound.proposal,
                template_id=None,
                template_ids=[],
                bindings=dict(unbound.proposal.entities),
                unbound_reason=unbound.reason,
            )
        )
    return out


def _hazard(proposal: HazardProposal, **extra: Any) -> HazardOut:
    return HazardOut(
        level=proposal.level.value,
        category=proposal.category.value,
        hazard_class=proposal.hazard_class,
        mechanism=proposal.mechanism,
        severity=proposal.severity.value,
        preventability=proposal.preventability.value,
        confidence=proposal.confidence.value,
        **extra,
    )


def unknown_out(unknown: UnknownFact) -> UnknownOut:
    return UnknownOut(
        attribute=unknown.attribute,
        description=unknown.description,
        critical=unknown.critical,
        why=unknown.why,
        entity=unknown.entity,
    )


def suggested_template(proposal: HazardProposal) -> dict[str, Any]:
    """A template skeleton a curator can start from for an unbound hazard."""
    return suggest_template(proposal)


def gate_response(decided: Decided) -> GateResponse:
    """The answer to a decision, made from the same value as its audit record."""
    result = decided.result
    decision = result.decision
    triggers = [f"{h.hazard_class}: {h.mechanism}" for h in decision.trigger_hazards] + [
        f"unknown {u.attribute}: {u.description}" for u in decision.trigger_unknowns
    ]
    reference, reference_reason = _reference(decided)
    suggestions = [
        suggested_template(u.proposal)
        for u in result.binding.unbound
        if decision.defer_kind is DeferKind.EXTEND_LIBRARY
    ]
    return GateResponse(
        request_id=decided.request_id,
        decision=decision.decision,
        rule=decision.rule,
        defer_kind=decision.defer_kind,
        question=decision.question,
        reason=decision.reason,
        hazards=hazards_out(result.binding),
        unknowns=[unknown_out(u) for u in result.report.unknowns],
        triggers=triggers,
        contract_id=decided.contract_id,
        analyzer=result.report.analyzer,
        parent_request_id=decided.parent_request_id,
        timings_ms={k: round(v, 3) for k, v in result.timings_ms.items()},
        suggested_templates=suggestions,
        reference_plan=reference,
        reference_plan_reason=reference_reason,
    )


class ContractConditionOut(BaseModel):
    """One condition of a contract: a formula over the scene's entities."""

    model_config = ConfigDict(from_attributes=True)

    id: str
    kind: ConditionKind
    formula: str
    description: str
    action: str | None
    template_id: str
    template_version: int
    bindings: dict[str, Any]
    envelope: bool = False


class ScopeStepOut(BaseModel):
    """One step the command authorizes; `object_kind`/`target_kind` when Stage 1 made the
    entity up (then any entity of that kind will do)."""

    action: str
    object: str | None
    target: str | None
    words: str
    kind: str
    object_kind: str | None = None
    target_kind: str | None = None


class ScopeOut(BaseModel):
    """The task's scope: the authorized steps, the actions allowed on anything, and whether
    something outside the task may be picked up to be moved aside."""

    command: str
    steps: list[ScopeStepOut]
    enabling: list[str]
    move_aside: bool


class ContractResponse(BaseModel):
    """A Task Safety Contract: what every plan and every action of the task must keep."""

    contract_id: str
    request_id: str | None
    invariants: list[ContractConditionOut]
    guards: list[ContractConditionOut]
    aborts: list[ContractConditionOut]
    template_versions: dict[str, int]
    planner_constraints: list[str]
    attempts_used: int = 0
    attempts_left: int | None = None
    status: ContractStatus = ContractStatus.ACTIVE
    scope: ScopeOut | None = None
    """None for a contract compiled before scopes existed: its plans get no scope check."""


def _condition(condition: ContractCondition) -> ContractConditionOut:
    return ContractConditionOut(
        id=condition.id,
        kind=condition.kind.value,
        formula=condition.formula,
        description=condition.description,
        action=condition.action,
        template_id=condition.template_id,
        template_version=condition.template_version,
        bindings=dict(condition.bindings),
        envelope=condition.envelope,
    )


def contract_response(contract: Contract, stored: ContractRecord) -> ContractResponse:
    return ContractResponse(
        contract_id=str(stored.id),
        request_id=stored.request_id,
        invariants=[_condition(c) for c in contract.invariants],
        guards=[_condition(c) for c in contract.guards],
        aborts=[_condition(c) for c in contract.aborts],
        template_versions=dict(contract.template_versions),
        planner_constraints=planner_constraints(contract),
        attempts_used=stored.attempts_used,
        attempts_left=stored.attempts_left,
        status=stored.status.value,
        scope=None if contract.scope is None else ScopeOut.model_validate(
            contract.scope.model_dump()),
    )
