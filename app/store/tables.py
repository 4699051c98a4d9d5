"""SafeGate's SQL schema as SQLAlchemy 2.0 typed ORM classes, portable to SQLite and PostgreSQL.

In: nothing (declarations only). Out: `Base.metadata`, which Alembic's migrations must match
(a test autogenerates against it and expects no drift), and the mapped classes the repository
queries. Ids are 32-character hex strings (uuid4) except template ids, which are the library's
own dotted names. Every timestamp is stored and returned timezone-aware in UTC; JSON columns hold
documents the domain models produce with `model_dump(mode="json")`.
Fails: never at import; constraint violations surface when a session flushes.
"""

from __future__ import annotations

import uuid
from datetime import UTC, datetime
from typing import Any

from sqlalchemy import (
    JSON,
    Boolean,
    CheckConstraint,
    DateTime,
    Dialect,
    Float,
    ForeignKey,
    Index,
    Integer,
    MetaData,
    String,
    Text,
    TypeDecorator,
)
from sqlalchemy.orm import DeclarativeBase, Mapped, mapped_column

NAMING_CONVENTION = {
    "ix": "ix_%(column_0_label)s",
    "uq": "uq_%(table_name)s_%(column_0_name)s",
    "ck": "ck_%(table_name)s_%(constraint_name)s",
    "fk": "fk_%(table_name)s_%(column_0_name)s_%(referred_table_name)s",
    "pk": "pk_%(table_name)s",
}

ID_LENGTH = 32
TEMPLATE_ID_LENGTH = 120


def new_id() -> str:
    """A fresh random 32-character hex id."""
    return uuid.uuid4().hex


def utc_now() -> datetime:
    """The current instant, timezone-aware in UTC."""
    return datetime.now(UTC)


class UtcDateTime(TypeDecorator[datetime]):
    """A timestamp that is always timezone-aware UTC on the way in and out.

    SQLite keeps no zone, so naive values read back are UTC by construction; a naive value
    handed in is refused rather than guessed at.
    """

    impl = DateTime(timezone=True)
    cache_ok = True

    def process_bind_param(self, value: datetime | None, dialect: Dialect) -> datetime | None:
        if value is None:
            return None
        if value.tzinfo is None:
            raise ValueError("naive datetime given to a timezone-aware column")
        return value.astimezone(UTC)

    def process_result_value(self, value: datetime | None, dialect: Dialect) -> datetime | None:
        if value is None:
            return None
        if value.tzinfo is None:
            return value.replace(tzinfo=UTC)
        return value.astimezone(UTC)


class Base(DeclarativeBase):
    metadata = MetaData(naming_convention=NAMING_CONVENTION)
    type_annotation_map = {
        datetime: UtcDateTime(),
        dict[str, Any]: JSON(),
        list[Any]: JSON(),
    }


class HazardTemplateRow(Base):
    """One Hazard Template Library entry; its content lives in `TemplateVersionRow`."""

    __tablename__ = "hazard_templates"
    __table_args__ = (
        CheckConstraint("status IN ('draft', 'active', 'deprecated')", name="status"),
        CheckConstraint("source IN ('seed', 'user')", name="source"),
        Index("ix_hazard_templates_status_category", "status", "category"),
    )

    id: Mapped[str] = mapped_column(String(TEMPLATE_ID_LENGTH), primary_key=True)
    hazard_class: Mapped[str] = mapped_column(String(120), index=True)
    category: Mapped[str] = mapped_column(String(32))
    status: Mapped[str] = mapped_column(String(16))
    source: Mapped[str] = mapped_column(String(8))
    current_version: Mapped[int] = mapped_column(Integer)
    created_at: Mapped[datetime] = mapped_column(default=utc_now)
    updated_at: Mapped[datetime] = mapped_column(default=utc_now)


class TemplateVersionRow(Base):
    """One immutable version of a template: the full document plus who wrote it and when."""

    __tablename__ = "template_versions"

    template_id: Mapped[str] = mapped_column(
        String(TEMPLATE_ID_LENGTH),
        ForeignKey("hazard_templates.id", ondelete="CASCADE"),
        primary_key=True,
    )
    version: Mapped[int] = mapped_column(Integer, primary_key=True)
    document: Mapped[dict[str, Any]]
    content_hash: Mapped[str] = mapped_column(String(64))
    author: Mapped[str] = mapped_column(String(200))
    status: Mapped[str] = mapped_column(String(16))
    created_at: Mapped[datetime] = mapped_column(default=utc_now)


