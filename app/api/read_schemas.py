"""Response models of the reading and administrative routes: the audit record, templates,
keys, the extension queue, the vocabulary and the probes.

The gate's and the verifier's answers are in `schemas.py` and `verify_schemas.py`. Every model
here forbids keys it does not name, so a body that grows a field without its model fails its
tests instead of losing the field on the wire; optional keys are left out when absent (the
routes answer with `response_model_exclude_unset`), as they always were.
"""

from __future__ import annotations

from datetime import datetime
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from app.domain.gate import Decision, DeferKind, Rule
from app.domain.models import (
    GateRequest,
    HazardReport,
    HazardTemplate,
    Severity,
    TemplateStatus,
)
from app.store.records import ApiKeyRole


class _Out(BaseModel):
    model_config = ConfigDict(extra="forbid")


class HealthResponse(_Out):
    """The process is up."""

    status: str = Field(examples=["ok"])


class ReadinessResponse(_Out):
    """The database answers and the library is loaded."""

    status: str = Field(examples=["ready"])
    templates: int = Field(description="Active templates loaded.")


class StoredReferencePlan(_Out):
    """What the audit trail keeps of a reference plan: the plan handed out, or null and why."""

    plan: list[dict[str, Any]] | None = Field(
        description="The steps as handed out (the plan wire shape), or null when none.")
    goal: str | None = Field(default=None, description="What the plan reaches.")
    reason: str | None = Field(default=None, description="Why there is a plan, or why none.")


class GateRecordResponse(_Out):
    """A decision's audit record, with the decisions that followed it."""

    id: str
    request_id: str = Field(description="The same id, under the name the gate answered it.")
    created_at: datetime
    request: GateRequest = Field(description="The request as it was sent.")
    hazard_report: HazardReport | None = Field(
        description="Stage 1's report: hazard proposals and unknowns.")
    decision: Decision
    rule: Rule
    defer_kind: DeferKind | None
    question: str | None
    triggers: list[dict[str, Any]] = Field(
        description="The hazards and unknowns that decided it, as the analysis reported them.")
    timings: dict[str, float] = Field(description="Milliseconds per stage.")
    analyzer: str
    template_versions: dict[str, int] = Field(
        description="Each template the contract used, with its version.")
    contract_id: str | None
    parent_request_id: str | None
    downgraded: bool = Field(description="Rejected since: the contract's verification "
                                         "attempts ran out.")
    downgrade_reason: str | None
    followed_by: list[str] = Field(description="Answers and re-evaluations, oldest first.")
    reference_plan: StoredReferencePlan | None = Field(
        default=None, description="The reference plan handed out with the decision, when the "
                                  "request asked for one (null otherwise).")


class IssueOut(_Out):
    """A problem found in a template document (`line` and `column` only within a formula)."""

    field: str
    message: str
    code: str
    line: int | None = None
    column: int | None = None


class TemplateValidationResponse(_Out):
    """The verdict on a template document; nothing is stored."""

    valid: bool
    errors: list[IssueOut]
    warnings: list[IssueOut]


class TemplateResponse(HazardTemplate):
    """A template at one version."""

    model_config = ConfigDict(extra="forbid", frozen=True)


class CuratedTemplateResponse(TemplateResponse):
    """A stored template with what its validation warned about."""

    warnings: list[IssueOut]


class TemplateVersionOut(_Out):
    """One stored version of a template."""

    template_id: str
    version: int
    template: TemplateResponse
    author: str
    status: TemplateStatus
    created_at: datetime


class TemplateHistoryResponse(TemplateResponse):
    """A template at its current version, with every version kept, oldest first."""

    versions: list[TemplateVersionOut]


class KeyResponse(_Out):
    """An API key as stored (never its secret)."""

    id: str
    role: ApiKeyRole
    name: str
    created_at: datetime
    revoked: bool


class CreatedKeyResponse(KeyResponse):
    """A new key, with its secret: shown this once."""

    key: str


class KeyListResponse(_Out):
    """Every key, revoked ones included."""

    keys: list[KeyResponse]


class WaitingHazardOut(_Out):
    hazard_class: str
    mechanism: str
    severity: Severity
    entities: dict[str, str]


class WaitingRequestOut(_Out):
    """A request whose latest decision waits for the library to cover a class."""

    request_id: str
    command: str
    created_at: str | None
    parent_request_id: str | None
    hazards: list[WaitingHazardOut]
    also_waiting_for: list[str]


class PendingClassOut(_Out):
    hazard_class: str
    count: int
    covered: bool
    covered_by: list[str]
    requests: list[WaitingRequestOut]
    suggested_template: dict[str, Any] | None


class PendingExtensionsResponse(_Out):
    """Requests waiting for a library extension, grouped by hazard class."""

    count: int
    classes: list[PendingClassOut]


class SymbolOut(_Out):
    name: str
    args: list[str]
    result: str
    meaning: str
    can_be_unknown: bool


class ActionArgumentOut(_Out):
    name: str
    type: str
    required: bool
    description: str | None = None


class PreconditionOut(_Out):
    formula: str
    description: str


class ActionOut(_Out):
    name: str
    summary: str
    aliases: list[str]
    arguments: list[ActionArgumentOut]
    preconditions: list[PreconditionOut]
    effects: list[str]


class VocabularyResponse(_Out):
    """The condition language's predicates and functions, and the action model."""

    symbols: list[SymbolOut]
    actions: list[ActionOut]
