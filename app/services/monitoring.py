"""The monitoring use case: open sessions, step them, persist halts, publish events, summarise.

In: a contract id (and optionally an initial state) to open a session; then each runtime message
of a session. Out: the session id; one JSON answer per message; events for `/events` listeners;
the MonitorSummary.

Persistence. A session row holds its contract, initial state, counters and halt. The halt is
written synchronously *before* the violation is answered or published; if that write fails the
session stays halted in memory, the violation is still answered (halting is the safe side) and
the write is retried at every flush. The per-message path writes nothing else: exchanges are kept
in memory and written as one `messages` event per flush (every `FLUSH_SECONDS` while a runtime is
connected, when `FLUSH_ENTRIES` pile up, and when the last connection closes), together with the
counters. After a restart a halted session comes back halted from its row; a running one is
rebuilt by replaying its logged messages through a fresh monitor, which also restores a pending
action. A hard crash may lose the last `FLUSH_SECONDS` of a running session's log (never a halt).
One process owns a session: run one worker (the embedded default), or route a session's traffic
to one worker.
Fails: `NotFound` (unknown contract or session), `Conflict` (exhausted contract), `FormulaError`
(a contract that cannot be monitored), `Unavailable` (database) from `open_session`/`session`.
"""

from __future__ import annotations

import asyncio
import json
import logging
import threading
from collections import OrderedDict
from typing import Any

import anyio.to_thread

from app.domain.contracts import Contract
from app.domain.errors import Conflict, InvalidInput, SafeGateError
from app.domain.models import InitialState
from app.domain.monitor import (
    CompiledContract,
    Monitor,
    MonitorCounters,
    MonitorSummary,
    MonitorViolation,
    decode_message,
    replay,
)
from app.domain.world import WorldState, state_from_request
from app.services.container import Services
from app.services.monitoring_sessions import (
    UNDECODABLE,
    LiveSession,
    Subscriber,
    replayable,
)
from app.store.records import ContractStatus, MonitorSessionRecord

FLUSH_SECONDS = 0.25
FLUSH_ENTRIES = 2048
# Large batches: each flush briefly competes with the event loop for the GIL, so fewer, larger
# writes keep the per-action tail low. The durability window is FLUSH_SECONDS either way.
COMPILED_CACHE = 256
_log = logging.getLogger("safegate.monitoring")


