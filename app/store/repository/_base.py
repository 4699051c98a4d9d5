"""The repository's plumbing: one transaction per call, with database errors made `Unavailable`.

In: an `Engine` or a `sessionmaker`. Out: `_transaction(doing)`, a context manager giving a
session inside a transaction that commits on success and rolls back on any exception, and
`_core_transaction(doing)`, the same with a bare Core connection for hot paths that only insert
(no ORM unit of work to set up and flush).
Fails: `Unavailable` for any SQLAlchemy error the caller did not translate itself.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from sqlalchemy import Connection, Engine, text
from sqlalchemy.orm import Session, sessionmaker

from app.store.db import database_errors, make_session_factory


class RepositoryBase:
    """Holds the session factory every query family shares."""

    def __init__(self, bind: Engine | sessionmaker[Session]) -> None:
        """Wrap an engine (a session factory is made for it) or an existing session factory.

        Args:
            bind: where sessions come from.
        """
        self._sessions = make_session_factory(bind) if isinstance(bind, Engine) else bind
        engine = self._sessions.kw.get("bind")
        if not isinstance(engine, Engine):
            raise TypeError("the session factory must be bound to an Engine")
        self._engine = engine

    @contextmanager
    def _transaction(self, doing: str) -> Iterator[Session]:
        with database_errors(doing), self._sessions.begin() as session:
            yield session

    @contextmanager
    def _core_transaction(self, doing: str) -> Iterator[Connection]:
        with database_errors(doing), self._engine.begin() as connection:
            yield connection

    def ping(self) -> None:
        """Check that the database answers a trivial query (for readiness probes).

        Raises:
            Unavailable: the database cannot be reached.
        """
        with self._transaction("pinging the database") as session:
            session.execute(text("SELECT 1"))
