"""Initial schema: templates, audit trail, contracts, verification, monitoring, keys, LLM cache.

Revision ID: 0001
Revises:
Create Date: 2026-11-21
"""

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0001"
down_revision: str | None = None
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    op.create_table(
        "api_keys",
        sa.Column("id", sa.String(length=32), nullable=False),
        sa.Column("key_hash", sa.String(length=128), nullable=False),
        sa.Column("role", sa.String(length=16), nullable=False),
        sa.Column("name", sa.String(length=200), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("revoked", sa.Boolean(), nullable=False),
        sa.CheckConstraint("role IN ('robot', 'curator', 'admin')", name=op.f("ck_api_keys_role")),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_api_keys")),
        sa.UniqueConstraint("key_hash", name=op.f("uq_api_keys_key_hash")),
    )
    op.create_table(
        "gate_records",
        sa.Column("id", sa.String(length=32), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("request", sa.JSON(), nullable=False),
        sa.Column("hazard_report", sa.JSON(), nullable=True),
        sa.Column("decision", sa.String(length=16), nullable=False),
        sa.Column("rule", sa.String(length=8), nullable=False),
        sa.Column("defer_kind", sa.String(length=32), nullable=True),
        sa.Column("question", sa.Text(), nullable=True),
        sa.Column("triggers", sa.JSON(), nullable=False),
        sa.Column("timings", sa.JSON(), nullable=False),
        sa.Column("analyzer", sa.String(length=200), nullable=False),
        sa.Column("template_versions", sa.JSON(), nullable=False),
        sa.Column("contract_id", sa.String(length=32), nullable=True),
        sa.Column("parent_request_id", sa.String(length=32), nullable=True),
        sa.Column("downgraded", sa.Boolean(), nullable=False),
        sa.Column("downgrade_reason", sa.Text(), nullable=True),
        sa.ForeignKeyConstraint(
            ["parent_request_id"],
            ["gate_records.id"],
            name=op.f("fk_gate_records_parent_request_id_gate_records"),
            ondelete="SET NULL",
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_gate_records")),
    )
    op.create_index(
        op.f("ix_gate_records_contract_id"), "gate_records", ["contract_id"], unique=False
    )
    op.create_index(
        op.f("ix_gate_records_created_at"), "gate_records", ["created_at"], unique=False
    )
    op.create_index(
        "ix_gate_records_defer_kind_created_at",
        "gate_records",
        ["defer_kind", "created_at"],
        unique=False,
    )
    op.create_index(
        op.f("ix_gate_records_parent_request_id"),
        "gate_records",
        ["parent_request_id"],
        unique=False,
    )
    op.create_table(
        "hazard_templates",
        sa.Column("id", sa.String(length=120), nullable=False),
        sa.Column("hazard_class", sa.String(length=120), nullable=False),
        sa.Column("category", sa.String(length=32), nullable=False),
        sa.Column("status", sa.String(length=16), nullable=False),
        sa.Column("source", sa.String(length=8), nullable=False),
        sa.Column("current_version", sa.Integer(), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("updated_at", sa.DateTime(timezone=True), nullable=False),
        sa.CheckConstraint("source IN ('seed', 'user')", name=op.f("ck_hazard_templates_source")),
        sa.CheckConstraint(
            "status IN ('draft', 'active', 'deprecated')", name=op.f("ck_hazard_templates_status")
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_hazard_templates")),
    )
    op.create_index(
        op.f("ix_hazard_templates_hazard_class"), "hazard_templates", ["hazard_class"], unique=False
    )
    op.create_index(
        "ix_hazard_templates_status_category",
        "hazard_templates",
        ["status", "category"],
        unique=False,
    )
    op.create_table(
        "llm_cache",
        sa.Column("cache_key", sa.String(length=128), nullable=False),
        sa.Column("model", sa.String(length=200), nullable=False),
        sa.Column("prompt_version", sa.String(length=64), nullable=False),
        sa.Column("result", sa.JSON(), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.PrimaryKeyConstraint("cache_key", "model", "prompt_version", name=op.f("pk_llm_cache")),
    )
    op.create_table(
        "contracts",
        sa.Column("id", sa.String(length=32), nullable=False),
        sa.Column("request_id", sa.String(length=32), nullable=False),
        sa.Column("contract", sa.JSON(), nullable=False),
        sa.Column("template_versions", sa.JSON(), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("attempts_used", sa.Integer(), nullable=False),
        sa.Column("max_attempts", sa.Integer(), nullable=False),
        sa.Column("status", sa.String(length=16), nullable=False),
        sa.CheckConstraint("status IN ('active', 'exhausted')", name=op.f("ck_contracts_status")),
        sa.CheckConstraint(
            "attempts_used >= 0 AND attempts_used <= max_attempts",
            name=op.f("ck_contracts_attempts"),
        ),
        sa.ForeignKeyConstraint(
            ["request_id"],
            ["gate_records.id"],
            name=op.f("fk_contracts_request_id_gate_records"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_contracts")),
    )
    op.create_index(op.f("ix_contracts_request_id"), "contracts", ["request_id"], unique=False)
    op.create_table(
        "template_versions",
        sa.Column("template_id", sa.String(length=120), nullable=False),
        sa.Column("version", sa.Integer(), nullable=False),
        sa.Column("document", sa.JSON(), nullable=False),
        sa.Column("content_hash", sa.String(length=64), nullable=False),
        sa.Column("author", sa.String(length=200), nullable=False),
        sa.Column("status", sa.String(length=16), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.ForeignKeyConstraint(
            ["template_id"],
            ["hazard_templates.id"],
            name=op.f("fk_template_versions_template_id_hazard_templates"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("template_id", "version", name=op.f("pk_template_versions")),
    )
    op.create_table(
        "monitor_sessions",
        sa.Column("id", sa.String(length=32), nullable=False),
        sa.Column("contract_id", sa.String(length=32), nullable=False),
        sa.Column("initial_state", sa.JSON(), nullable=False),
        sa.Column("halted", sa.Boolean(), nullable=False),
        sa.Column("halt_violation", sa.JSON(), nullable=True),
        sa.Column("counters", sa.JSON(), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("updated_at", sa.DateTime(timezone=True), nullable=False),
        sa.ForeignKeyConstraint(
            ["contract_id"],
            ["contracts.id"],
            name=op.f("fk_monitor_sessions_contract_id_contracts"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_monitor_sessions")),
    )
    op.create_index(
        op.f("ix_monitor_sessions_contract_id"), "monitor_sessions", ["contract_id"], unique=False
    )
    op.create_table(
        "verification_attempts",
        sa.Column("id", sa.String(length=32), nullable=False),
        sa.Column("contract_id", sa.String(length=32), nullable=False),
        sa.Column("plan", sa.JSON(), nullable=False),
        sa.Column("ok", sa.Boolean(), nullable=False),
        sa.Column("violations", sa.JSON(), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("duration_ms", sa.Float(), nullable=False),
        sa.ForeignKeyConstraint(
            ["contract_id"],
            ["contracts.id"],
            name=op.f("fk_verification_attempts_contract_id_contracts"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_verification_attempts")),
    )
    op.create_index(
        op.f("ix_verification_attempts_contract_id"),
        "verification_attempts",
        ["contract_id"],
        unique=False,
    )
    op.create_table(
        "monitor_events",
        sa.Column("session_id", sa.String(length=32), nullable=False),
        sa.Column("seq", sa.Integer(), nullable=False),
        sa.Column("type", sa.String(length=32), nullable=False),
        sa.Column("payload", sa.JSON(), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.ForeignKeyConstraint(
            ["session_id"],
            ["monitor_sessions.id"],
            name=op.f("fk_monitor_events_session_id_monitor_sessions"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("session_id", "seq", name=op.f("pk_monitor_events")),
    )


def downgrade() -> None:
    op.drop_table("monitor_events")
    op.drop_index(op.f("ix_verification_attempts_contract_id"), table_name="verification_attempts")
    op.drop_table("verification_attempts")
    op.drop_index(op.f("ix_monitor_sessions_contract_id"), table_name="monitor_sessions")
    op.drop_table("monitor_sessions")
    op.drop_table("template_versions")
    op.drop_index(op.f("ix_contracts_request_id"), table_name="contracts")
    op.drop_table("contracts")
    op.drop_table("llm_cache")
    op.drop_index("ix_hazard_templates_status_category", table_name="hazard_templates")
    op.drop_index(op.f("ix_hazard_templates_hazard_class"), table_name="hazard_templates")
    op.drop_table("hazard_templates")
    op.drop_index(op.f("ix_gate_records_parent_request_id"), table_name="gate_records")
    op.drop_index("ix_gate_records_defer_kind_created_at", table_name="gate_records")
    op.drop_index(op.f("ix_gate_records_created_at"), table_name="gate_records")
    op.drop_index(op.f("ix_gate_records_contract_id"), table_name="gate_records")
    op.drop_table("gate_records")
    op.drop_table("api_keys")
