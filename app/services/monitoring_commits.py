"""Group commit for monitoring sessions: a step is durable before its answer is sent.

In: `LiveSession`s with recorded, unwritten log entries (and a halt or counters to write).
Out: `durable(live)`, which returns once everything the session recorded so far is committed
(True) or its write failed (False). One writer task per event loop collects every session with
something to write, writes them all in one transaction on a dedicated thread (so a busy shared
thread pool never delays a monitor answer), and wakes their waiters; what was recorded meanwhile
goes in the next transaction. A sequential runtime pays one commit per message; many sessions
share each commit. With other replicas (PostgreSQL), each transaction also carries the events
its entries answered (violations, refusals) as notifications, delivered when it commits.

A failed write leaves a running session `broken`: the entries after its last durable one are
dropped (they were checked against a state that is not durable) and every waiter is told False,
so nothing is answered allow; the service reloads the session from the database before it checks
another message. A halted session is never reloaded (that would forget the halt): its entries and
halt are kept and retried at the next write. When several sessions share a failed transaction,
each is retried alone, so one session's failure (another writer took its event number) does not
fail the others.
Fails: never raises; failures are logged and reported through `durable`.
"""

from __future__ import annotations

import asyncio
import logging
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from typing import Any

from app.domain.errors import SafeGateError
from app.services.monitoring_sessions import LiveSession
from app.store.notifications import notify_payload
from app.store.repository import MonitorLogWrite, MonitorRepository

_log = logging.getLogger("safegate.monitoring")


@dataclass(slots=True)
class _Taken:
    """One session's part of a transaction, and how far it makes the session durable."""

    live: LiveSession
    write: MonitorLogWrite
    upto: int
    events: list[dict[str, Any]]


class StepCommitter:
    """The monitor's group commit (one per `MonitorService`)."""

    def __init__(self, repository: MonitorRepository, *, origin: str | None = None) -> None:
        """Args:
            repository: where steps are written.
            origin: this replica's id, when each commit also notifies the other replicas of
                the events it stores (PostgreSQL); None when there are none to tell.
        """
        self._repository = repository
        self._origin = origin
        self._executor = ThreadPoolExecutor(max_workers=1,
                                            thread_name_prefix="safegate-monitor-commit")
        self._dirty: dict[str, LiveSession] = {}
        self._loop: asyncio.AbstractEventLoop | None = None
        self._wake: asyncio.Event | None = None
        self._task: asyncio.Task[None] | None = None

    def _wake_writer(self) -> None:
        loop = asyncio.get_running_loop()
        if self._loop is not loop or self._task is None or self._task.done():
            self._loop, self._wake = loop, asyncio.Event()
            self._task = loop.create_task(self._run())
        assert self._wake is not None
        self._wake.set()

    async def durable(self, live: LiveSession) -> bool:
        """Wait until everything `live` recorded so far, its halt and (when asked) its counters
        are committed.

        Returns:
            True once written; False if the write failed (see the module's docstring).
        """
        if live.written >= live.recorded and live.halt_saved and not live.counters_dirty:
            return True
        waiter: asyncio.Future[bool] = asyncio.get_running_loop().create_future()
        live.waiters.append((live.recorded, waiter))
        self._dirty[live.id] = live
        self._wake_writer()
        return await waiter

    async def _run(self) -> None:
        assert self._wake is not None
        loop = asyncio.get_running_loop()
        while True:
            await self._wake.wait()
            self._wake.clear()
            while self._dirty:
                sessions = list(self._dirty.values())
                self._dirty.clear()
                taken = [self._take(live) for live in sessions]
                failed = await loop.run_in_executor(self._executor, self._write,
                                                    [t.write for t in taken])
                for item in taken:
                    self._settle(item, item.live.id not in failed)

    def _take(self, live: LiveSession) -> _Taken:
        """Move what `live` has to write into a write (on the loop, between two steps)."""
        entries, live.log = live.log, []
        events, live.outbox = live.outbox, []
        monitor = live.monitor
        halt = None
        if not live.halt_saved and monitor.violation is not None:
            halt = monitor.violation.to_wire()
        counters = None
        if halt is not None or live.counters_dirty:
            counters = monitor.counters.to_json()
            live.counters_dirty, live.counters_at = False, live.recorded
        notifications: tuple[str, ...] = ()
        if self._origin is not None:
            notifications = tuple(notify_payload(self._origin, live.id, event)
                                  for event in events)
        write = MonitorLogWrite(live.id, live.next_event, entries, counters, halt, notifications)
        if entries:
            live.next_event += 1
        return _Taken(live, write, live.recorded, events)

    def _write(self, writes: list[MonitorLogWrite]) -> set[str]:
        """Commit the writes (on the writer thread); returns the sessions whose write failed.
        Anything raised counts as a failure: a waiter is never left without an answer."""
        writes = [w for w in writes
                  if w.entries or w.counters is not None or w.halt_violation is not None]
        if not writes:
            return set()
        try:
            self._repository.write_monitor_logs(writes)
            return set()
        except Exception as error:  # any failure means: not durable
            if len(writes) == 1:
                _log_failure(writes[0], error)
                return {writes[0].session_id}
        failed = set()
        for write in writes:
            try:
                self._repository.write_monitor_logs([write])
            except Exception as error:
                _log_failure(write, error)
                failed.add(write.session_id)
        return failed

    @staticmethod
    def _settle(item: _Taken, ok: bool) -> None:
        live, write = item.live, item.write
        if ok:
            live.written = max(live.written, item.upto)
            if write.halt_violation is not None:
                live.halt_saved = True
            waiting = []
            for target, waiter in live.waiters:
                if target <= live.written:
                    if not waiter.done():
                        waiter.set_result(True)
                else:
                    waiting.append((target, waiter))
            live.waiters = waiting
            return
        if write.entries:
            live.next_event = write.event_seq  # the number was not used
        if write.counters is not None:
            live.counters_dirty = True
        if live.monitor.halted:
            live.log[:0] = write.entries  # kept for the next write, with the halt
            live.outbox[:0] = item.events
        else:
            live.broken = True
            live.log = []
            live.written = live.recorded
        for _, waiter in live.waiters:
            if not waiter.done():
                waiter.set_result(False)
        live.waiters = []


def _log_failure(write: MonitorLogWrite, error: Exception) -> None:
    if isinstance(error, SafeGateError):
        _log.error("could not write monitor session %s: %s", write.session_id, error.detail)
    else:
        _log.exception("could not write monitor session %s", write.session_id,
                       exc_info=error)
