"""The client SDK's one exception tree.

SafeGateClientError
├── ApiError            SafeGate answered with an error status (carries the problem+json body)
├── SafeGateUnavailable SafeGate could not be reached (or stayed busy) through every retry
├── MonitorError        the monitor answered `error`: the message was not checked (not allowed)
│   └── MonitorResync   ... because it does not follow the session's last step: resynchronise
├── MonitorHalted       the monitor halted the session: a violation now, or an earlier one
└── MonitorConnectionError   the websocket could not be opened, or closed while waiting

A refused action (`MonitorError`, `MonitorHalted`) means: do not run it; so does any error at
all. No error of the SDK, nor any transport failure, is ever turned into an allowed action or an
authorized task.
"""

from __future__ import annotations

from typing import Any


class SafeGateClientError(Exception):
    """Root of every error the SDK raises on purpose."""


class ApiError(SafeGateClientError):
    """A non-2xx answer; `problem` is the RFC 9457 body (or the raw text as `detail`)."""

    def __init__(self, status: int, problem: dict[str, Any]) -> None:
        self.status = status
        self.problem = problem
        super().__init__(f"{status} {problem.get('title', '')}: {problem.get('detail', '')}")


class SafeGateUnavailable(SafeGateClientError):
    """The request never got an answer: connection failures or timeouts on every attempt.
    Nothing was decided; the robot must not act on it."""


class MonitorError(SafeGateClientError):
    """The monitor could not check a message (malformed, out of order...): not allowed."""

    def __init__(self, answer: dict[str, Any]) -> None:
        self.answer = answer
        super().__init__(str(answer.get("detail", "the monitor answered an error")))


class MonitorResync(MonitorError):
    """The message does not follow the session's last stored step. `last_seq` (the last
    finished action) and `pending_seq` (an allowed action awaiting its `after`) say where the
    monitor stands: go on from there, or send your current state with `MonitorClient.sync`."""

    def __init__(self, answer: dict[str, Any]) -> None:
        super().__init__(answer)
        position = answer.get("resync") or {}
        self.last_seq: int | None = position.get("last_seq")
        self.pending_seq: int | None = position.get("pending_seq")


class MonitorHalted(SafeGateClientError):
    """The session is halted; `violation` is the violation that halted it."""

    def __init__(self, answer: dict[str, Any]) -> None:
        self.answer = answer
        self.violation: dict[str, Any] = dict(answer.get("violation") or {})
        what = self.violation.get("condition_id", "unknown condition")
        super().__init__(f"session halted by {self.violation.get('kind', 'a')} {what}: "
                         f"{self.violation.get('description', '')}")


class MonitorConnectionError(SafeGateClientError):
    """The monitor websocket is not (or no longer) usable."""
