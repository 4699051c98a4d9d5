"""Engines, timestamps and failure: an unreachable database is `Unavailable`, never an answer."""

from __future__ import annotations

import socket
from collections.abc import Callable, Iterator
from datetime import UTC, datetime
from pathlib import Path

import pytest
from sqlalchemy import Engine, text
from sqlalchemy.dialects import sqlite

from app.domain.errors import Unavailable
from app.domain.models import HazardTemplate, TemplateStatus
from app.store.db import create_engine_for, make_session_factory, migrate
from app.store.records import ApiKeyRole, GateRecord
from app.store.repository import Repository
from app.store.tables import UtcDateTime


def _closed_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind(("127.0.0.1", 0))
        port: int = probe.getsockname()[1]
    return port


@pytest.fixture
def unreachable() -> Iterator[Repository]:
    """A repository whose PostgreSQL server does not exist (nothing listens on the port)."""
    engine = create_engine_for(f"postgresql+psycopg://postgres@127.0.0.1:{_closed_port()}/none")
    yield Repository(engine)
    engine.dispose()


class TestCreateEngineFor:
    def test_sqlite_files_enforce_foreign_keys_and_use_wal(self, sqlite_url: str) -> None:
        engine = create_engine_for(sqlite_url)
        try:
            with engine.connect() as connection:
                assert connection.execute(text("PRAGMA foreign_keys")).scalar() == 1
                assert connection.execute(text("PRAGMA journal_mode")).scalar() == "wal"
        finally:
            engine.dispose()

    def test_in_memory_sqlite_is_one_database_across_sessions(self) -> None:
        engine = create_engine_for("sqlite://")
        try:
            migrate(engine)
            Repository(engine).put_cached_analysis("k", "m", "v", {"n": 1})
            assert Repository(engine).get_cached_analysis("k", "m", "v") == {"n": 1}
        finally:
            engine.dispose()

    def test_postgres_gets_a_working_engine(self, postgres_url: str) -> None:
        engine = create_engine_for(postgres_url)
        try:
            with engine.connect() as connection:
                assert connection.execute(text("SELECT 1")).scalar() == 1
        finally:
            engine.dispose()


class TestRepositoryBinding:
    def test_a_session_factory_works_like_an_engine(self, migrated_engine: Engine) -> None:
        through_factory = Repository(make_session_factory(migrated_engine))
        through_factory.put_cached_analysis("k", "m", "v", {"n": 2})
        assert Repository(migrated_engine).get_cached_analysis("k", "m", "v") == {"n": 2}


class TestUtcDateTime:
    def test_naive_datetimes_are_refused(self) -> None:
        with pytest.raises(ValueError, match="naive"):
            UtcDateTime().process_bind_param(datetime(2024, 1, 1), sqlite.dialect())

    def test_naive_values_read_back_are_utc(self) -> None:
        read = UtcDateTime().process_result_value(datetime(2024, 1, 1, 12), sqlite.dialect())
        assert read == datetime(2024, 1, 1, 12, tzinfo=UTC)


@pytest.mark.faults
class TestUnavailable:
    def test_ping_fails_closed(self, unreachable: Repository) -> None:
        with pytest.raises(Unavailable):
            unreachable.ping()

    def test_reading_templates_fails_instead_of_returning_none(
        self, unreachable: Repository
    ) -> None:
        with pytest.raises(Unavailable):
            unreachable.list_active_templates()

    def test_key_lookup_fails_instead_of_finding_nothing(self, unreachable: Repository) -> None:
        with pytest.raises(Unavailable):
            unreachable.find_active_api_key("0" * 64)

    def test_spending_an_attempt_fails(self, unreachable: Repository) -> None:
        with pytest.raises(Unavailable):
            unreachable.use_verification_attempt("0" * 32)

    def test_writes_fail(
        self,
        unreachable: Repository,
        make_gate_record: Callable[..., GateRecord],
        make_template: Callable[..., HazardTemplate],
    ) -> None:
        with pytest.raises(Unavailable):
            unreachable.save_gate_record(make_gate_record())
        with pytest.raises(Unavailable):
            unreachable.upsert_seed_templates([make_template()])
        with pytest.raises(Unavailable):
            unreachable.create_api_key(key_hash="h", role=ApiKeyRole.ROBOT, name="r")

    def test_migrating_an_unreachable_database_fails(self) -> None:
        with pytest.raises(Unavailable):
            migrate(f"postgresql+psycopg://postgres@127.0.0.1:{_closed_port()}/none")

    def test_a_database_without_the_schema_is_unavailable(self, sqlite_url: str) -> None:
        engine = create_engine_for(sqlite_url)
        try:
            with pytest.raises(Unavailable):
                Repository(engine).set_template_status("a.b", TemplateStatus.ACTIVE)
        finally:
            engine.dispose()

    def test_an_unwritable_sqlite_file_is_unavailable(self, tmp_path: Path) -> None:
        engine = create_engine_for(f"sqlite:///{tmp_path / 'missing_dir' / 'x.db'}")
        try:
            with pytest.raises(Unavailable):
                Repository(engine).ping()
        finally:
            engine.dispose()

    def test_the_detail_does_not_leak_the_url(self) -> None:
        secret_url = f"postgresql+psycopg://admin:hunter2@127.0.0.1:{_closed_port()}/none"
        engine = create_engine_for(secret_url)
        try:
            with pytest.raises(Unavailable) as caught:
                Repository(engine).ping()
            assert "hunter2" not in caught.value.detail
        finally:
            engine.dispose()
