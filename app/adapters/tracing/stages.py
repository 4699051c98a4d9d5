"""The gate stages' timings for tracing, as plain data that crosses a process boundary.

In: the services' stage calls (Stages 1-4 from the pipeline's own timings, Stage 5's proofs,
Stage 6's checks), inside `recording()`. Out: `StageSpan`s (name, wall-clock start and end in
nanoseconds, attributes) and the attributes meant for the enclosing request's span, which
`app.adapters.tracing.otel` turns into OpenTelemetry spans. Stages 1-5 run in the
analysis pool's worker processes, so their spans travel back with the job's result as this data
and become children of the HTTP request's span in the app's process: one exporter, one trace.
Nothing here imports OpenTelemetry; outside `recording(True)` every call is a no-op.
Fails: never (recording is appending to a list).
"""

from __future__ import annotations

import time
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field

from app.domain.pipeline import GateResult

AttributeValue = str | bool | int | float

# The pipeline's timings (`GateResult.timings_ms`) and the stage each one is, in pipeline order.
GATE_STAGES = (
    ("analysis", "safegate.stage1.analysis"),
    ("binding", "safegate.stage2.binding"),
    ("decision", "safegate.stage3.decision"),
    ("contract", "safegate.stage4.contract"),
)


@dataclass(frozen=True)
class StageSpan:
    """One stage as a span: what ran, from when to when (ns since the epoch), with what."""

    name: str
    start_ns: int
    end_ns: int
    attributes: Mapping[str, AttributeValue] = field(default_factory=dict)


@dataclass
class StageTrace:
    """What one unit of work (a job, a monitor check) recorded."""

    spans: list[StageSpan] = field(default_factory=list)
    request_attributes: dict[str, AttributeValue] = field(default_factory=dict)
    """For the span of the request that asked for the work (the decision and its rule)."""


_current: ContextVar[StageTrace | None] = ContextVar("safegate_stage_trace", default=None)


@contextmanager
def recording(enabled: bool) -> Iterator[StageTrace | None]:
    """Record the stages run inside the block (when `enabled`; else yield None)."""
    trace = StageTrace() if enabled else None
    token = _current.set(trace)
    try:
        yield trace
    finally:
        _current.reset(token)


def is_recording() -> bool:
    """Whether stage spans are being recorded here (lets callers skip building attributes)."""
    return _current.get() is not None


def record(name: str, start_ns: int, end_ns: int,
           attributes: Mapping[str, AttributeValue] | None = None) -> None:
    """Add one stage span, if recording."""
    trace = _current.get()
    if trace is not None:
        trace.spans.append(StageSpan(name, start_ns, end_ns, dict(attributes or {})))


def annotate_request(**attributes: AttributeValue) -> None:
    """Attributes for the enclosing request's span, if recording."""
    trace = _current.get()
    if trace is not None:
        trace.request_attributes.update(attributes)


@contextmanager
def stage(name: str, **attributes: AttributeValue) -> Iterator[dict[str, AttributeValue]]:
    """Time the block as one stage span; the block may add attributes to the yielded dict."""
    if _current.get() is None:
        yield {}
        return
    found = dict(attributes)
    started = time.time_ns()
    try:
        yield found
    finally:
        record(name, started, time.time_ns(), found)


def record_gate(result: GateResult, started_ns: int, gate_request_id: str) -> None:
    """Stages 1-4 of one `run_gate` call that began at `started_ns`, one span each.

    The pipeline measures each stage itself (`timings_ms`, which the metrics use too) and runs
    them back to back, so they are laid end to end from the call's start: tracing needs no hook
    in the pure domain, and the spans show the very durations the metrics count.
    """
    if _current.get() is None:
        return
    decision = result.decision
    report = result.report
    common: dict[str, AttributeValue] = {"safegate.gate_request_id": gate_request_id}
    details: dict[str, dict[str, AttributeValue]] = {
        "analysis": {"safegate.analyzer": report.analyzer,
                     "safegate.hazards": len(report.proposals),
                     "safegate.unknowns": len(report.unknowns),
                     "safegate.critical_unknowns": sum(u.critical for u in report.unknowns)},
        "binding": {"safegate.bound": len(result.binding.bound),
                    "safegate.unbound": len(result.binding.unbound)},
        "decision": {"safegate.decision": decision.decision.value,
                     "safegate.rule": decision.rule.value},
        "contract": {"safegate.contract": result.contract is not None},
    }
    if decision.defer_kind is not None:
        details["decision"]["safegate.defer_kind"] = decision.defer_kind.value
    start = started_ns
    for key, name in GATE_STAGES:
        if key not in result.timings_ms:  # Stage 4 runs on authorize only
            continue
        end = start + round(result.timings_ms[key] * 1_000_000)
        record(name, start, end, common | details[key])
        start = end
    annotate_request(**{"safegate.gate_request_id": gate_request_id,
                        "safegate.decision": decision.decision.value,
                        "safegate.rule": decision.rule.value})
