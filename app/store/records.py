"""What the repository hands in and out besides hazard templates: frozen pydantic records.

In/out: the gate's audit record, contracts and their verification attempts, monitoring sessions
and events, API keys, and the result of seeding the template library. Parts the domain already
models (`GateRequest`, `HazardReport`, `InitialState`, `HazardTemplate`, the gate's `Decision`,
`Rule` and `DeferKind`) are typed; parts it does
not model yet (the contract body, triggers, violations, plans) are plain JSON values.
Fails: pydantic `ValidationError` when a record is built from values of the wrong shape.
"""

from __future__ import annotations

from datetime import datetime
from enum import StrEnum
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from app.domain.gate import Decision, DeferKind, Rule
from app.domain.models import (
    GateRequest,
    HazardReport,
    HazardTemplate,
    InitialState,
    TemplateStatus,
)

JsonObject = dict[str, Any]


class _Record(BaseModel):
    model_config = ConfigDict(frozen=True)


class GateRecord(_Record):
    """One gate request and its decision: the audit trail's unit.

    `id` and `created_at` left as None are filled in by `save_gate_record`.
    `template_versions` maps each template id used to the version used.
    """

    id: str | None = None
    created_at: datetime | None = None
    request: GateRequest
    hazard_report: HazardReport | None = None
    decision: Decision
    rule: Rule
    defer_kind: DeferKind | None = None
    question: str | None = None
    triggers: list[Any] = Field(default_factory=list)
    timings: JsonObject = Field(default_factory=dict)
    analyzer: str = "symbolic"
    template_versions: dict[str, int] = Field(default_factory=dict)
    contract_id: str | None = None
    parent_request_id: str | None = None
    downgraded: bool = False
    downgrade_reason: str | None = None
    reference_plan: JsonObject | None = None
    """Only when the caller asked for one (`POST /gate?reference_plan=true`): the plan handed
    out, `{"plan": [...], "goal": ..., "reason": ...}`, or `{"plan": null, "reason": ...}`."""


class ContractStatus(StrEnum):
    ACTIVE = "active"
    EXHAUSTED = "exhausted"


class ContractRecord(_Record):
    """A stored Task Safety Contract and how much of its verification budget is spent."""

    id: str | None = None
    request_id: str
    contract: JsonObject
    template_versions: dict[str, int] = Field(default_factory=dict)
    created_at: datetime | None = None
    attempts_used: int = Field(default=0, ge=0)
    max_attempts: int = Field(ge=1)
    status: ContractStatus = ContractStatus.ACTIVE

    @property
    def attempts_left(self) -> int:
        """Verification attempts still allowed (0 once exhausted)."""
        if self.status is ContractStatus.EXHAUSTED:
            return 0
        return max(self.max_attempts - self.attempts_used, 0)


class VerificationAttemptRecord(_Record):
    """One `/verify` call: the plan checked, the verdict and how long the check took."""

    id: str | None = None
    contract_id: str
    plan: list[Any]
    ok: bool
    violations: list[Any] = Field(default_factory=list)
    created_at: datetime | None = None
    duration_ms: float = Field(ge=0)


class MonitorSessionRecord(_Record):
    """A runtime monitoring session. Once `halted` is true it never becomes false again."""

    id: str | None = None
    contract_id: str
    initial_state: InitialState
    halted: bool = False
    halt_violation: JsonObject | None = None
    counters: JsonObject = Field(default_factory=dict)
    created_at: datetime | None = None
    updated_at: datetime | None = None


class MonitorEventRecord(_Record):
    """One message exchanged in a monitoring session; `seq` counts 1, 2, 3... per session."""

    session_id: str
    seq: int = Field(ge=1)
    type: str = Field(min_length=1, max_length=32)
    payload: JsonObject
    created_at: datetime


class ApiKeyRole(StrEnum):
    ROBOT = "robot"
    CURATOR = "curator"
    ADMIN = "admin"


class ApiKeyRecord(_Record):
    """An API key as stored: never the secret, only its hash."""

    id: str
    key_hash: str
    role: ApiKeyRole
    name: str
    created_at: datetime
    revoked: bool


class TemplateVersionRecord(_Record):
    """One stored version of a hazard template."""

    template_id: str
    version: int
    template: HazardTemplate
    author: str
    status: TemplateStatus
    created_at: datetime


class TemplateHistory(_Record):
    """A template at its current version together with every version it has had, oldest first."""

    current: HazardTemplate
    versions: tuple[TemplateVersionRecord, ...]


class SeedReport(_Record):
    """What one load of the seed library changed, by template id."""

    added: tuple[str, ...] = ()
    new_versions: tuple[str, ...] = ()
    unchanged: tuple[str, ...] = ()
    skipped_user: tuple[str, ...] = ()


class TemplateChange(_Record):
    """One template an import writes: its content (as a new version when `new_version`), the
    status it ends with, and the version the import was planned against (None: a new id)."""

    template: HazardTemplate
    status: TemplateStatus
    new_version: bool
    base_version: int | None
