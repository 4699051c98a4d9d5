"""The in-memory side of a monitoring session: its monitor, its unwritten log, its subscribers.

In: a `Monitor` for a stored session. Out: `LiveSession`, which the monitoring service steps,
commits and publishes from, and `Subscriber`, one per `/events` listener (a bounded queue: a
listener too slow to keep up is cut off rather than allowed to slow the monitor down).
Fails: never; this module does no I/O.
"""

from __future__ import annotations

import asyncio
from dataclasses import dataclass, field
from typing import Any

from app.domain.monitor import Monitor, Verdict

SUBSCRIBER_QUEUE = 1024
MAX_LOGGED_TEXT = 500
UNDECODABLE = "undecodable"


class Subscriber:
    """One listener's queue of events; `None` in the queue means "you were dropped"."""

    def __init__(self, size: int = SUBSCRIBER_QUEUE) -> None:
        self.queue: asyncio.Queue[dict[str, Any] | None] = asyncio.Queue(maxsize=size)
        self.dropped = False

    def offer(self, event: dict[str, Any]) -> None:
        """Queue an event; on overflow, drop the listener (its queue is emptied for the notice)."""
        if self.dropped:
            return
        try:
            self.queue.put_nowait(event)
        except asyncio.QueueFull:
            self.dropped = True
            while not self.queue.empty():
                self.queue.get_nowait()
            self.queue.put_nowait(None)


@dataclass(eq=False)
class LiveSession:
    """A session loaded in this process.

    `log` holds entries not yet handed to a write; `recorded` counts every entry ever recorded
    and `written` those committed (so `written == recorded` when everything answered is durable);
    `waiters` are answers waiting for their entry to be committed. `next_event` is the number
    the next write gives its `messages` event. `halt_saved` is False only between a violation and
    the moment its halt is durable (or while a failed write awaits a retry); `counters_dirty`
    asks the next write to store the counters, `counters_at` is `recorded` when they last were.
    `broken`: a write failed, and the monitor may be ahead of the database; it is reloaded
    before the next message is checked. `outbox` holds the events for listeners on other
    replicas, sent with the commit that stores the entries they answer.
    """

    id: str
    contract_id: str
    monitor: Monitor
    next_event: int = 1
    log: list[dict[str, Any]] = field(default_factory=list)
    outbox: list[dict[str, Any]] = field(default_factory=list)
    recorded: int = 0
    written: int = 0
    waiters: list[tuple[int, asyncio.Future[bool]]] = field(default_factory=list)
    counters_dirty: bool = False
    counters_at: int = 0
    halt_saved: bool = True
    broken: bool = False
    reload_lock: asyncio.Lock = field(default_factory=asyncio.Lock)
    clients: int = 0
    subscribers: set[Subscriber] = field(default_factory=set)

    @property
    def driven(self) -> bool:
        """Whether this process drives the session: a runtime is attached here, or something
        it answered is not yet written (so its memory is ahead of the database)."""
        return bool(self.clients or self.log or self.waiters or not self.halt_saved)

    def record(self, message: object, verdict: Verdict) -> None:
        """Remember one exchange for the event log (and for replay after a restart)."""
        if isinstance(message, dict):
            logged: object = message
        else:
            text = message.decode("utf-8", "replace") if isinstance(message, bytes) else str(
                message)
            logged = {UNDECODABLE: text[:MAX_LOGGED_TEXT]}
        entry: dict[str, Any] = {"in": logged, "out": verdict.type}
        if verdict.detail is not None and verdict.type == "error":
            entry["detail"] = verdict.detail
        self.log.append(entry)
        self.recorded += 1

    def publish(self, event: dict[str, Any]) -> None:
        """Send an event to every listener."""
        for subscriber in list(self.subscribers):
            subscriber.offer(event)
            if subscriber.dropped:
                self.subscribers.discard(subscriber)

    def status_event(self) -> dict[str, Any]:
        """What a listener is told when it subscribes."""
        violation = self.monitor.violation
        return {
            "type": "status", "session_id": self.id, "halted": self.monitor.halted,
            "violation": None if violation is None else violation.to_wire(),
        }

    def event_for(self, verdict: Verdict) -> dict[str, Any] | None:
        """The event listeners get for a verdict: violations and refusals only."""
        if verdict.type not in ("violation", "halted"):
            return None
        return {"session_id": self.id, **verdict.to_wire()}


def replayable(entries: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The logged entries whose input can be fed to a fresh monitor again, to rebuild a
    session's state and counts (each with its `in` and the `out` it was answered)."""
    return [entry for entry in entries if isinstance(entry.get("in"), dict)]
