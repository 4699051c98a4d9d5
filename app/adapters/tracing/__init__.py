"""Opt-in OpenTelemetry tracing (`SAFEGATE_OTEL_ENABLED`), confined to this package.

In: the settings (and, from tests and benchmarks, a span exporter of their own). Out: a
`Tracing`: it adds the HTTP/websocket span middleware to the app, names a request's span after
its route, and turns the stages that `stages.recording()` captured (in this process or in an
analysis worker) into child spans of the current request's span. Tracing off, or the `otel`
extra not installed, gives the base `Tracing`, whose every method does nothing; OpenTelemetry is
imported only by `start_tracing` when it is on (`otel.py` is the one module that imports it).
Fails: never a request or a decision. A tracer that cannot start is logged and left off; a
replay that fails is logged and dropped; the exporter sends from its own thread.
"""

from __future__ import annotations

import logging
import sys
from typing import TYPE_CHECKING, Any

from app.adapters.tracing.stages import StageTrace

if TYPE_CHECKING:
    from fastapi import FastAPI

    from app.config import Settings

_log = logging.getLogger("safegate.tracing")


class Tracing:
    """Tracing switched off: nothing is added, recorded or exported."""

    enabled = False

    def add_middleware(self, app: FastAPI) -> None:
        """Add the span-per-request middleware (inside the request-id middleware)."""

    def name_request(self, method: str, route: str) -> None:
        """Name the current request's span after its route template (`POST /gate/{id}`)."""

    def replay(self, trace: StageTrace | None) -> None:
        """Make the recorded stages children of the current span."""

    def force_flush(self) -> None:
        """Export every finished span now."""

    def shutdown(self) -> None:
        """Flush and stop the exporter."""


def start_tracing(settings: Settings, exporter: Any = None) -> Tracing:
    """The app's tracing: OpenTelemetry when `settings.otel_enabled`, else the no-op base.

    Args:
        settings: `otel_enabled`, `otel_exporter`, `otel_service_name`.
        exporter: an OpenTelemetry `SpanExporter` to use instead of the configured one (tests
            and benchmarks pass an in-memory one, so nothing reaches the network).
    """
    if not settings.otel_enabled:
        return Tracing()
    try:
        from app.adapters.tracing.otel import OtelTracing
    except ImportError as error:
        _log.error("SAFEGATE_OTEL_ENABLED is set but OpenTelemetry is not installed "
                   "(pip install 'safegate[otel]'); serving without traces: %s", error)
        return Tracing()
    try:
        return OtelTracing(settings, exporter)
    except Exception:
        _log.exception("OpenTelemetry could not start; serving without traces")
        return Tracing()


def current_trace_ids() -> tuple[str, str] | None:
    """The current span's trace and span ids (hex), for log lines; None outside a span.

    Without OpenTelemetry imported there can be no span, so nothing is imported here.
    """
    otel_trace = sys.modules.get("opentelemetry.trace")
    if otel_trace is None:
        return None
    context = otel_trace.get_current_span().get_span_context()
    if not context.is_valid:
        return None
    return format(context.trace_id, "032x"), format(context.span_id, "016x")
