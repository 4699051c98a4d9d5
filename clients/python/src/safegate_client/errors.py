"""The client SDK's one exception tree.

SafeGateClientError
├── ApiError            SafeGate answered with an error status (carries the problem+json body)
├── UnexpectedAnswer    a 2xx answer (or a monitor answer) that does not fit the wire models
├── SafeGateUnavailable SafeGate could not be reached (or stayed busy) through every retry
├── MonitorError        the monitor answered `error`: the message was not checked (not allowed)
│   └── MonitorResync   ... because it does not follow the session's last step: resynchronise
├── MonitorHalted       the monitor halted the session: a violation now, or an earlier one
└── MonitorConnectionError   the websocket could not be opened, or closed while waiting

A refused action (`MonitorError`, `MonitorHalted`) means: do not run it; so does any error at
all. No error of the SDK, nor any transport failure, nor an answer the SDK cannot read, is ever
turned into an allowed action or an authorized task.
"""

from __future__ import annotations

from typing import Any

from safegate_client.models.monitor import ErrorAnswer, HaltedAnswer, Violation, ViolationAnswer


class SafeGateClientError(Exception):
    """Root of every error the SDK raises on purpose."""


class ApiError(SafeGateClientError):
    """A non-2xx answer; `problem` is the RFC 9457 body (or the raw text as `detail`)."""

    def __init__(self, status: int, problem: dict[str, Any]) -> None:
        self.status = status
        self.problem = problem
        super().__init__(f"{status} {problem.get('title', '')}: {problem.get('detail', '')}")


class UnexpectedAnswer(SafeGateClientError):
    """An answer that is not what the wire format promises (not JSON, or not of the model's
    shape: e.g. a decision this SDK does not know). Nothing is decided by it."""


class SafeGateUnavailable(SafeGateClientError):
    """The request never got an answer: connection failures or timeouts on every attempt.
    Nothing was decided; the robot must not act on it."""


class MonitorError(SafeGateClientError):
    """The monitor could not check a message (malformed, out of order...): not allowed."""

    def __init__(self, answer: ErrorAnswer) -> None:
        self.answer = answer
        super().__init__(answer.detail)


class MonitorResync(MonitorError):
    """The message does not follow the session's last stored step. `last_seq` (the last
    finished action) and `pending_seq` (an allowed action awaiting its `after`) say where the
    monitor stands: go on from there, or send your current state with `MonitorClient.sync`."""

    def __init__(self, answer: ErrorAnswer) -> None:
        super().__init__(answer)
        self.last_seq: int | None = answer.resync.last_seq if answer.resync else None
        self.pending_seq: int | None = answer.resync.pending_seq if answer.resync else None


class MonitorHalted(SafeGateClientError):
    """The session is halted; `violation` is the violation that halted it (None only when the
    server did not say)."""

    def __init__(self, answer: ViolationAnswer | HaltedAnswer) -> None:
        self.answer = answer
        self.violation: Violation | None = answer.violation
        if self.violation is None:
            super().__init__(f"session halted: {getattr(answer, 'detail', None) or 'halted'}")
        else:
            super().__init__(f"session halted by {self.violation.kind} "
                             f"{self.violation.condition_id}: {self.violation.description}")


class MonitorConnectionError(SafeGateClientError):
    """The monitor websocket is not (or no longer) usable."""
