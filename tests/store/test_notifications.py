"""LISTEN/NOTIFY for monitor events on a real PostgreSQL (`app/store/notifications.py`).

A notification goes out with the commit that stores its step, and only then: a write that fails
(its event number already taken) tells nobody. The listener comes back after its connection is
killed server-side (`pg_terminate_backend`), says so through `on_connected` (so its caller can
catch up), and hears what is sent afterwards. Payloads too long for PostgreSQL are abridged.
"""

from __future__ import annotations

import asyncio
import json

import pytest
from sqlalchemy import create_engine, text

from app.domain.errors import Unavailable
from app.domain.models import InitialState
from app.store.notifications import (
    MAX_PAYLOAD_BYTES,
    MonitorEventListener,
    RemoteEvent,
    notify_payload,
    parse_payload,
    supports_notify,
)
from app.store.records import ContractRecord, MonitorSessionRecord
from app.store.repository import MonitorLogWrite, Repository

pytestmark = pytest.mark.postgres


@pytest.fixture
def database_url(postgres_url: str) -> str:
    """PostgreSQL only: SQLite has one process and no NOTIFY."""
    return postgres_url

VIOLATION = {"type": "violation", "seq": 3, "halted": True,
             "violation": {"condition_id": "c1", "description": "too fast"}}


def new_session(repository: Repository, contract: ContractRecord) -> str:
    assert contract.id is not None
    record = repository.create_monitor_session(MonitorSessionRecord(
        contract_id=contract.id, initial_state=InitialState()))
    assert record.id is not None
    return record.id


async def wait_for(predicate: object, seconds: float = 10.0) -> None:
    deadline = asyncio.get_running_loop().time() + seconds
    while not predicate():  # type: ignore[operator]
        if asyncio.get_running_loop().time() > deadline:
            raise TimeoutError("condition not reached")
        await asyncio.sleep(0.02)


class TestPayloads:
    def test_a_payload_round_trips(self) -> None:
        received = parse_payload(notify_payload("replica-a", "s1", VIOLATION))
        assert received == RemoteEvent("replica-a", "s1", VIOLATION, abridged=False)

    def test_a_payload_over_the_limit_is_abridged_to_what_fits(self) -> None:
        big = {**VIOLATION, "violation": {"description": "x" * 10_000}}
        payload = notify_payload("replica-a", "s1", big)
        assert len(payload.encode()) <= MAX_PAYLOAD_BYTES
        received = parse_payload(payload)
        assert received is not None and received.abridged
        assert received.event == {"type": "violation", "seq": 3, "halted": True}

    def test_a_foreign_payload_is_ignored(self) -> None:
        assert parse_payload("hello") is None
        assert parse_payload(json.dumps({"origin": 1, "session_id": "s", "event": {}})) is None

    def test_only_postgresql_fans_out(self) -> None:
        assert supports_notify("postgresql+psycopg://u@h/db")
        assert not supports_notify("sqlite:///./safegate.db")


class TestListener:
    def test_a_committed_step_notifies_and_a_failed_one_does_not(
        self, repository: Repository, saved_contract: ContractRecord, database_url: str
    ) -> None:
        session_id = new_session(repository, saved_contract)
        heard: list[RemoteEvent] = []

        async def scenario() -> None:
            async def on_event(event: RemoteEvent) -> None:
                heard.append(event)

            async def on_connected() -> None:
                return None

            listener = MonitorEventListener(database_url, on_event, on_connected)
            await listener.start()
            assert listener.connected.is_set()
            write = MonitorLogWrite(session_id, 1, [{"in": {}, "out": "violation"}],
                                    notifications=(notify_payload("a", session_id, VIOLATION),))
            await asyncio.to_thread(repository.write_monitor_logs, [write])
            await wait_for(lambda: len(heard) == 1)
            with pytest.raises(Unavailable):  # event 1 is taken: nothing is committed
                await asyncio.to_thread(repository.write_monitor_logs, [write])
            await asyncio.sleep(0.5)
            await listener.stop()

        asyncio.run(scenario())
        assert heard == [RemoteEvent("a", session_id, VIOLATION)]

    def test_the_listener_reconnects_after_its_connection_is_killed(
        self, repository: Repository, saved_contract: ContractRecord, database_url: str
    ) -> None:
        session_id = new_session(repository, saved_contract)
        heard: list[RemoteEvent] = []
        connected: list[int] = []
        engine = create_engine(database_url, isolation_level="AUTOCOMMIT")

        async def scenario() -> None:
            async def on_event(event: RemoteEvent) -> None:
                heard.append(event)

            async def on_connected() -> None:
                connected.append(len(connected) + 1)

            listener = MonitorEventListener(database_url, on_event, on_connected)
            await listener.start()
            with engine.connect() as admin:
                killed = admin.execute(text(
                    "SELECT count(pg_terminate_backend(pid)) FROM pg_stat_activity "
                    "WHERE application_name = 'safegate-monitor-listener' "
                    "AND datname = current_database()")).scalar()
            assert killed == 1
            await wait_for(lambda: listener.connections == 2)
            write = MonitorLogWrite(session_id, 1, [{"in": {}, "out": "violation"}],
                                    notifications=(notify_payload("a", session_id, VIOLATION),))
            await asyncio.to_thread(repository.write_monitor_logs, [write])
            await wait_for(lambda: len(heard) == 1)
            await listener.stop()

        try:
            asyncio.run(scenario())
        finally:
            engine.dispose()
        assert connected == [1, 2]
        assert heard[0].event == VIOLATION
