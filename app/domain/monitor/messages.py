"""The monitor's wire vocabulary: runtime messages in, verdicts and violations out.

In: one websocket message from a robot runtime, as text, bytes or an already decoded object
(`{"type": "before" | "after", "seq": 7, "action": {...}, "state": {...}}`, see
`shared/spec/plans-and-monitoring.md`; and `{"type": "sync", "seq": 7, "state": {...}}`, the
runtime's answer to a request to resynchronise, see the README's monitor protocol). Out: a
`MonitorMessage` (`parse_message`), and the answers: `Verdict` (allow, violation, error, halted)
with `to_wire()`, and `MonitorViolation`.
Fails: `parse_message` raises `InvalidInput` for anything that is not a well-formed message (not
JSON, not an object, an unknown type, a missing or non-integer seq, a state that does not fit
the initial-state shape, a `sync` without its scene and robot); the monitor turns that into an
`error` verdict.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass, field
from datetime import datetime
from typing import Any, Literal

from pydantic import ValidationError

from app.domain.errors import InvalidInput
from app.domain.models import InitialState

MessageType = Literal["before", "after", "sync"]
VerdictType = Literal["allow", "violation", "error", "halted"]
_MESSAGE_TYPES: dict[str, MessageType] = {"before": "before", "after": "after", "sync": "sync"}
MAX_MESSAGE_CHARS = 1_000_000


@dataclass(frozen=True, slots=True)
class MonitorMessage:
    """A validated runtime message. `state` is None when the message carries no observation."""

    type: MessageType
    seq: int
    action: Mapping[str, Any] | None
    state: InitialState | None


def decode_message(raw: object) -> object:
    """JSON text or bytes decoded; anything else returned as it is.

    Raises:
        InvalidInput: text that is not JSON, bytes that are not UTF-8, or an oversized message.
    """
    if isinstance(raw, bytes | bytearray):
        try:
            raw = bytes(raw).decode("utf-8")
        except UnicodeDecodeError as error:
            raise InvalidInput("message is not UTF-8 text") from error
    if isinstance(raw, str):
        if len(raw) > MAX_MESSAGE_CHARS:
            raise InvalidInput(f"message longer than {MAX_MESSAGE_CHARS} characters")
        try:
            return json.loads(raw)
        except ValueError as error:
            raise InvalidInput(f"message is not JSON: {error}") from error
    return raw


def seq_of(decoded: object) -> int | None:
    """The message's seq when it has a usable one (to echo in an error), else None."""
    if isinstance(decoded, Mapping):
        seq = decoded.get("seq")
        if isinstance(seq, int) and not isinstance(seq, bool):
            return seq
    return None


def parse_message(decoded: object) -> MonitorMessage:
    """Validate a decoded runtime message.

    Args:
        decoded: the JSON value the runtime sent.

    Returns:
        The message with its state validated against the initial-state shape.

    Raises:
        InvalidInput: the message does not fit the protocol.
    """
    if not isinstance(decoded, Mapping):
        raise InvalidInput("a message must be a JSON object")
    kind = decoded.get("type")
    message_type = _MESSAGE_TYPES.get(kind) if isinstance(kind, str) else None
    if message_type is None:
        raise InvalidInput(f"unknown message type {kind!r}: expected 'before', 'after' or "
                           f"'sync'", field="type")
    seq = seq_of(decoded)
    if seq is None or seq < 0:
        raise InvalidInput("'seq' must be a non-negative integer", field="seq")
    action = decoded.get("action")
    if action is not None and not isinstance(action, Mapping):
        raise InvalidInput("'action' must be an object", field="action")
    if kind == "before" and action is None:
        raise InvalidInput("a 'before' message must name its action", field="action")
    raw_state = decoded.get("state")
    state: InitialState | None = None
    if raw_state is not None:
        try:
            state = InitialState.model_validate(raw_state)
        except ValidationError as error:
            first = error.errors()[0]
            where = ".".join(str(part) for part in first.get("loc", ()))
            raise InvalidInput(f"'state' does not fit the scene/robot shape at {where or 'state'}:"
                               f" {first.get('msg', 'invalid')}", field=f"state.{where}"
                               ) from error
    if message_type == "sync" and (state is None or state.scene is None or state.robot is None):
        raise InvalidInput("a 'sync' message must carry the runtime's current state: both "
                           "'state.scene' and 'state.robot'", field="state")
    return MonitorMessage(message_type, seq, action, state)


_PHASES: dict[str, MessageType] = {"after": "after", "sync": "sync"}


@dataclass(frozen=True, slots=True)
class MonitorViolation:
    """The violation that halted a session (the paper's MonitorViolation)."""

    timestamp: datetime
    action: Mapping[str, Any]
    kind: str
    condition_id: str
    formula: str
    description: str
    seq: int
    phase: MessageType
    established: bool = True
    unknown_facts: tuple[str, ...] = ()
    quote: str | None = None
    """For a `scope` violation: the words of the command the action departs from."""

    def to_wire(self) -> dict[str, Any]:
        """The JSON shape of the spec, plus `seq`, `phase`, `established` and `unknown_facts`
        (and `quote` for a scope violation)."""
        wire = {
            "timestamp": self.timestamp.isoformat().replace("+00:00", "Z"),
            "action": dict(self.action), "kind": self.kind,
            "condition_id": self.condition_id, "formula": self.formula,
            "description": self.description, "seq": self.seq, "phase": self.phase,
            "established": self.established, "unknown_facts": list(self.unknown_facts),
        }
        if self.quote is not None:
            wire["quote"] = self.quote
        return wire

    @classmethod
    def from_wire(cls, wire: Mapping[str, Any]) -> MonitorViolation:
        """Rebuild a stored violation (e.g. after a restart)."""
        return cls(
            timestamp=datetime.fromisoformat(str(wire["timestamp"]).replace("Z", "+00:00")),
            action=dict(wire.get("action") or {}), kind=str(wire["kind"]),
            condition_id=str(wire["condition_id"]), formula=str(wire.get("formula", "")),
            description=str(wire.get("description", "")), seq=int(wire.get("seq", 0)),
            phase=_PHASES.get(str(wire.get("phase")), "before"),
            established=bool(wire.get("established", True)),
            unknown_facts=tuple(str(f) for f in wire.get("unknown_facts", ())),
            quote=None if wire.get("quote") is None else str(wire["quote"]),
        )


@dataclass(frozen=True, slots=True)
class Verdict:
    """The monitor's answer to one message; `allowed` only for `allow`."""

    type: VerdictType
    seq: int | None
    violation: MonitorViolation | None = None
    detail: str | None = None
    halted: bool = False
    extra: Mapping[str, Any] = field(default_factory=dict)

    @property
    def allowed(self) -> bool:
        """Whether the runtime may go on (the action may run, or its outcome is accepted)."""
        return self.type == "allow"

    def to_wire(self) -> dict[str, Any]:
        """The answer's JSON shape (`shared/spec/plans-and-monitoring.md`)."""
        wire: dict[str, Any] = {"type": self.type, "seq": self.seq}
        if self.type == "allow":
            return wire
        wire["halted"] = self.halted
        if self.detail is not None:
            wire["detail"] = self.detail
        if self.violation is not None:
            wire["violation"] = self.violation.to_wire()
        wire.update(self.extra)
        return wire

