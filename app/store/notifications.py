"""Monitor events across replicas: PostgreSQL LISTEN/NOTIFY on one channel.

In: the events a replica's monitoring sessions raise (violations that halt a session, refusals
of a halted one), encoded by `notify_payload` and sent with `pg_notify` inside the transaction
that stores them (`MonitorQueries.write_monitor_logs`), so PostgreSQL delivers a halt to the other
replicas exactly when it is committed, never one that was rolled back. Out: on every replica,
`MonitorEventListener` receives them on a dedicated psycopg connection (autocommit, `LISTEN`) and
hands each one (`RemoteEvent`) to a callback; after every (re)connection it calls `on_connected`,
since events sent while it was away are gone (NOTIFY is not stored): the caller re-reads what it
shows from the database then.
A payload longer than PostgreSQL's limit (8000 bytes) is sent abridged (no violation body); the
receiver reads the violation from the session's row.
SQLite has one process and no NOTIFY: nothing here is used there (`supports_notify`).
Fails: `MonitorEventListener` never raises to its caller: a lost connection is logged and
reconnected with a growing pause (at most `MAX_RECONNECT_SECONDS`), and a silent network loss is
found by a query every `PING_SECONDS` without a notification. Nothing here decides a verdict: a
listener that is down only delays what other replicas' watchers are told.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import logging
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from typing import Any

import psycopg
from sqlalchemy import make_url

CHANNEL = "safegate_monitor_events"
MAX_PAYLOAD_BYTES = 7900  # PostgreSQL refuses 8000 and more
PING_SECONDS = 5.0
MAX_RECONNECT_SECONDS = 5.0
CONNECT_TIMEOUT_SECONDS = 5
_log = logging.getLogger("safegate.notifications")


def supports_notify(database_url: str) -> bool:
    """Whether the database can fan events out to other processes (PostgreSQL only)."""
    return make_url(database_url).get_backend_name() == "postgresql"


def libpq_conninfo(database_url: str) -> str:
    """A SQLAlchemy URL (`postgresql+psycopg://...`) as the libpq URI psycopg connects with."""
    url = make_url(database_url).set(drivername="postgresql")
    return url.render_as_string(hide_password=False)


@dataclass(frozen=True, slots=True)
class RemoteEvent:
    """An event another replica (`origin`) raised for a session; `abridged` when the violation
    was left out to fit the payload limit."""

    origin: str
    session_id: str
    event: dict[str, Any]
    abridged: bool = False


def notify_payload(origin: str, session_id: str, event: dict[str, Any]) -> str:
    """The NOTIFY payload for one event (abridged to fit PostgreSQL's limit when needed)."""
    payload = json.dumps({"origin": origin, "session_id": session_id, "event": event},
                         separators=(",", ":"))
    if len(payload.encode()) <= MAX_PAYLOAD_BYTES:
        return payload
    short = {key: event[key] for key in ("type", "seq", "halted") if key in event}
    return json.dumps({"origin": origin, "session_id": session_id, "event": short,
                       "abridged": True}, separators=(",", ":"))


def parse_payload(payload: str) -> RemoteEvent | None:
    """A received payload, or None when it is not one of ours (logged, never raised)."""
    try:
        decoded = json.loads(payload)
        event = decoded["event"]
        origin, session_id = decoded["origin"], decoded["session_id"]
        if not (isinstance(event, dict) and isinstance(origin, str)
                and isinstance(session_id, str)):
            raise TypeError("wrong types")
    except (ValueError, KeyError, TypeError) as error:
        _log.warning("ignored a malformed notification on %s: %s", CHANNEL, error)
        return None
    return RemoteEvent(origin, session_id, event, bool(decoded.get("abridged", False)))


class MonitorEventListener:
    """LISTEN on `CHANNEL` for as long as it runs, reconnecting whenever the connection is lost.

    `on_event` gets every notification (its own replica's too: the caller filters by origin);
    `on_connected` runs after each successful LISTEN, the first one included. `connected` is
    set while LISTEN is in force, and tells a caller whether events may be missed right now.
    """

    def __init__(self, database_url: str, on_event: Callable[[RemoteEvent], Awaitable[None]],
                 on_connected: Callable[[], Awaitable[None]]) -> None:
        self._conninfo = libpq_conninfo(database_url)
        self._on_event = on_event
        self._on_connected = on_connected
        self._task: asyncio.Task[None] | None = None
        self.connected = asyncio.Event()
        self.connections = 0

    async def start(self, timeout: float = 10.0) -> None:
        """Start listening; wait (up to `timeout` s) for the first LISTEN, so a replica that
        serves has its fan-out in force (if the wait times out it keeps trying in the
        background: the database is down, and the app's own readiness shows it)."""
        self._task = asyncio.get_running_loop().create_task(self._run(), name=CHANNEL)
        with contextlib.suppress(TimeoutError):
            await asyncio.wait_for(self.connected.wait(), timeout)

    async def stop(self) -> None:
        """Stop listening and close the connection."""
        if self._task is None:
            return
        self._task.cancel()
        with contextlib.suppress(asyncio.CancelledError):
            await self._task
        self._task = None

    async def _run(self) -> None:
        pause = 0.1
        while True:
            connections_before = self.connections
            try:
                await self._listen()
            except asyncio.CancelledError:
                raise
            except Exception as error:  # any loss of the connection: reconnect
                self.connected.clear()
                if self.connections > connections_before:
                    pause = 0.1  # it was up: try again at once, then back off
                _log.warning("monitor event listener lost its connection (%s: %s); "
                             "reconnecting in %.1f s", type(error).__name__, error, pause)
            await asyncio.sleep(pause)
            pause = min(MAX_RECONNECT_SECONDS, pause * 2)

    async def _listen(self) -> None:
        connection = await psycopg.AsyncConnection.connect(
            self._conninfo, autocommit=True, connect_timeout=CONNECT_TIMEOUT_SECONDS,
            application_name="safegate-monitor-listener")
        async with connection:
            await connection.execute(f"LISTEN {CHANNEL}")
            self.connections += 1
            self.connected.set()
            _log.info("listening for monitor events on %s", CHANNEL)
            await self._on_connected()
            while True:
                async for notify in connection.notifies(timeout=PING_SECONDS):
                    received = parse_payload(notify.payload)
                    if received is not None:
                        try:
                            await self._on_event(received)
                        except Exception:  # one bad event must not stop the fan-out
                            _log.exception("could not deliver a monitor event")
                # Quiet for PING_SECONDS: make sure the connection is still there.
                await connection.execute("SELECT 1")