class GateRecordRow(Base):
    """The audit trail: one gate request with the decision it got and why."""

    __tablename__ = "gate_records"
    __table_args__ = (Index("ix_gate_records_defer_kind_created_at", "defer_kind", "created_at"),)

    id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True, default=new_id)
    created_at: Mapped[datetime] = mapped_column(default=utc_now, index=True)
    request: Mapped[dict[str, Any]]
    hazard_report: Mapped[dict[str, Any] | None]
    decision: Mapped[str] = mapped_column(String(16))
    rule: Mapped[str] = mapped_column(String(8))
    defer_kind: Mapped[str | None] = mapped_column(String(32))
    question: Mapped[str | None] = mapped_column(Text)
    triggers: Mapped[list[Any]]
    timings: Mapped[dict[str, Any]]
    analyzer: Mapped[str] = mapped_column(String(200))
    template_versions: Mapped[dict[str, Any]]
    contract_id: Mapped[str | None] = mapped_column(String(ID_LENGTH), index=True)
    parent_request_id: Mapped[str | None] = mapped_column(
        String(ID_LENGTH), ForeignKey("gate_records.id", ondelete="SET NULL"), index=True
    )
    downgraded: Mapped[bool] = mapped_column(Boolean, default=False)
    downgrade_reason: Mapped[str | None] = mapped_column(Text)
    reference_plan: Mapped[dict[str, Any] | None]


class ContractRow(Base):
    """A compiled Task Safety Contract and its verification budget."""

    __tablename__ = "contracts"
    __table_args__ = (
        CheckConstraint("status IN ('active', 'exhausted')", name="status"),
        CheckConstraint("attempts_used >= 0 AND attempts_used <= max_attempts", name="attempts"),
    )

    id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True, default=new_id)
    request_id: Mapped[str] = mapped_column(
        String(ID_LENGTH), ForeignKey("gate_records.id", ondelete="CASCADE"), index=True
    )
    contract: Mapped[dict[str, Any]]
    template_versions: Mapped[dict[str, Any]]
    created_at: Mapped[datetime] = mapped_column(default=utc_now)
    attempts_used: Mapped[int] = mapped_column(Integer, default=0)
    max_attempts: Mapped[int] = mapped_column(Integer)
    status: Mapped[str] = mapped_column(String(16), default="active")


class VerificationAttemptRow(Base):
    """One `/verify` call against a contract."""

    __tablename__ = "verification_attempts"

    id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True, default=new_id)
    contract_id: Mapped[str] = mapped_column(
        String(ID_LENGTH), ForeignKey("contracts.id", ondelete="CASCADE"), index=True
    )
    plan: Mapped[list[Any]]
    ok: Mapped[bool] = mapped_column(Boolean)
    violations: Mapped[list[Any]]
    created_at: Mapped[datetime] = mapped_column(default=utc_now)
    duration_ms: Mapped[float] = mapped_column(Float)


class MonitorSessionRow(Base):
    """A runtime monitoring session; `halted` is absorbing."""

    __tablename__ = "monitor_sessions"

    id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True, default=new_id)
    contract_id: Mapped[str] = mapped_column(
        String(ID_LENGTH), ForeignKey("contracts.id", ondelete="CASCADE"), index=True
    )
    initial_state: Mapped[dict[str, Any]]
    halted: Mapped[bool] = mapped_column(Boolean, default=False)
    halt_violation: Mapped[dict[str, Any] | None]
    counters: Mapped[dict[str, Any]]
    created_at: Mapped[datetime] = mapped_column(default=utc_now)
    updated_at: Mapped[datetime] = mapped_column(default=utc_now)


class MonitorEventRow(Base):
    """One message of a monitoring session, numbered 1, 2, 3... within its session."""

    __tablename__ = "monitor_events"

    session_id: Mapped[str] = mapped_column(
        String(ID_LENGTH),
        ForeignKey("monitor_sessions.id", ondelete="CASCADE"),
        primary_key=True,
    )
    seq: Mapped[int] = mapped_column(Integer, primary_key=True)
    type: Mapped[str] = mapped_column(String(32))
    payload: Mapped[dict[str, Any]]
    created_at: Mapped[datetime] = mapped_column(default=utc_now)


class ApiKeyRow(Base):
    """An API key, stored only as a hash of the secret."""

    __tablename__ = "api_keys"
    __table_args__ = (CheckConstraint("role IN ('robot', 'curator', 'admin')", name="role"),)

    id: Mapped[str] = mapped_column(String(ID_LENGTH), primary_key=True, default=new_id)
    key_hash: Mapped[str] = mapped_column(String(128), unique=True)
    role: Mapped[str] = mapped_column(String(16))
    name: Mapped[str] = mapped_column(String(200))
    created_at: Mapped[datetime] = mapped_column(default=utc_now)
    revoked: Mapped[bool] = mapped_column(Boolean, default=False)


class LlmCacheRow(Base):
    """A cached LLM hazard analysis, keyed by the caller's hash of its inputs."""

    __tablename__ = "llm_cache"

    cache_key: Mapped[str] = mapped_column(String(128), primary_key=True)
    model: Mapped[str] = mapped_column(String(200), primary_key=True)
    prompt_version: Mapped[str] = mapped_column(String(64), primary_key=True)
    result: Mapped[dict[str, Any]]
    created_at: Mapped[datetime] = mapped_column(default=utc_now)
