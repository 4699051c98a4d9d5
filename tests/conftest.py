"""Database fixtures for the whole suite: real SQLite files and real PostgreSQL databases.

- `sqlite_url`: a fresh SQLite file in the test's temporary directory.
- `postgres_url`: a fresh, empty PostgreSQL database made for this test alone and dropped after
  it. The server is the one `SAFEGATE_TEST_POSTGRES_URL` names (CI sets
  `postgresql+psycopg://postgres@127.0.0.1:5432/test`; that database is only used to create and
  drop the per-test ones), else a throwaway server pytest-postgresql starts with the machine's
  pg_ctl. No server at all is an error, never a skip: PostgreSQL tests must run.
- `database_url`: both of the above, as parameters "sqlite" and "postgres" (marked `postgres`).
- `migrated_engine` and `repository`: an engine at Alembic's head, and a `Repository` on it,
  for `database_url`.
"""

from __future__ import annotations

import functools
import os
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest
from pytest_postgresql import factories
from sqlalchemy import Engine, create_engine, make_url, text

from app.domain.models import HazardTemplate
from app.store.db import create_engine_for, migrate
from app.store.repository import Repository
from app.store.seed import load_library

# Every test runs with the network guard: a socket to another machine fails the test.
pytest_plugins = ["tests.network_guard"]

POSTGRES_URL_ENV = "SAFEGATE_TEST_POSTGRES_URL"
PG_CTL_AS_POSTGRES = Path(__file__).parent / "store" / "pg_ctl_as_postgres.py"

# The wrapper finds the machine's newest pg_ctl (/usr/lib/postgresql/*/bin) and, when the tests
# run as root, runs it as the `postgres` user, because initdb refuses to run as root.
safegate_postgresql_proc = factories.postgresql_proc(
    executable=str(PG_CTL_AS_POSTGRES), host="127.0.0.1", port=None, user="postgres"
)


@pytest.fixture(scope="session")
def postgres_admin_url(request: pytest.FixtureRequest) -> str:
    """A URL to a PostgreSQL database allowed to CREATE and DROP DATABASE."""
    configured = os.environ.get(POSTGRES_URL_ENV)
    if configured:
        return configured
    if not os.access(PG_CTL_AS_POSTGRES, os.X_OK):
        PG_CTL_AS_POSTGRES.chmod(0o755)
    server = request.getfixturevalue("safegate_postgresql_proc")
    return f"postgresql+psycopg://{server.user}@{server.host}:{server.port}/postgres"


@pytest.fixture(scope="session")
def postgres_admin_engine(postgres_admin_url: str) -> Iterator[Engine]:
    """An autocommit engine on the admin database (CREATE DATABASE cannot run in a transaction)."""
    engine = create_engine(postgres_admin_url, isolation_level="AUTOCOMMIT", pool_size=1)
    yield engine
    engine.dispose()


@pytest.fixture
def postgres_url(postgres_admin_url: str, postgres_admin_engine: Engine) -> Iterator[str]:
    """A new empty PostgreSQL database for this test only, dropped afterwards."""
    name = f"safegate_test_{uuid.uuid4().hex[:16]}"
    with postgres_admin_engine.connect() as connection:
        connection.execute(text(f'CREATE DATABASE "{name}"'))
    yield make_url(postgres_admin_url).set(database=name).render_as_string(hide_password=False)
    with postgres_admin_engine.connect() as connection:
        connection.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))


@pytest.fixture
def sqlite_url(tmp_path: Path) -> str:
    """A new SQLite database file in this test's temporary directory."""
    return f"sqlite:///{tmp_path / 'safegate.db'}"


@pytest.fixture(params=["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)])
def database_url(request: pytest.FixtureRequest) -> str:
    """A fresh database URL, once for SQLite and once for PostgreSQL."""
    url: str = request.getfixturevalue(f"{request.param}_url")
    return url


@pytest.fixture
def migrated_engine(database_url: str) -> Iterator[Engine]:
    """An engine on `database_url` with the schema at Alembic's head."""
    engine = create_engine_for(database_url)
    migrate(engine)
    yield engine
    engine.dispose()


@pytest.fixture
def repository(migrated_engine: Engine) -> Repository:
    """A `Repository` on a freshly migrated database."""
    return Repository(migrated_engine)


@functools.cache
def seed_library() -> tuple[HazardTemplate, ...]:
    """The seed Hazard Template Library (`templates_db/`), read once per test process."""
    return tuple(load_library(Path(__file__).resolve().parents[1] / "templates_db"))
