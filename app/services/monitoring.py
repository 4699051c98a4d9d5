"""The monitoring use case: open sessions, step them, persist halts, publish events, summarise.

In: a contract id (and optionally an initial state) to open a session; then each runtime message
of a session. Out: the session id; one JSON answer per message; events for `/events` listeners;
the MonitorSummary.

Persistence: a step is durable before it is answered. A session row holds its contract, initial
state, counters and halt; its event log holds every exchange (`messages` events). Each message
that changes the session (an `allow`, a `violation`) is written, with its halt, before its answer
is sent: a group commit (`monitoring_commits.py`) writes what all sessions recorded meanwhile in
one transaction. Refusals (`error`, `halted`) change nothing and are written with the next
commit. So after a crash, even a SIGKILL, a session rebuilt from the database (its logged messages
replayed through a fresh monitor, which also restores a pending action; a halted one from its
row) stands exactly where its last answer left it. A replay that does not give the answers the log
says were given (the contract's meaning or the monitor changed since) halts if it halts, and
otherwise asks the runtime to resynchronise rather than go on from a state nobody was told about.
If a commit fails, the answer is an `error` (never an allow) and the session is reloaded from the
database before its next message; a violation is answered anyway (halting is the safe side) and
its halt write retried. Counters are written with the halt, and a halted session's again when
its runtime disconnects or every `FLUSH_SECONDS` (a running session's are rebuilt by replay).
Messages whose seq does not follow the last durable step get an `error` asking the runtime to
resynchronise (`app/domain/monitor/`).
One process owns a session at a time: a second process that appended to it makes the first one's
next write fail (the event number is taken), so it reloads instead of answering from a stale state.
Replicas: a session kept in memory here only for listeners (no runtime attached here) is reloaded
from the database whenever a runtime attaches, a listener joins or its summary is read, so a
runtime that moves from a dead replica to this one goes on from the durable state. Violations
and refusals reach other replicas' listeners through the database (`monitoring_fanout.py`).
Fails: `NotFound` (unknown contract or session), `Conflict` (exhausted contract), `FormulaError`
(a contract that cannot be monitored), `Unavailable` (database) from `open_session`/`session`.
"""

from __future__ import annotations

import asyncio
import json
import logging
from typing import Any

import anyio.to_thread

from app.adapters.tracing import stages
from app.domain.errors import Conflict, InvalidInput, SafeGateError
from app.domain.models import InitialState
from app.domain.monitor import MonitorSummary, Verdict, decode_message
from app.metrics import Metrics
from app.services.input_limits import MODEL_CAPS, InputLimits
from app.services.monitoring_commits import StepCommitter
from app.services.monitoring_loader import SessionLoader
from app.services.monitoring_sessions import UNDECODABLE, LiveSession, Subscriber
from app.store.records import ContractStatus, MonitorSessionRecord
from app.store.repository import AuditRepository, ContractRepository, MonitorRepository

FLUSH_SECONDS = 0.25
_log = logging.getLogger("safegate.monitoring")


