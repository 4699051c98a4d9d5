"""The database going away: every gate call is a 503 problem+json, never a decision, and the
readiness probe says so; when the database comes back, so does the gate.

PostgreSQL: the test's database stops accepting connections under a running app and its open
connections are terminated, which is what a crashed or unreachable database looks like to a
client.
SQLite: the database file, its WAL and the directory are made unwritable (`chattr +i`, which
holds even for root; plain permissions otherwise) while the app runs.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient
from sqlalchemy import Engine, make_url, text

from app.config import Settings
from app.main import create_app

pytestmark = pytest.mark.faults
COMMAND = {"command": "bring the mug to the kitchen"}


def assert_unavailable(response: Any) -> None:
    assert response.status_code == 503, response.text
    assert response.headers["content-type"] == "application/problem+json"
    body = response.json()
    assert body["status"] == 503 and "decision" not in body


_TERMINATE = ("SELECT pg_terminate_backend(pid) FROM pg_stat_activity "
              "WHERE datname = :name AND pid <> pg_backend_pid()")


@contextmanager
def database_closed(admin: Engine, name: str) -> Iterator[None]:
    """The database refuses every connection and its open ones are cut, until the block ends."""
    with admin.connect() as connection:
        connection.execute(text(f'ALTER DATABASE "{name}" WITH ALLOW_CONNECTIONS false'))
        connection.execute(text(_TERMINATE), {"name": name})
    try:
        yield
    finally:
        with admin.connect() as connection:
            connection.execute(text(f'ALTER DATABASE "{name}" WITH ALLOW_CONNECTIONS true'))


@pytest.mark.postgres
class TestPostgresGoesAway:
    def test_gate_and_readiness_answer_503_then_recover(
        self, postgres_url: str, postgres_admin_engine: Engine
    ) -> None:
        name = make_url(postgres_url).database
        assert name is not None
        with TestClient(create_app(Settings(database_url=postgres_url))) as client:
            assert client.post("/gate", json=COMMAND).status_code == 200
            with database_closed(postgres_admin_engine, name):
                for _ in range(3):
                    assert_unavailable(client.post("/gate", json=COMMAND))
                assert_unavailable(client.get("/readyz"))
                assert client.get("/healthz").status_code == 200  # the process is alive
            assert client.get("/readyz").status_code == 200
            assert client.post("/gate", json=COMMAND).status_code == 200


def _freeze(paths: list[Path]) -> list[Path]:
    """Make paths unwritable; returns those that need unfreezing."""
    if os.geteuid() == 0 and shutil.which("chattr"):
        existing = [p for p in paths if p.exists()]
        subprocess.run(["chattr", "+i", *map(str, existing)], check=True)
        return existing
    for path in paths:
        if path.exists():
            path.chmod(0o555 if path.is_dir() else 0o444)
    return []


def _thaw(paths: list[Path], frozen: list[Path]) -> None:
    if frozen:
        subprocess.run(["chattr", "-i", *map(str, frozen)], check=True)
    for path in paths:
        if path.exists():
            path.chmod(0o755 if path.is_dir() else 0o644)


class TestSqliteBecomesUnwritable:
    def test_gate_answers_503_never_a_decision(self, tmp_path: Path) -> None:
        directory = tmp_path / "store"
        directory.mkdir()
        database = directory / "safegate.db"
        with TestClient(create_app(Settings(database_url=f"sqlite:///{database}"))) as client:
            assert client.post("/gate", json=COMMAND).status_code == 200
            # Not the -shm file: SQLite maps it into memory, and a frozen mapping is a SIGBUS.
            paths = [database, Path(f"{database}-wal"), directory]
            frozen = _freeze(paths)
            try:
                for _ in range(3):
                    assert_unavailable(client.post("/gate", json=COMMAND))
            finally:
                _thaw(paths, frozen)
            assert client.post("/gate", json=COMMAND).status_code == 200