class MonitorService:
    """Every monitoring session of one app. The async methods run on the event loop; the
    blocking ones (`open_session`) in worker threads."""

    def __init__(self, services: Services) -> None:
        self._services = services
        self._repository = services.repository
        self._live: dict[str, LiveSession] = {}
        self._loading: dict[str, asyncio.Lock] = {}
        self._compiled: OrderedDict[str, CompiledContract] = OrderedDict()
        self._compiled_lock = threading.Lock()

    # Opening and loading sessions.
    def _compiled_contract(self, contract_id: str, body: dict[str, Any]) -> CompiledContract:
        with self._compiled_lock:  # called from worker threads
            compiled = self._compiled.get(contract_id)
        if compiled is None:
            compiled = CompiledContract(Contract.model_validate(body))
            with self._compiled_lock:
                self._compiled[contract_id] = compiled
                while len(self._compiled) > COMPILED_CACHE:
                    self._compiled.popitem(last=False)
        return compiled

    def _initial_world(self, request_id: str, initial: InitialState) -> WorldState:
        """The session's starting state; the task's user profile still describes its people."""
        request = self._repository.get_gate_record(request_id).request
        return state_from_request(request.model_copy(
            update={"scene": initial.scene, "robot": initial.robot}))

    def open_session(
        self, contract_id: str, initial_state: InitialState | None = None
    ) -> MonitorSessionRecord:
        """Open a session (blocking: call it from a worker thread).

        Args:
            contract_id: the contract to enforce.
            initial_state: where the task starts; default: the gate request's scene and robot.

        Returns:
            The stored session.

        Raises:
            NotFound: no such contract. Conflict: the contract is exhausted.
            FormulaError: a condition of the contract cannot be monitored.
        """
        stored = self._repository.get_contract(contract_id)
        if stored.status is ContractStatus.EXHAUSTED:
            raise Conflict(f"contract {contract_id!r} is exhausted: its task was rejected")
        self._compiled_contract(contract_id, stored.contract)
        if initial_state is None:
            request = self._repository.get_gate_record(stored.request_id).request
            initial_state = InitialState(scene=request.scene, robot=request.robot)
        return self._repository.create_monitor_session(
            MonitorSessionRecord(contract_id=contract_id, initial_state=initial_state))

    def _restore(self, session_id: str) -> LiveSession:
        """Rebuild a session from the database (blocking)."""
        record = self._repository.get_monitor_session(session_id)
        stored = self._repository.get_contract(record.contract_id)
        compiled = self._compiled_contract(record.contract_id, stored.contract)
        world = self._initial_world(stored.request_id, record.initial_state)
        if record.halted and record.halt_violation is not None:
            monitor = Monitor(compiled, world, counters=MonitorCounters.from_json(record.counters),
                              violation=MonitorViolation.from_wire(record.halt_violation))
            return LiveSession(session_id, record.contract_id, monitor)
        monitor = Monitor(compiled, world)
        for event in self._repository.list_monitor_events(session_id):
            if event.type == "messages":
                replay(monitor, replayable(list(event.payload.get("messages", []))))
        live = LiveSession(session_id, record.contract_id, monitor)
        if monitor.halted:  # only if the contract's meaning changed since; halting is safe
            live.halt_saved = False
        return live

    async def session(self, session_id: str) -> LiveSession:
        """The live session, loaded (or rebuilt after a restart) on first use.

        Raises:
            NotFound: no such session.
        """
        live = self._live.get(session_id)
        if live is not None:
            return live
        lock = self._loading.setdefault(session_id, asyncio.Lock())
        async with lock:
            live = self._live.get(session_id)
            if live is None:
                live = await anyio.to_thread.run_sync(self._restore, session_id)
                self._live[session_id] = live
                if not live.halt_saved:
                    await self._save_halt(live)
        self._loading.pop(session_id, None)
        return live

    async def summary(self, session_id: str) -> tuple[str, MonitorSummary]:
        """The session's contract id and MonitorSummary (from memory, else from the database).

        Raises:
            NotFound: no such session.
        """
        live = self._live.get(session_id)
        if live is None:
            live = await anyio.to_thread.run_sync(self._restore, session_id)
        return live.contract_id, live.monitor.summary()

    # Connections.
    async def attach(self, session_id: str) -> LiveSession:
        """A runtime connects: the session, counted as in use until `detach`."""
        live = await self.session(session_id)
        live.clients += 1
        return live

    async def detach(self, live: LiveSession) -> None:
        """A runtime disconnects: write what is pending; unload the session once unused."""
        live.clients -= 1
        await self.flush(live)
        if live.clients == 0 and not live.subscribers and not live.log and live.halt_saved:
            self._live.pop(live.id, None)

    def subscribe(self, live: LiveSession) -> Subscriber:
        """A listener joins; it first gets the session's status."""
        subscriber = Subscriber()
        subscriber.offer(live.status_event())
        live.subscribers.add(subscriber)
        return subscriber

    def unsubscribe(self, live: LiveSession, subscriber: Subscriber) -> None:
        """A listener leaves."""
        live.subscribers.discard(subscriber)
        if live.clients == 0 and not live.subscribers and not live.log and live.halt_saved:
            self._live.pop(live.id, None)

    # The per-message path.
    async def handle(self, live: LiveSession, raw: str | bytes | None) -> str:
        """Check one runtime message and return the answer to send (JSON text).

        A violation's halt is durable (or its write has failed and is being retried) before
        this returns; nothing else waits for the database.
        """
        try:
            message: object = decode_message(raw)
        except InvalidInput:
            message = raw if raw is not None else b""
        except RecursionError:
            # Nested past the JSON decoder's reach: give the monitor something it refuses
            # (an error, or "halted"), never the text to decode again.
            message = {UNDECODABLE: "the message is nested too deeply to decode"}
        verdict = live.monitor.step(message)
        live.record(message, verdict)
        if verdict.type == "violation":
            if verdict.violation is not None:
                self._services.metrics.monitor_halts.labels(verdict.violation.kind).inc()
            live.halt_saved = False
            await self._save_halt(live)
        event = live.event_for(verdict)
        if event is not None:
            live.publish(event)
        if len(live.log) >= FLUSH_ENTRIES and not live.flush_lock.locked():
            asyncio.get_running_loop().create_task(self.flush(live))
        return json.dumps(verdict.to_wire())

    async def _save_halt(self, live: LiveSession) -> None:
        violation = live.monitor.violation
        if violation is None:
            return
        counters, wire = live.monitor.counters.to_json(), violation.to_wire()
        try:
            await anyio.to_thread.run_sync(lambda: self._repository.update_monitor_session(
                live.id, counters=counters, halt_violation=wire))
            live.halt_saved = True
        except SafeGateError:
            _log.exception("could not persist the halt of monitor session %s; will retry",
                           live.id)

    async def flush(self, live: LiveSession) -> None:
        """Write the pending log entries and counters (and retry an unsaved halt).

        Writes run as tasks shielded from cancellation and each flush first waits for the
        previous one, so batches reach the log whole and in order even when a connection
        is torn down mid-write.
        """
        async with live.flush_lock:
            if live.writing is not None:
                await asyncio.shield(live.writing)
            if not live.halt_saved:
                await self._save_halt(live)
            if not live.log and not live.counters_dirty:
                return
            entries, live.log = live.log, []
            live.counters_dirty = False
            live.writing = asyncio.get_running_loop().create_task(
                self._write(live, entries, live.monitor.counters.to_json()))
            await asyncio.shield(live.writing)

    async def _write(self, live: LiveSession, entries: list[dict[str, Any]],
                     counters: dict[str, Any]) -> None:
        def write() -> None:
            # Counters first: if the append then fails, re-queueing duplicates nothing.
            self._repository.update_monitor_session(live.id, counters=counters)
            if entries:
                self._repository.append_monitor_event(live.id, "messages",
                                                      {"messages": entries})

        try:
            await anyio.to_thread.run_sync(write)
        except SafeGateError:
            _log.exception("could not write the log of monitor session %s", live.id)
            live.log[:0] = entries
            live.counters_dirty = True

    async def flush_periodically(self, live: LiveSession) -> None:
        """Flush every `FLUSH_SECONDS` until cancelled (one task per runtime connection)."""
        while True:
            await asyncio.sleep(FLUSH_SECONDS)
            if live.log or live.counters_dirty or not live.halt_saved:
                await self.flush(live)
