"""Engines, sessions, migrations and the one place database errors become `Unavailable`.

In: a database URL (`sqlite:///./safegate.db`, `postgresql+psycopg://user@host/db`) or an engine.
Out: a configured `Engine` (`create_engine_for`), a schema at Alembic's head (`migrate`), a
`sessionmaker`, and `database_errors()`, a context manager that turns driver failures into
`app.domain.errors.Unavailable` so no caller can mistake "the database is down" for an answer.
Fails: `Unavailable` when the database cannot be reached or migrated.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from alembic import command
from alembic.config import Config
from pydantic_core import to_json
from sqlalchemy import Connection, Engine, create_engine, event, make_url, text
from sqlalchemy.engine import URL
from sqlalchemy.exc import SQLAlchemyError
from sqlalchemy.orm import Session, sessionmaker
from sqlalchemy.pool import StaticPool

from app.domain.errors import Unavailable

DEFAULT_DATABASE_URL = "sqlite:///./safegate.db"
MIGRATIONS_DIRECTORY = Path(__file__).resolve().parents[2] / "migrations"
POSTGRES_CONNECT_TIMEOUT_SECONDS = 5
SQLITE_BUSY_TIMEOUT_MS = 5000
STARTUP_LOCK_KEY = 0x5AFE5EED  # start-up (migrate + seed); migrations/env.py holds its own key


def _is_sqlite_memory(url: URL) -> bool:
    return url.database in (None, "", ":memory:") or (url.query.get("mode") == "memory")


def create_engine_for(url: str, **engine_options: Any) -> Engine:
    """Build an engine with SafeGate's settings for the URL's dialect.

    SQLite gets foreign keys enforced, a busy timeout, WAL journaling when the database is a file,
    transactions that take the write lock when they begin (so concurrent writers queue instead of
    failing), and connections shareable across threads (FastAPI runs sync routes in a thread
    pool); an in-memory SQLite database is kept on one shared connection so every session sees it.
    PostgreSQL gets pre-ping and a short connect timeout so an outage fails fast.

    Args:
        url: a SQLAlchemy database URL.
        **engine_options: extra keyword arguments for `sqlalchemy.create_engine`.

    Returns:
        A new engine; dispose of it when done.
    """
    parsed = make_url(url)
    engine_options = {"json_serializer": _json_text, **engine_options}
    if parsed.get_backend_name() == "sqlite":
        return _create_sqlite_engine(parsed, engine_options)
    options: dict[str, Any] = {"pool_pre_ping": True}
    if parsed.get_backend_name() == "postgresql":
        options["connect_args"] = {"connect_timeout": POSTGRES_CONNECT_TIMEOUT_SECONDS}
    options.update(engine_options)
    return create_engine(parsed, **options)


def _json_text(value: Any) -> str:
    """JSON columns' encoder: pydantic-core's (compiled), several times the standard library's
    speed on the audit trail's large documents. A pydantic model may be stored as it is: it is
    written as `model_dump(mode="json", by_alias=True)` would give it, in one pass."""
    return to_json(value, by_alias=True).decode()


def _create_sqlite_engine(url: URL, engine_options: dict[str, Any]) -> Engine:
    in_memory = _is_sqlite_memory(url)
    options: dict[str, Any] = {"connect_args": {"check_same_thread": False}}
    if in_memory:
        options["poolclass"] = StaticPool
    options.update(engine_options)
    engine = create_engine(url, **options)

    @event.listens_for(engine, "connect")
    def _configure_sqlite(dbapi_connection: Any, _record: Any) -> None:
        # Take transaction control away from the driver so `_begin_immediately` decides.
        dbapi_connection.isolation_level = None
        cursor = dbapi_connection.cursor()
        try:
            cursor.execute("PRAGMA foreign_keys=ON")
            cursor.execute(f"PRAGMA busy_timeout={SQLITE_BUSY_TIMEOUT_MS}")
            if not in_memory:
                cursor.execute("PRAGMA journal_mode=WAL")
                # In WAL mode NORMAL still survives a killed process (the WAL is on disk
                # before a commit returns); only an OS crash can lose the last commits.
                cursor.execute("PRAGMA synchronous=NORMAL")
        finally:
            cursor.close()

    @event.listens_for(engine, "begin")
    def _begin_immediately(connection: Connection) -> None:
        # Every transaction takes the write lock up front: a read-then-write transaction that
        # began deferred would fail outright (not wait) if another writer committed in between.
        connection.exec_driver_sql("BEGIN IMMEDIATE")

    return engine


def alembic_config(url: str | None = None) -> Config:
    """An Alembic configuration pointing at this repository's `migrations/` directory.

    Args:
        url: the database to migrate; None lets `migrations/env.py` read the environment.

    Returns:
        A `Config` usable with `alembic.command`.
    """
    config = Config()
    config.set_main_option("script_location", str(MIGRATIONS_DIRECTORY))
    if url is not None:
        config.set_main_option("sqlalchemy.url", url.replace("%", "%%"))
    return config


def migrate(engine_or_url: Engine | str, revision: str = "head") -> None:
    """Run `alembic upgrade` to `revision` (default head) on a database.

    Args:
        engine_or_url: an engine to migrate through, or a URL to open one for.
        revision: the Alembic revision to upgrade to.

    Raises:
        Unavailable: the database could not be reached or the migration failed.
    """
    owns_engine = isinstance(engine_or_url, str)
    engine = create_engine_for(engine_or_url) if isinstance(engine_or_url, str) else engine_or_url
    try:
        with database_errors("migrating the database"), engine.begin() as connection:
            config = alembic_config()
            config.attributes["connection"] = connection
            command.upgrade(config, revision)
    finally:
        if owns_engine:
            engine.dispose()


@contextmanager
def startup_lock(engine: Engine) -> Iterator[None]:
    """Hold a database-wide lock while one process migrates and seeds (PostgreSQL: an advisory
    lock on a connection of its own), so replicas or workers starting together on one database
    take turns instead of racing to create the same tables and templates. SQLite: nothing (its
    writers already queue, and it serves one process).

    Raises:
        Unavailable: the lock could not be taken.
    """
    if engine.dialect.name != "postgresql":
        yield
        return
    with database_errors("waiting for other replicas' start-up"), engine.connect() as holder:
        holder.execute(text("SELECT pg_advisory_lock(:key)"), {"key": STARTUP_LOCK_KEY})
        holder.commit()
        try:
            yield
        finally:
            holder.execute(text("SELECT pg_advisory_unlock(:key)"), {"key": STARTUP_LOCK_KEY})
            holder.commit()


def make_session_factory(engine: Engine) -> sessionmaker[Session]:
    """A session factory whose objects stay readable after commit."""
    return sessionmaker(bind=engine, expire_on_commit=False)


@contextmanager
def database_errors(doing: str) -> Iterator[None]:
    """Turn any SQLAlchemy error raised inside the block into `Unavailable`.

    Args:
        doing: what was being attempted, for the error's detail (never the URL or credentials).

    Raises:
        Unavailable: the block raised a `SQLAlchemyError`.
    """
    try:
        yield
    except SQLAlchemyError as error:
        raise Unavailable(
            f"database error while {doing}: {type(error).__name__}", dependency="database"
        ) from error