class MonitorService:
    """Every monitoring session of one app. The async methods run on the event loop; the
    blocking ones (`open_session`) in worker threads."""

    def __init__(self, *, monitoring: MonitorRepository, contracts: ContractRepository,
                 audit: AuditRepository, metrics: Metrics, origin: str | None = None,
                 limits: InputLimits = MODEL_CAPS) -> None:
        """Args:
            monitoring: the sessions and their event logs.
            contracts: the contracts sessions enforce.
            audit: the gate records whose scene and robot a session starts from by default.
            metrics: where open sessions and halts are counted.
            origin: this replica's id when events fan out to other replicas through the
                database (PostgreSQL); None when this process is the only one (SQLite).
            limits: the most items a list of a session's initial scene may have.
        """
        self._limits = limits
        self._monitoring = monitoring
        self._contracts = contracts
        self._audit = audit
        self._metrics = metrics
        self._live: dict[str, LiveSession] = {}
        self._loading: dict[str, asyncio.Lock] = {}
        self._loader = SessionLoader(monitoring=monitoring, contracts=contracts, audit=audit)
        self._commits = StepCommitter(monitoring, origin=origin)
        self.origin = origin
        self._open_gauge = metrics.monitor_sessions_open

    # Opening and loading sessions.
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
        self._limits.check_initial_state(initial_state)
        stored = self._contracts.get_contract(contract_id)
        if stored.status is ContractStatus.EXHAUSTED:
            raise Conflict(f"contract {contract_id!r} is exhausted: its task was rejected")
        self._loader.compiled(contract_id, stored.contract)
        if initial_state is None:
            request = self._audit.get_gate_record(stored.request_id).request
            initial_state = InitialState(scene=request.scene, robot=request.robot)
        return self._monitoring.create_monitor_session(
            MonitorSessionRecord(contract_id=contract_id, initial_state=initial_state))

    async def session(self, session_id: str) -> LiveSession:
        """The live session, loaded (or rebuilt after a restart) on first use; a session loaded
        here that no runtime here drives is first brought up to what the database holds (a
        runtime on another replica, or before a crash, may have moved it on).

        Raises:
            NotFound: no such session. Unavailable: the database could not be read.
        """
        live = self._live.get(session_id)
        if live is not None:
            await self.refresh(live)
            return live
        lock = self._loading.setdefault(session_id, asyncio.Lock())
        async with lock:
            live = self._live.get(session_id)
            if live is None:
                live = await anyio.to_thread.run_sync(self._loader.restore, session_id)
                self._live[session_id] = live
                if not live.halt_saved:
                    await self._commits.durable(live)
        self._loading.pop(session_id, None)
        return live

    def loaded(self, session_id: str) -> LiveSession | None:
        """The session if this process has it in memory (for the fan-out), else None."""
        return self._live.get(session_id)

    async def refresh(self, live: LiveSession) -> None:
        """Put a session that no runtime drives here back where the database has it.

        A session this process drives (a runtime attached, or writes pending) is left alone:
        its memory is the newest state, and a second writer elsewhere makes its next write
        fail, which reloads it. Anything else may be stale: it is replaced in place, so its
        listeners stay subscribed.

        Raises:
            NotFound: no such session. Unavailable: the database could not be read.
        """
        async with live.reload_lock:
            if live.driven or live.broken:
                return
            restored = await anyio.to_thread.run_sync(self._loader.restore, live.id)
            if live.driven or live.broken:  # a runtime attached meanwhile: its state wins
                return
            live.monitor, live.next_event = restored.monitor, restored.next_event
            live.halt_saved = restored.halt_saved
            if not live.halt_saved:
                await self._commits.durable(live)

    async def halt_violation(self, session_id: str) -> dict[str, Any] | None:
        """The stored violation that halted a session (for an abridged remote event)."""
        return await anyio.to_thread.run_sync(self._loader.halt_violation, session_id)

    def watched_elsewhere(self) -> list[LiveSession]:
        """Sessions with listeners here that no runtime here drives (the fan-out's concern)."""
        return [live for live in self._live.values() if live.subscribers and not live.driven]

    async def summary(self, session_id: str) -> tuple[str, MonitorSummary]:
        """The session's contract id and MonitorSummary: from memory when a runtime here drives
        it, else from the database (another replica may be driving it).

        Raises:
            NotFound: no such session.
        """
        live = self._live.get(session_id)
        if live is not None and not live.broken and not live.driven:
            # A runtime that just disconnected may still have refusals being written: what
            # this process answered is in the database before the summary is read from it.
            await self._commits.durable(live)
        if live is None or live.broken or not live.driven:
            live = await anyio.to_thread.run_sync(self._loader.restore, session_id)
        return live.contract_id, live.monitor.summary()

    # Connections.
    async def attach(self, session_id: str) -> LiveSession:
        """A runtime connects: the session, counted as in use until `detach`."""
        live = await self.session(session_id)
        if live.clients == 0:
            self._open_gauge.inc()
        live.clients += 1
        return live

    async def detach(self, live: LiveSession) -> None:
        """A runtime disconnects: write what is pending; unload the session once unused."""
        live.clients -= 1
        if live.clients == 0:
            self._open_gauge.dec()
        await self.flush(live)
        self._unload_if_unused(live)

    def _unload_if_unused(self, live: LiveSession) -> None:
        if (live.clients == 0 and not live.subscribers and live.halt_saved
                and (live.broken or (not live.log and not live.waiters))
                and self._live.get(live.id) is live):
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
        self._unload_if_unused(live)

    # The per-message path.
    async def handle(self, live: LiveSession, raw: str | bytes | None) -> str:
        """Check one runtime message and return the answer to send (JSON text).

        An `allow` or a `violation` is returned only once the step (and its halt) is
        committed; if the commit fails, an allow becomes an `error` and the session is reloaded
        from the database before the next message. Refusals wait for nothing.
        """
        if live.broken:
            try:
                await self._reload(live)
            except SafeGateError as error:
                return json.dumps(_not_checked(raw, f"{error.detail}; the message was not "
                                                    f"checked: send it again").to_wire())
        try:
            message: object = decode_message(raw)
        except InvalidInput:
            message = raw if raw is not None else b""
        except RecursionError:
            # Nested past the JSON decoder's reach: give the monitor something it refuses
            # (an error, or "halted"), never the text to decode again.
            message = {UNDECODABLE: "the message is nested too deeply to decode"}
        with stages.stage("safegate.stage6.monitor_check",
                          **{"safegate.session_id": live.id}) as found:
            verdict = live.monitor.step(message)
            found["safegate.verdict"] = verdict.type
        live.record(message, verdict)
        # Other replicas' listeners hear of a violation or refusal with the commit that
        # stores it (`StepCommitter`); this process's listeners once it is answered.
        event = live.event_for(verdict)
        if event is not None:
            live.outbox.append(event)
        if verdict.type in ("allow", "violation"):
            if verdict.type == "violation":
                if verdict.violation is not None:
                    self._metrics.monitor_halts.labels(verdict.violation.kind).inc()
                live.halt_saved = False
            if not await self._commits.durable(live) and verdict.type == "allow":
                verdict = Verdict("error", verdict.seq, detail=(
                    "the step could not be stored, so it is not allowed: send the same message "
                    "again (the session goes on from its last stored step)"))
        if event is not None:
            live.publish(event)
        return json.dumps(verdict.to_wire())

    async def _reload(self, live: LiveSession) -> None:
        """Put a broken session back where the database has it (after a failed write).

        Raises:
            Unavailable: the database could not be read.
        """
        async with live.reload_lock:
            if not live.broken:
                return
            restored = await anyio.to_thread.run_sync(self._loader.restore, live.id)
            live.monitor, live.next_event = restored.monitor, restored.next_event
            live.log, live.outbox, live.written = [], [], live.recorded
            live.counters_at, live.halt_saved = live.recorded, restored.halt_saved
            live.broken = False
            if not live.halt_saved:
                await self._commits.durable(live)

    async def flush(self, live: LiveSession) -> None:
        """Write what is pending: refusals not yet logged, an unsaved halt, and a halted
        session's counters (the refusals it counted since its halt)."""
        if live.broken:
            return
        if live.monitor.halted and live.counters_at != live.recorded:
            live.counters_dirty = True  # a running session's counters come back by replay
        if live.log or live.counters_dirty or not live.halt_saved:
            await self._commits.durable(live)

    async def flush_periodically(self, live: LiveSession) -> None:
        """Flush every `FLUSH_SECONDS` until cancelled (one task per runtime connection)."""
        while True:
            await asyncio.sleep(FLUSH_SECONDS)
            await self.flush(live)


def _not_checked(raw: object, detail: str) -> Verdict:
    """An error for a message the monitor could not look at (its seq echoed if readable)."""
    try:
        decoded = decode_message(raw)
    except (InvalidInput, RecursionError):
        decoded = None
    seq = decoded.get("seq") if isinstance(decoded, dict) else None
    return Verdict("error", seq if isinstance(seq, int) and not isinstance(seq, bool) else None,
                   detail=detail)
