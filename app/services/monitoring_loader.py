"""Loading monitoring sessions from the database: compiled contracts and replayed sessions.

In: a session id (or a contract id and its stored body). Out: `SessionLoader.restore`, a
`LiveSession` rebuilt from the database exactly where its last durable answer left it (its
logged messages replayed through a fresh monitor, which also restores a pending action; a halted
one from its row), and `SessionLoader.compiled`, contracts compiled once and kept in a small
cache. A replay that does not give the answers the log says were given (the contract's meaning
or the monitor changed since) halts if it halts, and otherwise asks the runtime to resynchronise
rather than go on from a state nobody was told about.
Blocking: call `restore` from a worker thread.
Fails: `NotFound` (unknown session or contract), `Unavailable` (database), `FormulaError` (a
contract that cannot be monitored).
"""

from __future__ import annotations

import logging
import threading
from collections import OrderedDict
from typing import Any

from app.domain.contracts import Contract
from app.domain.models import InitialState
from app.domain.monitor import (
    CompiledContract,
    Monitor,
    MonitorCounters,
    MonitorViolation,
    replay,
)
from app.domain.world import WorldState, state_from_request
from app.services.monitoring_sessions import LiveSession, replayable
from app.store.repository import AuditRepository, ContractRepository, MonitorRepository

COMPILED_CACHE = 256
_log = logging.getLogger("safegate.monitoring")


class SessionLoader:
    """Rebuilds sessions from the database; safe to call from several threads."""

    def __init__(self, *, monitoring: MonitorRepository, contracts: ContractRepository,
                 audit: AuditRepository) -> None:
        self._monitoring = monitoring
        self._contracts = contracts
        self._audit = audit
        self._compiled: OrderedDict[str, CompiledContract] = OrderedDict()
        self._compiled_lock = threading.Lock()

    def compiled(self, contract_id: str, body: dict[str, Any]) -> CompiledContract:
        """The contract compiled for monitoring (cached by id; a contract never changes).

        Raises:
            FormulaError: a condition cannot be monitored.
        """
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
        request = self._audit.get_gate_record(request_id).request
        return state_from_request(request.model_copy(
            update={"scene": initial.scene, "robot": initial.robot}))

    def restore(self, session_id: str) -> LiveSession:
        """Rebuild a session from the database (blocking).

        Returns:
            The session as its last durable answer left it; `halt_saved` is False only when
            the replay halted it without a stored halt (the caller writes it).

        Raises:
            NotFound: no such session. Unavailable: the database could not be read.
        """
        record = self._monitoring.get_monitor_session(session_id)
        stored = self._contracts.get_contract(record.contract_id)
        compiled = self.compiled(record.contract_id, stored.contract)
        world = self._initial_world(stored.request_id, record.initial_state)
        if record.halted and record.halt_violation is not None:
            monitor = Monitor(compiled, world, counters=MonitorCounters.from_json(record.counters),
                              violation=MonitorViolation.from_wire(record.halt_violation))
            return LiveSession(session_id, record.contract_id, monitor,
                               next_event=self._monitoring.last_monitor_event_seq(session_id) + 1)
        monitor = Monitor(compiled, world)
        last_event, diverged = 0, 0
        for event in self._monitoring.list_monitor_events(session_id):
            last_event = event.seq
            if event.type != "messages":
                continue
            entries = replayable(list(event.payload.get("messages", [])))
            verdicts = replay(monitor, [entry["in"] for entry in entries])
            diverged += sum(verdict.type != entry.get("out")
                            for entry, verdict in zip(entries, verdicts, strict=True))
        live = LiveSession(session_id, record.contract_id, monitor, next_event=last_event + 1)
        if monitor.halted:  # only if the contract's meaning changed since; halting is safe
            live.halt_saved = False
        elif diverged:
            _log.warning("monitor session %s: %d logged answers differ when replayed; asking "
                         "its runtime to resynchronise", session_id, diverged)
            monitor.require_sync("this session's state could not be rebuilt exactly after a "
                                 "restart")
        return live

    def halt_violation(self, session_id: str) -> dict[str, Any] | None:
        """The stored violation that halted a session, if any (blocking)."""
        return self._monitoring.get_monitor_session(session_id).halt_violation
