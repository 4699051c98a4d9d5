"""Queries on runtime monitoring sessions and their event logs.

In: `MonitorSessionRecord` values, counters, violations and event payloads (JSON objects).
Out: the stored records. Halting is absorbing: the first halt violation is kept, a later one is
ignored, and nothing sets `halted` back to false. Event numbers are assigned here, 1, 2, 3... per
session, with a retry when two writers race for the same number; except in `write_monitor_logs`,
the monitor's group commit, whose caller numbers the events itself (a number another writer took
fails the whole write, which the caller treats as a lost race and reloads).
Fails: `NotFound` for unknown ids, `Unavailable` for database errors.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from sqlalchemy import func, insert, select, text, update
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.domain.errors import NotFound, Unavailable
from app.domain.models import InitialState
from app.store.notifications import CHANNEL
from app.store.records import MonitorEventRecord, MonitorSessionRecord
from app.store.repository._base import RepositoryBase
from app.store.tables import ContractRow, MonitorEventRow, MonitorSessionRow, new_id, utc_now

APPEND_RETRIES = 5
_NOTIFY = text("SELECT pg_notify(:channel, :payload)")


@dataclass(frozen=True, slots=True)
class MonitorLogWrite:
    """What one session adds in one group commit: a `messages` event numbered `event_seq`
    holding `entries` (none when `entries` is empty), its counters, its halt, and the
    notifications (`app.store.notifications` payloads) other replicas get when it commits."""

    session_id: str
    event_seq: int
    entries: list[dict[str, Any]]
    counters: dict[str, Any] | None = None
    halt_violation: dict[str, Any] | None = None
    notifications: tuple[str, ...] = ()


def _to_session(row: MonitorSessionRow) -> MonitorSessionRecord:
    return MonitorSessionRecord(
        id=row.id,
        contract_id=row.contract_id,
        initial_state=InitialState.model_validate(row.initial_state),
        halted=row.halted,
        halt_violation=dict(row.halt_violation) if row.halt_violation is not None else None,
        counters=dict(row.counters),
        created_at=row.created_at,
        updated_at=row.updated_at,
    )


def _to_event(row: MonitorEventRow) -> MonitorEventRecord:
    return MonitorEventRecord(
        session_id=row.session_id,
        seq=row.seq,
        type=row.type,
        payload=dict(row.payload),
        created_at=row.created_at,
    )


def _session_row(session: Session, session_id: str) -> MonitorSessionRow:
    row = session.get(MonitorSessionRow, session_id)
    if row is None:
        raise NotFound(f"no monitor session {session_id!r}")
    return row


class MonitorQueries(RepositoryBase):
    """Monitoring sessions and their events."""

    def create_monitor_session(self, record: MonitorSessionRecord) -> MonitorSessionRecord:
        """Open a monitoring session for a contract.

        Raises:
            NotFound: the contract does not exist.
        """
        with self._transaction("creating a monitor session") as session:
            if session.get(ContractRow, record.contract_id) is None:
                raise NotFound(f"no contract {record.contract_id!r}")
            now = utc_now()
            row = MonitorSessionRow(
                id=record.id or new_id(),
                contract_id=record.contract_id,
                initial_state=record.initial_state.model_dump(mode="json", by_alias=True),
                halted=record.halted,
                halt_violation=record.halt_violation,
                counters=dict(record.counters),
                created_at=record.created_at or now,
                updated_at=record.updated_at or now,
            )
            session.add(row)
            session.flush()
            return _to_session(row)

    def get_monitor_session(self, session_id: str) -> MonitorSessionRecord:
        """One monitoring session by id.

        Raises:
            NotFound: no such session.
        """
        with self._transaction("reading a monitor session") as session:
            return _to_session(_session_row(session, session_id))

    def update_monitor_session(
        self,
        session_id: str,
        *,
        counters: dict[str, Any] | None = None,
        halt_violation: dict[str, Any] | None = None,
    ) -> MonitorSessionRecord:
        """Replace a session's counters and/or halt it.

        Args:
            session_id: the session.
            counters: the new counters, or None to keep them.
            halt_violation: the violation that halts the session; ignored when it is already
                halted, so the first violation is the one remembered.

        Returns:
            The session as stored afterwards.

        Raises:
            NotFound: no such session.
        """
        with self._transaction("updating a monitor session") as session:
            _session_row(session, session_id)
            changes: dict[str, Any] = {"updated_at": utc_now()}
            if counters is not None:
                changes["counters"] = dict(counters)
            session.execute(
                update(MonitorSessionRow)
                .where(MonitorSessionRow.id == session_id)
                .values(**changes)
                .execution_options(synchronize_session=False)
            )
            if halt_violation is not None:
                # Conditional on not halted yet, so concurrent halts keep the first violation.
                session.execute(
                    update(MonitorSessionRow)
                    .where(MonitorSessionRow.id == session_id)
                    .where(MonitorSessionRow.halted.is_(False))
                    .values(halted=True, halt_violation=dict(halt_violation))
                    .execution_options(synchronize_session=False)
                )
            row = _session_row(session, session_id)
            session.refresh(row)
            return _to_session(row)

    def append_monitor_event(
        self, session_id: str, event_type: str, payload: dict[str, Any]
    ) -> MonitorEventRecord:
        """Append one event to a session's log with the next sequence number.

        Raises:
            NotFound: no such session.
            Unavailable: database error, or the sequence kept colliding with other writers.
        """
        for _ in range(APPEND_RETRIES):
            try:
                with self._transaction("appending a monitor event") as session:
                    # Locking the session row queues concurrent appenders on PostgreSQL.
                    if session.get(MonitorSessionRow, session_id, with_for_update=True) is None:
                        raise NotFound(f"no monitor session {session_id!r}")
                    last = session.scalar(
                        select(func.max(MonitorEventRow.seq)).where(
                            MonitorEventRow.session_id == session_id
                        )
                    )
                    row = MonitorEventRow(
                        session_id=session_id,
                        seq=(last or 0) + 1,
                        type=event_type,
                        payload=dict(payload),
                        created_at=utc_now(),
                    )
                    session.add(row)
                    session.flush()
                    return _to_event(row)
            except Unavailable as error:
                if not isinstance(error.__cause__, IntegrityError):
                    raise
        raise Unavailable(f"could not number an event of monitor session {session_id!r}")

    def list_monitor_events(
        self, session_id: str, *, after_seq: int = 0, limit: int | None = None
    ) -> list[MonitorEventRecord]:
        """A session's events with `seq > after_seq`, in order (empty for an unknown session)."""
        query = (
            select(MonitorEventRow)
            .where(MonitorEventRow.session_id == session_id)
            .where(MonitorEventRow.seq > after_seq)
            .order_by(MonitorEventRow.seq)
        )
        if limit is not None:
            query = query.limit(limit)
        with self._transaction("listing monitor events") as session:
            return [_to_event(row) for row in session.scalars(query).all()]

    def write_monitor_logs(self, writes: Sequence[MonitorLogWrite]) -> None:
        """Write several sessions' steps in one transaction (the monitor's group commit).

        Each write appends its entries as one `messages` event numbered `event_seq`, replaces the
        session's counters when given, and halts it when a violation is given (the first halt
        is kept, as in `update_monitor_session`). All or nothing. On PostgreSQL each write's
        notifications are sent with `pg_notify` in the same transaction, so the other replicas
        hear of a halt when, and only if, it is committed (SQLite has no other process to tell).

        Raises:
            Unavailable: database error, including an event number already taken (another
                writer appended to the session) or an unknown session.
        """
        now = utc_now()
        rows = [{"session_id": w.session_id, "seq": w.event_seq, "type": "messages",
                 "payload": {"messages": w.entries}, "created_at": now}
                for w in writes if w.entries]
        with self._core_transaction("writing monitor steps") as connection:
            if rows:
                connection.execute(insert(MonitorEventRow), rows)
            for w in writes:
                if w.counters is not None:
                    connection.execute(
                        update(MonitorSessionRow).where(MonitorSessionRow.id == w.session_id)
                        .values(counters=w.counters, updated_at=now))
                if w.halt_violation is not None:
                    connection.execute(
                        update(MonitorSessionRow).where(MonitorSessionRow.id == w.session_id)
                        .where(MonitorSessionRow.halted.is_(False))
                        .values(halted=True, halt_violation=w.halt_violation, updated_at=now))
            if connection.dialect.name == "postgresql":
                for payload in (p for w in writes for p in w.notifications):
                    connection.execute(_NOTIFY, {"channel": CHANNEL, "payload": payload})

    def last_monitor_event_seq(self, session_id: str) -> int:
        """The number of a session's last event (0 when it has none)."""
        query = select(func.max(MonitorEventRow.seq)).where(
            MonitorEventRow.session_id == session_id)
        with self._core_transaction("reading a monitor session's last event") as connection:
            return int(connection.scalar(query) or 0)
