"""Stage 6, Runtime Monitoring: one session's monitor, stepped message by message.

In: a `CompiledContract`, the session's initial `WorldState`, then each runtime message
(`before`/`after`, see `messages.py`). Out: a `Verdict` per message, and the counters of the
paper's MonitorSummary.

Before an action: the observation (if any) is applied, the action is parsed against it, then the
aborts and the guards of that action type are evaluated, then (for a contract with a scope) the
action is checked against the task's scope: an action outside it is a `scope` violation. The monitor
cannot see ahead, so it allows picking up something outside the task (it may be moved aside) and
halts at the first action that uses it or puts it down in another room. After it: the action model
predicts the next state (`world.step`) and the observation, which is authoritative, corrects it;
then the aborts and the invariants are evaluated. Every condition is three-valued and fails closed,
for invariants too: Stage 5 treats an unknown fact as free and refuses a plan whose invariant some
value of it would break, so a runtime state where the invariant is unknown is one the verified plan
never promised; the violation names the unknown facts, so the runtime knows what to report.

The first violation halts the session, absorbingly: the monitor has no reset, and every later
message is answered `halted`. A malformed message is answered `error` (not allowed, not halted)
and changes nothing. `step` never raises.

Steps follow each other: after the first action, a `before` must carry the seq after the last
finished action, an `after` the seq of the running one. A message that does not follow is never
checked against a state the runtime may have moved past: it gets an `error` carrying `resync`
(the monitor's `last_seq` and `pending_seq`), and the runtime either goes on from there or sends
`sync`, its current state after its last finished action; the monitor checks the aborts and the
invariants in that state and goes on from it (allow), or halts. A monitor restored from a log it
could not reproduce is put in the same position (`require_sync`).
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from datetime import UTC, datetime
from typing import Any

from app.domain.errors import InvalidInput, PlanError
from app.domain.monitor.conditions import CompiledContract, Failure, first_failure
from app.domain.monitor.counters import MonitorCounters, MonitorSummary
from app.domain.monitor.messages import (
    MessageType,
    MonitorMessage,
    MonitorViolation,
    Verdict,
    decode_message,
    parse_message,
    seq_of,
)
from app.domain.scope_check import AsideTracker, Departure
from app.domain.world import Action, WorldState, apply_snapshot, parse_action, step

Clock = Callable[[], datetime]


class OutOfStep(InvalidInput):
    """A message that does not follow the monitor's last step: the runtime must resynchronise."""


def utc_clock() -> datetime:
    """The current time in UTC (the default clock of violations)."""
    return datetime.now(UTC)


@dataclass(frozen=True, slots=True)
class _Pending:
    """An action allowed by its `before` whose `after` has not arrived yet."""

    seq: int
    action: Action
    wire: Mapping[str, Any]


