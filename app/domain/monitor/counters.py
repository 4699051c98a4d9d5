"""What a monitoring session has checked: the counters and the paper's MonitorSummary.

In: the counts a `Monitor` keeps as it steps, and its compiled contract. Out: `MonitorCounters`
(mutable, JSON round-trip with `to_json`/`from_json` for persistence) and `MonitorSummary`
(frozen): actions checked, guards checked (one per guard per action of its type), invariants
checked (one per invariant per state), aborts checked (one per abort per state, before and
after), every violation, whether halted, the per-condition breakdown, and the seq of the last
finished and of the running action (for a runtime that reconnects).
Fails: `from_json` ignores unknown keys and treats a missing or malformed count as zero.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import TYPE_CHECKING, Any

from app.domain.monitor.messages import MonitorViolation

if TYPE_CHECKING:
    from app.domain.monitor.conditions import CompiledContract

_COUNTS = ("messages", "actions_checked", "states_checked", "guards_checked",
           "invariants_checked", "aborts_checked", "errors", "refused")


@dataclass(slots=True)
class MonitorCounters:
    """Running counts of one session (`actions_by_name`: before-checks per canonical action)."""

    messages: int = 0
    actions_checked: int = 0
    states_checked: int = 0
    guards_checked: int = 0
    invariants_checked: int = 0
    aborts_checked: int = 0
    errors: int = 0
    refused: int = 0
    actions_by_name: dict[str, int] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """The counts as a JSON object."""
        out: dict[str, Any] = {name: getattr(self, name) for name in _COUNTS}
        out["actions_by_name"] = dict(self.actions_by_name)
        return out

    @classmethod
    def from_json(cls, data: Mapping[str, Any]) -> MonitorCounters:
        """Counts read back from `to_json`'s shape."""
        def count(value: object) -> int:
            return value if isinstance(value, int) and not isinstance(value, bool) else 0

        by_name = data.get("actions_by_name")
        return cls(
            **{name: count(data.get(name)) for name in _COUNTS},
            actions_by_name={str(k): count(v) for k, v in by_name.items()}
            if isinstance(by_name, Mapping) else {},
        )

    def summary(
        self, contract: CompiledContract, violations: tuple[MonitorViolation, ...], *,
        halted: bool, last_seq: int | None = None, pending_seq: int | None = None,
    ) -> MonitorSummary:
        """The MonitorSummary these counts make for a contract."""
        per_condition: dict[str, int] = {c.key: 0 for c in contract.invariants}
        for compiled in contract.invariants:
            per_condition[compiled.key] += self.states_checked
        for compiled in contract.aborts:
            per_condition[compiled.key] = (
                per_condition.get(compiled.key, 0) + self.actions_checked + self.states_checked)
        for name, times in self.actions_by_name.items():
            for compiled in contract.guards_for(name):
                per_condition[compiled.key] = per_condition.get(compiled.key, 0) + times
        for compiled in contract.conditions:
            per_condition.setdefault(compiled.key, 0)
        return MonitorSummary(
            actions_checked=self.actions_checked, states_checked=self.states_checked,
            guards_checked=self.guards_checked, invariants_checked=self.invariants_checked,
            aborts_checked=self.aborts_checked, violations=violations, halted=halted,
            messages=self.messages, errors=self.errors, refused=self.refused,
            checks_by_condition=per_condition, last_seq=last_seq, pending_seq=pending_seq,
        )


@dataclass(frozen=True, slots=True)
class MonitorSummary:
    """The paper's MonitorSummary, with a few extra counts."""

    actions_checked: int
    states_checked: int
    guards_checked: int
    invariants_checked: int
    aborts_checked: int
    violations: tuple[MonitorViolation, ...]
    halted: bool
    messages: int
    errors: int
    refused: int
    checks_by_condition: Mapping[str, int]
    last_seq: int | None = None
    pending_seq: int | None = None

    def to_wire(self) -> dict[str, Any]:
        """The summary as JSON."""
        out: dict[str, Any] = {f.name: getattr(self, f.name) for f in fields(self)}
        out["violations"] = [v.to_wire() for v in self.violations]
        out["checks_by_condition"] = dict(self.checks_by_condition)
        return out
