"""Stage 6, Runtime Monitoring: a contract enforced action by action, halting on a violation.

In: a `Contract` (compiled once into a `CompiledContract`), the initial `WorldState`, then the
runtime's `before`/`after` messages (and `sync`, its state after a request to resynchronise).
Out: one `Verdict` per message (allow, violation, error, halted), the `MonitorViolation` that
halted the session, and the `MonitorSummary`.
Fails: `CompiledContract` raises `FormulaError` for a contract that cannot be monitored;
`Monitor.step` never raises (a bad message is an `error` verdict, never an allow).
"""

from app.domain.monitor.conditions import CompiledCondition, CompiledContract, first_failure
from app.domain.monitor.counters import MonitorCounters, MonitorSummary
from app.domain.monitor.messages import (
    MonitorMessage,
    MonitorViolation,
    Verdict,
    decode_message,
    parse_message,
)
from app.domain.monitor.monitor import Monitor, replay, utc_clock

__all__ = [
    "CompiledCondition",
    "CompiledContract",
    "Monitor",
    "MonitorCounters",
    "MonitorMessage",
    "MonitorSummary",
    "MonitorViolation",
    "Verdict",
    "decode_message",
    "first_failure",
    "parse_message",
    "replay",
    "utc_clock",
]
