"""SafeGate's Prometheus metrics: one registry per app, so tests and workers never share counters.

In: events from the services (decisions, verifications, halts) and the HTTP middleware.
Out: counters and histograms served at `GET /metrics`.
"""

from __future__ import annotations

from prometheus_client import CollectorRegistry, Counter, Histogram

_LATENCY_BUCKETS = (0.0005, 0.001, 0.002, 0.003, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 1.0, 5.0)


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

    def record_decision(self, decision: str, rule: str, timings_ms: dict[str, float]) -> None:
        self.decisions.labels(decision, rule).inc()
        for stage, milliseconds in timings_ms.items():
            if stage != "total":
                self.gate_stage_seconds.labels(stage).observe(milliseconds / 1000)
