"""SafeGate's Prometheus metrics: one registry per app, so tests and workers never share counters.

In: events from the services (decisions, verifications, halts, monitor sessions opened and closed,
the analysis pool's queue) and the HTTP middleware. Out: counters, histograms and gauges served at
`GET /metrics` (`Metrics.exposition`).
Multiprocess mode: with `PROMETHEUS_MULTIPROC_DIR` set (before the process starts), every
process (each `safegate serve --workers N` worker) writes its values to files in that directory,
and `/metrics`, whichever worker answers it, reports all of them (`MultiProcessCollector`):
counters and histograms summed, the gauges summed over the processes alive (`livesum`). A
process removes its gauge files when it exits; those of a process killed outright are removed
at the next scrape. The directory must be empty when the server starts (`safegate serve` empties
it). Without the variable, each app reports its own registry.
Fails: never; a metric is never a reason to fail a request.
"""

from __future__ import annotations

import glob
import os

from prometheus_client import (
    CollectorRegistry,
    Counter,
    Gauge,
    Histogram,
    generate_latest,
    multiprocess,
)

from app.domain.gate import Decision, Rule

_LATENCY_BUCKETS = (0.0005, 0.001, 0.002, 0.003, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 1.0, 5.0)
MULTIPROC_DIR_ENV = "PROMETHEUS_MULTIPROC_DIR"


def multiprocess_directory() -> str | None:
    """The directory of multiprocess mode, or None when each process reports alone."""
    return os.environ.get(MULTIPROC_DIR_ENV) or os.environ.get(MULTIPROC_DIR_ENV.lower())


def clear_multiprocess_directory() -> None:
    """Remove the value files of earlier runs (call before any worker starts)."""
    directory = multiprocess_directory()
    if directory is None:
        return
    os.makedirs(directory, exist_ok=True)
    for path in glob.glob(os.path.join(directory, "*.db")):
        os.remove(path)


def pid_alive(pid: int) -> bool:
    """Whether a process with this id exists (one owned by another user counts)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _forget_dead_processes(directory: str) -> None:
    """Drop the live gauges of processes that died without saying so (SIGKILL, OOM)."""
    pids = set()
    for path in glob.glob(os.path.join(directory, "gauge_live*_*.db")):
        tail = os.path.basename(path).rsplit("_", 1)[-1].removesuffix(".db")
        if tail.isdigit():
            pids.add(int(tail))
    for pid in pids:
        if not pid_alive(pid):
            multiprocess.mark_process_dead(pid, directory)  # type: ignore[no-untyped-call]


class Metrics:
    """SafeGate's Prometheus metrics, on a registry of their own (one per app)."""

    def __init__(self) -> None:
        self.registry = CollectorRegistry()
        self.requests = Counter(
            "safegate_http_requests_total", "HTTP requests answered",
            ["method", "route", "status"], registry=self.registry,
        )
        self.latency = Histogram(
            "safegate_http_request_duration_seconds", "Time to answer an HTTP request",
            ["method", "route"], buckets=_LATENCY_BUCKETS, registry=self.registry,
        )
        self.decisions = Counter(
            "safegate_gate_decisions_total", "Gate decisions by decision and rule",
            ["decision", "rule"], registry=self.registry,
        )
        self.gate_stage_seconds = Histogram(
            "safegate_gate_stage_duration_seconds", "Time spent in each gate stage",
            ["stage"], buckets=_LATENCY_BUCKETS, registry=self.registry,
        )
        self.verifications = Counter(
            "safegate_verifications_total", "Plan verifications by outcome",
            ["outcome"], registry=self.registry,
        )
        self.monitor_halts = Counter(
            "safegate_monitor_halts_total", "Monitor sessions halted, by violation kind",
            ["kind"], registry=self.registry,
        )
        self.monitor_sessions_open = Gauge(
            "safegate_monitor_sessions_open", "Monitor sessions with a runtime connected",
            registry=self.registry, multiprocess_mode="livesum",
        )
        self.analysis_in_flight = Gauge(
            "safegate_analysis_pool_in_flight", "Gate jobs running or waiting in the analysis pool",
            registry=self.registry, multiprocess_mode="livesum",
        )
        self.analysis_queued = Gauge(
            "safegate_analysis_pool_queued", "Gate jobs waiting for an analysis worker",
            registry=self.registry, multiprocess_mode="livesum",
        )

    def record_decision(self, decision: Decision, rule: Rule,
                        timings_ms: dict[str, float]) -> None:
        self.decisions.labels(decision.value, rule.value).inc()
        for stage, milliseconds in timings_ms.items():
            if stage != "total":
                self.gate_stage_seconds.labels(stage).observe(milliseconds / 1000)

    def exposition(self) -> bytes:
        """The text `/metrics` serves: every process's values in multiprocess mode, else this
        app's registry."""
        directory = multiprocess_directory()
        if directory is None:
            return generate_latest(self.registry)
        _forget_dead_processes(directory)
        registry = CollectorRegistry()
        multiprocess.MultiProcessCollector(registry, path=directory)  # type: ignore[no-untyped-call]
        return generate_latest(registry)

    def process_exiting(self) -> None:
        """This process stops serving: its live gauges no longer count."""
        directory = multiprocess_directory()
        if directory is not None:
            multiprocess.mark_process_dead(os.getpid(), directory)  # type: ignore[no-untyped-call]
