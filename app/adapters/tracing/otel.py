"""OpenTelemetry behind `Tracing`: the one module of SafeGate that imports it (the `otel` extra).

In: the settings and an optional span exporter. Out: `OtelTracing`, with its own
`TracerProvider` (never the process-wide global, so each app, and each test, has its own),
a batch span processor, and OpenTelemetry's ASGI middleware for the request spans (it also reads
a caller's W3C `traceparent`). The request span carries `safegate.request_id` (the
`X-Request-ID`); stage spans carry it too, with the gate's audit id and what the stage found.
Fails: `replay` and `name_request` log and drop their error; exporting happens on the batch
processor's thread, whose failures OpenTelemetry logs.
"""

from __future__ import annotations

import logging
from typing import Any

from asgi_correlation_id import correlation_id
from fastapi import FastAPI
from opentelemetry import trace
from opentelemetry.instrumentation.asgi import OpenTelemetryMiddleware
from opentelemetry.sdk.resources import Resource
from opentelemetry.sdk.trace import TracerProvider
from opentelemetry.sdk.trace.export import BatchSpanProcessor, ConsoleSpanExporter, SpanExporter

from app.adapters.tracing import Tracing
from app.adapters.tracing.stages import StageTrace
from app.config import Settings

_log = logging.getLogger("safegate.tracing")
REQUEST_ID_ATTRIBUTE = "safegate.request_id"


def _configured_exporter(kind: str) -> SpanExporter:
    if kind == "console":
        return ConsoleSpanExporter()
    # Imported only when asked for: it reads OTEL_EXPORTER_OTLP_ENDPOINT and friends itself.
    from opentelemetry.exporter.otlp.proto.http.trace_exporter import OTLPSpanExporter

    return OTLPSpanExporter()


def _tag_request(span: Any, scope: dict[str, Any]) -> None:
    """The ASGI middleware's hook: the request id (set by the outer middleware) on its span."""
    if span.is_recording() and (request_id := correlation_id.get()):
        span.set_attribute(REQUEST_ID_ATTRIBUTE, request_id)


class OtelTracing(Tracing):
    """Spans per request and per stage, exported in batches."""

    enabled = True

    def __init__(self, settings: Settings, exporter: SpanExporter | None = None) -> None:
        resource = Resource.create({"service.name": settings.otel_service_name})
        self.provider = TracerProvider(resource=resource)
        self.provider.add_span_processor(
            BatchSpanProcessor(exporter or _configured_exporter(settings.otel_exporter)))
        self.tracer = self.provider.get_tracer("safegate")

    def add_middleware(self, app: FastAPI) -> None:
        app.add_middleware(OpenTelemetryMiddleware, tracer_provider=self.provider,
                           server_request_hook=_tag_request,
                           exclude_spans=["receive", "send"])

    def name_request(self, method: str, route: str) -> None:
        try:
            span = trace.get_current_span()
            if span.is_recording() and method:
                span.update_name(f"{method} {route}")
                span.set_attribute("http.route", route)
        except Exception:  # tracing never fails a request
            _log.exception("could not name the request's span")

    def replay(self, trace_: StageTrace | None) -> None:
        if trace_ is None:
            return
        try:
            request_id = correlation_id.get()
            common = {REQUEST_ID_ATTRIBUTE: request_id} if request_id else {}
            for stage in trace_.spans:
                span = self.tracer.start_span(stage.name, start_time=stage.start_ns,
                                              attributes={**common, **stage.attributes})
                span.end(end_time=stage.end_ns)
            parent = trace.get_current_span()
            if trace_.request_attributes and parent.is_recording():
                parent.set_attributes(trace_.request_attributes)
        except Exception:  # tracing never fails a request
            _log.exception("could not record the stages' spans")

    def force_flush(self) -> None:
        self.provider.force_flush()

    def shutdown(self) -> None:
        self.provider.shutdown()
