"""Monitor events across replicas: what a listener here hears of sessions driven elsewhere.

In: the database URL and a factory of the service, in the app's lifespan (`monitoring_for`).
Out: the app's `MonitorService`; on PostgreSQL also a `MonitorFanout`, which listens
(`app.store.notifications`) for the violations and refusals other replicas commit and hands
each to this process's listeners of that session (its `/events` websockets), then brings the
session's copy here up to date. With SQLite there is one process: the service publishes to its
own listeners and nothing else runs.
After the listening connection was lost and is back, each session watched here but driven
elsewhere is reloaded from the database, and its listeners get a `status` event if it halted
meanwhile, so a missed notification delays a watcher but never hides a halt from it.
Fails: never raises into the app: a delivery that cannot read the database is logged and
skipped. The fan-out decides nothing: verdicts come from the replica the runtime is attached
to and the durable log, so a lost connection can never make the monitor allow anything.
"""

from __future__ import annotations

import logging
import uuid
from collections.abc import AsyncIterator, Callable
from contextlib import asynccontextmanager

from app.domain.errors import SafeGateError
from app.services.monitoring import MonitorService
from app.store.notifications import MonitorEventListener, RemoteEvent, supports_notify

_log = logging.getLogger("safegate.monitoring")


class MonitorFanout:
    """Delivers other replicas' monitor events to this process's listeners."""

    def __init__(self, monitoring: MonitorService, database_url: str) -> None:
        if monitoring.origin is None:
            raise ValueError("a fanned-out MonitorService needs its replica id (origin)")
        self._monitoring = monitoring
        self._origin = monitoring.origin
        self.listener = MonitorEventListener(database_url, self._deliver, self._connected)
        self.delivered = 0

    async def start(self) -> None:
        """Start listening (waits for the first LISTEN, see `MonitorEventListener.start`)."""
        await self.listener.start()

    async def stop(self) -> None:
        """Stop listening."""
        await self.listener.stop()

    async def _deliver(self, remote: RemoteEvent) -> None:
        if remote.origin == self._origin:
            return  # this process told its own listeners when it answered
        live = self._monitoring.loaded(remote.session_id)
        if live is None or not live.subscribers:
            return  # nobody here listens to that session
        event = dict(remote.event)
        if remote.abridged and event.get("type") in ("violation", "halted"):
            try:
                event["violation"] = await self._monitoring.halt_violation(remote.session_id)
            except SafeGateError as error:
                _log.warning("could not read the halt of session %s for its listeners: %s",
                             remote.session_id, error.detail)
        live.publish(event)
        self.delivered += 1
        if not live.monitor.halted:
            await self._refresh(remote.session_id)

    async def _connected(self) -> None:
        """After each (re)connection: catch up on what may have been missed meanwhile."""
        for live in self._monitoring.watched_elsewhere():
            was_halted = live.monitor.halted
            if await self._refresh(live.id) and live.monitor.halted and not was_halted:
                live.publish(live.status_event())

    async def _refresh(self, session_id: str) -> bool:
        live = self._monitoring.loaded(session_id)
        if live is None:
            return False
        try:
            await self._monitoring.refresh(live)
        except SafeGateError as error:
            _log.warning("could not reload monitor session %s for its listeners: %s",
                         session_id, error.detail)
            return False
        return True


@asynccontextmanager
async def monitoring_for(
    url: str, build: Callable[[str | None], MonitorService],
) -> AsyncIterator[tuple[MonitorService, MonitorFanout | None]]:
    """The app's monitoring service for as long as the app runs, and with PostgreSQL the
    fan-out that carries its events to and from the other replicas on the same database.

    Args:
        url: the database URL (PostgreSQL fans out; SQLite has one process).
        build: makes the service, given this replica's origin id (None: no fan-out).
    """
    if not supports_notify(url):
        yield build(None), None
        return
    monitoring = build(uuid.uuid4().hex)
    fanout = MonitorFanout(monitoring, url)
    await fanout.start()
    try:
        yield monitoring, fanout
    finally:
        await fanout.stop()