class Monitor:
    """The runtime monitor of one session."""

    __slots__ = ("_aborts_clear", "_aside", "_clock", "_last_seq", "_pending", "_sync_reason",
                 "_violation", "contract", "counters", "state")

    def __init__(
        self,
        contract: CompiledContract,
        state: WorldState,
        *,
        counters: MonitorCounters | None = None,
        violation: MonitorViolation | None = None,
        clock: Clock = utc_clock,
    ) -> None:
        """Start monitoring (or resume a halted session).

        Args:
            contract: the compiled contract to enforce.
            state: the state the task starts in.
            counters: counts carried over from a stored session, else zeros.
            violation: the stored violation of a session that is already halted.
            clock: the source of violation timestamps.
        """
        self.contract = contract
        self.state = state
        self.counters = counters if counters is not None else MonitorCounters()
        self._violation = violation
        self._pending: _Pending | None = None
        self._last_seq = -1
        self._clock = clock
        # The state the aborts were last found false in: states are immutable, so a `before`
        # that brings no observation need not evaluate them again.
        self._aborts_clear: WorldState | None = None
        self._aside = None if contract.scope is None else AsideTracker(contract.scope)
        self._sync_reason: str | None = None

    @property
    def halted(self) -> bool:
        """Whether a violation has halted the session (forever)."""
        return self._violation is not None

    @property
    def violation(self) -> MonitorViolation | None:
        """The violation that halted the session, if any."""
        return self._violation

    @property
    def pending_seq(self) -> int | None:
        """The seq of the allowed action still waiting for its `after`, if any."""
        return None if self._pending is None else self._pending.seq

    @property
    def last_seq(self) -> int | None:
        """The seq of the last action whose `after` was accepted, if any."""
        return None if self._last_seq < 0 else self._last_seq

    @property
    def sync_required(self) -> bool:
        """Whether only a `sync` is accepted until the runtime has sent its current state."""
        return self._sync_reason is not None

    def require_sync(self, reason: str) -> None:
        """Accept nothing but a `sync` from now on (e.g. the state could not be rebuilt)."""
        self._sync_reason = reason

    def resync(self) -> dict[str, Any]:
        """Where the monitor stands, for a runtime asked to resynchronise."""
        return {"last_seq": self.last_seq, "pending_seq": self.pending_seq}

    def summary(self) -> MonitorSummary:
        """The paper's MonitorSummary of this session so far."""
        violations = () if self._violation is None else (self._violation,)
        return self.counters.summary(self.contract, violations, halted=self.halted,
                                     last_seq=self.last_seq, pending_seq=self.pending_seq)

    def step(self, message: object) -> Verdict:
        """Check one runtime message.

        Args:
            message: the message as received: JSON text or bytes, or a decoded object.

        Returns:
            `allow`; `violation` (and the session halts); `halted` once halted; or `error` for
            a message that cannot be checked, which is never an allow.
        """
        self.counters.messages += 1
        try:
            decoded = decode_message(message)
        except InvalidInput as error:
            return self._refuse(None, error.detail)
        if self._violation is not None:
            self.counters.refused += 1
            return Verdict("halted", seq_of(decoded), self._violation, halted=True,
                           detail="the session is halted; no action is allowed")
        try:
            parsed = parse_message(decoded)
            if parsed.type == "sync":
                return self._sync(parsed)
            if self._sync_reason is not None:
                raise OutOfStep(f"{self._sync_reason}: send 'sync' with the current state")
            if parsed.type == "before":
                return self._before(parsed)
            return self._after(parsed)
        except OutOfStep as error:
            self.counters.errors += 1
            detail = error.detail if self._sync_reason is not None else (
                f"{error.detail}: resynchronise (go on from 'resync', or send 'sync' with the "
                f"current state)")
            return Verdict("error", seq_of(decoded), detail=detail,
                           extra={"resync": self.resync()})
        except InvalidInput as error:
            return self._refuse(seq_of(decoded), error.detail)
        except Exception as error:  # a monitor must answer, never crash
            return self._refuse(seq_of(decoded), f"message could not be checked: {error!r}")

    def _refuse(self, seq: int | None, detail: str) -> Verdict:
        if self._violation is not None:
            self.counters.refused += 1
            return Verdict("halted", seq, self._violation, halted=True, detail=detail)
        self.counters.errors += 1
        return Verdict("error", seq, detail=detail)

    def _observe(self, state: WorldState, message: MonitorMessage) -> WorldState:
        return state if message.state is None else apply_snapshot(state, message.state)

    def _before(self, message: MonitorMessage) -> Verdict:
        seq = message.seq
        pending = self._pending
        if pending is not None and pending.seq != seq:
            raise OutOfStep(f"seq {seq} does not follow: action {pending.seq} is still running "
                            f"(its 'after' was not received)", field="seq")
        if pending is None and self._last_seq >= 0 and seq != self._last_seq + 1:
            raise OutOfStep(f"seq {seq} does not follow the last finished action "
                            f"({self._last_seq})", field="seq")
        state = self._observe(self.state, message)
        assert message.action is not None  # parse_message requires it for `before`
        action = parse_action(message.action, step=seq, state=state)
        aborts, guards = self.contract.aborts, self.contract.guards_for(action.name)
        failure = None
        if state is not self._aborts_clear:
            failure = first_failure(aborts, state, None, must_be=False)
            self._aborts_clear = state if failure is None else None
        failure = failure or first_failure(guards, state, action.args, must_be=True)
        counters = self.counters
        counters.actions_checked += 1
        counters.aborts_checked += len(aborts)
        counters.guards_checked += len(guards)
        by_action = counters.actions_by_name
        by_action[action.name] = by_action.get(action.name, 0) + 1
        self.state = state
        if failure is not None:
            return self._halt(failure, action.to_wire(), seq, "before")
        departure = self._departure(action, state, seq)
        if departure is not None:
            return self._halt_scope(departure, action, seq)
        self._pending = _Pending(seq, action, message.action)
        return Verdict("allow", seq)

    def _after(self, message: MonitorMessage) -> Verdict:
        seq, pending = message.seq, self._pending
        if pending is None or pending.seq != seq:
            expected = "no action is running" if pending is None else f"expected {pending.seq}"
            raise OutOfStep(f"'after' for seq {seq} matches no allowed action ({expected})",
                            field="seq")
        action = pending.action
        if message.action is not None and message.action != pending.wire:
            reported = parse_action(message.action, step=seq, state=self.state)
            if (reported.name, reported.object, reported.target) != (
                    action.name, action.object, action.target):
                raise InvalidInput(f"'after' reports {reported.to_wire()} but seq {seq} was "
                                   f"allowed for {action.to_wire()}", field="action")
        try:
            predicted = step(self.state, action)
        except PlanError:
            predicted = self.state  # the observation alone must then tell what changed
        state = self._observe(predicted, message)
        failure = self._settle(state, seq)
        if failure is not None:
            return self._halt(failure, action.to_wire(), seq, "after")
        return Verdict("allow", seq)

    def _departure(self, action: Action, state: WorldState, seq: int) -> Departure | None:
        scope, aside = self.contract.scope, self._aside
        if scope is None or aside is None:
            return None
        return scope.departure(action, state, seq) or aside.observe(action, state, seq)

    def _halt_scope(self, departure: Departure, action: Action, seq: int) -> Verdict:
        self._violation = MonitorViolation(
            timestamp=self._clock(), action=action.to_wire(), kind="scope",
            condition_id=departure.condition_id, formula=departure.formula,
            description=departure.description, seq=seq, phase="before", quote=departure.quote)
        self._pending = None
        return Verdict("violation", seq, self._violation, halted=True)

    def _sync(self, message: MonitorMessage) -> Verdict:
        """The runtime's state after its last finished action `seq`: checked, then the state
        the session goes on from. An action still running here is finished if `seq` reaches
        it (its effects predicted, then corrected by the state), abandoned otherwise."""
        seq, pending = message.seq, self._pending
        if seq < self._last_seq:
            raise OutOfStep(f"'sync' for seq {seq} goes back before the last finished action "
                            f"({self._last_seq})", field="seq")
        state, action = self.state, None
        if pending is not None and seq >= pending.seq:
            action = pending.action
            with contextlib.suppress(PlanError):  # else the observation alone tells
                state = step(state, action)
        state = self._observe(state, message)
        failure = self._settle(state, seq)
        self._sync_reason = None
        if failure is not None:
            return self._halt(failure, {} if action is None else action.to_wire(), seq, "sync")
        return Verdict("allow", seq)

    def _settle(self, state: WorldState, seq: int) -> Failure | None:
        """Check the aborts and the invariants in the state an action (or a sync) left, and go
        on from that state as the last finished action `seq`; the first condition it breaks."""
        aborts, invariants = self.contract.aborts, self.contract.invariants
        failure = first_failure(aborts, state, None, must_be=False)
        self._aborts_clear = state if failure is None else None
        failure = failure or first_failure(invariants, state, None, must_be=True)
        counters = self.counters
        counters.states_checked += 1
        counters.aborts_checked += len(aborts)
        counters.invariants_checked += len(invariants)
        self.state, self._pending, self._last_seq = state, None, seq
        return failure

    def _halt(self, failure: Failure, action: Mapping[str, Any], seq: int,
              phase: MessageType) -> Verdict:
        condition = failure.compiled.condition
        self._violation = MonitorViolation(
            timestamp=self._clock(), action=action, kind=failure.compiled.kind,
            condition_id=condition.id, formula=condition.formula,
            description=_describe(failure), seq=seq, phase=phase,
            established=failure.established, unknown_facts=failure.unknown_facts,
        )
        self._pending = None
        return Verdict("violation", seq, self._violation, halted=True)


def _describe(failure: Failure) -> str:
    condition = failure.compiled.condition
    text = condition.description.rstrip(".")
    if failure.established:
        return f"{text}." if failure.compiled.kind != "abort" else f"abort condition: {text}."
    missing = ", ".join(failure.unknown_facts) or "facts it depends on"
    if failure.compiled.kind == "abort":
        return (f"could not establish that this abort condition is false: {text} "
                f"(the state does not determine {missing}).")
    return f"could not be established: {text} (the state does not determine {missing})."


def replay(monitor: Monitor, messages: Iterable[Mapping[str, Any]]) -> list[Verdict]:
    """Feed a session's logged messages again (to rebuild its state after a restart).

    Returns:
        The verdicts, one per message, to compare with the answers that were given.
    """
    return [monitor.step(message) for message in messages]
