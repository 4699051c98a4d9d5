"""The audit trail keeps the reference plan a gate answer handed out (issue 17).

Revision ID: 0002
Revises: 0001
Create Date: 2026-11-26
"""

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0002"
down_revision: str | None = "0001"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("gate_records") as batch:
        batch.add_column(sa.Column("reference_plan", sa.JSON(), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("gate_records") as batch:
        batch.drop_column("reference_plan")
