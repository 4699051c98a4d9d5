"""Alembic migrations on real SQLite and PostgreSQL: up, no drift from the models, down."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from alembic import command
from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext
from sqlalchemy import Engine, inspect, text

from app.store.db import alembic_config, create_engine_for, migrate
from app.store.repository import Repository
from app.store.tables import Base

REPO_ROOT = Path(__file__).resolve().parents[2]
ALEMBIC = Path(sys.executable).with_name("alembic")


def _tables(engine: Engine) -> set[str]:
    return set(inspect(engine).get_table_names())


class TestMigrate:
    def test_upgrade_head_on_an_empty_database_creates_every_table(self, database_url: str) -> None:
        engine = create_engine_for(database_url)
        try:
            assert _tables(engine) == set()
            migrate(engine)
            assert _tables(engine) == set(Base.metadata.tables) | {"alembic_version"}
        finally:
            engine.dispose()

    def test_migrated_schema_has_no_drift_from_the_models(self, migrated_engine: Engine) -> None:
        with migrated_engine.connect() as connection:
            context = MigrationContext.configure(connection, opts={"compare_type": True})
            differences = compare_metadata(context, Base.metadata)
        assert differences == []

    def test_migrating_twice_changes_nothing(self, migrated_engine: Engine) -> None:
        migrate(migrated_engine)
        with migrated_engine.connect() as connection:
            versions = connection.execute(text("SELECT version_num FROM alembic_version")).all()
        assert [row[0] for row in versions] == ["0002"]

    def test_records_written_before_the_reference_plan_column_read_back_without_one(
        self, database_url: str
    ) -> None:
        engine = create_engine_for(database_url)
        try:
            migrate(engine, "0001")
            with engine.begin() as connection:
                connection.execute(text(
                    "INSERT INTO gate_records (id, created_at, request, decision, rule, "
                    "triggers, timings, analyzer, template_versions, downgraded) VALUES "
                    "(:id, CURRENT_TIMESTAMP, :request, 'authorize', 'R4', '[]', '{}', "
                    "'symbolic', '{}', false)"),
                    {"id": "a" * 32, "request": '{"command": "tidy up"}'})
            migrate(engine)
            record = Repository(engine).get_gate_record("a" * 32)
            assert record.request.command == "tidy up" and record.reference_plan is None
        finally:
            engine.dispose()

    def test_downgrade_base_leaves_no_tables(self, migrated_engine: Engine) -> None:
        with migrated_engine.begin() as connection:
            config = alembic_config()
            config.attributes["connection"] = connection
            command.downgrade(config, "base")
        assert _tables(migrated_engine) <= {"alembic_version"}
        with migrated_engine.connect() as connection:
            assert connection.execute(text("SELECT count(*) FROM alembic_version")).scalar() == 0

    def test_migrate_accepts_a_url(self, database_url: str) -> None:
        migrate(database_url)
        engine = create_engine_for(database_url)
        try:
            assert "hazard_templates" in _tables(engine)
        finally:
            engine.dispose()


class TestAlembicCommandLine:
    def test_upgrade_reads_the_url_from_the_environment(self, database_url: str) -> None:
        environment = {**os.environ, "SAFEGATE_DATABASE_URL": database_url}
        subprocess.run(
            [str(ALEMBIC), "upgrade", "head"], cwd=REPO_ROOT, env=environment, check=True
        )
        engine = create_engine_for(database_url)
        try:
            assert "gate_records" in _tables(engine)
        finally:
            engine.dispose()

    def test_x_url_overrides_the_environment(self, sqlite_url: str, tmp_path: Path) -> None:
        decoy = f"sqlite:///{tmp_path / 'decoy.db'}"
        environment = {**os.environ, "SAFEGATE_DATABASE_URL": decoy}
        subprocess.run(
            [str(ALEMBIC), "-x", f"url={sqlite_url}", "upgrade", "head"],
            cwd=REPO_ROOT,
            env=environment,
            check=True,
        )
        assert not (tmp_path / "decoy.db").exists()
        engine = create_engine_for(sqlite_url)
        try:
            assert "contracts" in _tables(engine)
        finally:
            engine.dispose()
