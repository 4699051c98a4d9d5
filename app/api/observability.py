"""Operations at the edge: request ids, access logs, Prometheus metrics, a body-size limit.

In: every HTTP request and websocket (pure ASGI middlewares, cheap enough for the gate's hot path).
Out: an `X-Request-ID` on every HTTP answer (the caller's, up to 128 printable characters, or a new
one; `asgi-correlation-id` keeps it in a context variable, so every log line of the request or
websocket carries it, see `app.api.logs`), one log line per HTTP request on the `safegate.access`
logger, with `gate_request_id` (the audit record's id, which the gate routes also answer in
`X-Gate-Request-ID`) when the request decided something, metrics at `GET /metrics`, the request's
span (tracing on) named after its route, and a 413 problem+json for a body larger than
`max_body_bytes` (checked on the declared length and, for a chunked body or a declared length that
lies, while it streams in: whatever the app made of the cut-off body is dropped and the 413 sent in
its place).
Fails: never blocks a request on logging or metrics.
"""

from __future__ import annotations

import contextlib
import json
import logging
import time
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from asgi_correlation_id import CorrelationIdMiddleware, correlation_id
from fastapi import FastAPI, Request, Response
from prometheus_client import CONTENT_TYPE_LATEST

from app.adapters.tracing import Tracing
from app.metrics import Metrics

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

_access_log = logging.getLogger("safegate.access")

REQUEST_ID_HEADER = "X-Request-ID"
GATE_REQUEST_ID_HEADER = "X-Gate-Request-ID"
_GATE_REQUEST_ID = GATE_REQUEST_ID_HEADER.lower().encode("latin-1")
MAX_REQUEST_ID_CHARS = 128


def acceptable_request_id(value: str) -> bool:
    """Whether a caller's `X-Request-ID` is kept (else a new id replaces it)."""
    return len(value) <= MAX_REQUEST_ID_CHARS and value.isprintable()


class _BodyTooLarge(Exception):
    pass


def _problem_body(status: int, title: str, detail: str) -> bytes:
    return json.dumps(
        {"type": "about:blank", "title": title, "status": status, "detail": detail}
    ).encode()


class ObservabilityMiddleware:
    """Request id, access log, metrics and body limit, for HTTP requests only."""

    def __init__(self, app: ASGIApp, *, metrics: Metrics, max_body_bytes: int,
                 tracing: Tracing | None = None) -> None:
        self.app = app
        self.metrics = metrics
        self.max_body_bytes = max_body_bytes
        self.tracing = tracing or Tracing()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        started = time.perf_counter()
        declared = next((v for k, v in scope.get("headers", []) if k.lower() == b"content-length"),
                        None)
        outcome: dict[str, Any] = {"status": 500, "gate_request_id": None}

        if declared is not None and declared.isdigit() and int(declared) > self.max_body_bytes:
            await self._too_large(send)
            self._observe(scope, outcome | {"status": 413}, started)
            return

        received = 0
        too_large = False

        async def limited_receive() -> Message:
            nonlocal received, too_large
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.max_body_bytes:
                    too_large = True
                    raise _BodyTooLarge
            return message

        async def observed_send(message: Message) -> None:
            if too_large:
                # The app caught the overflow (FastAPI turns any error while reading a body
                # into "error parsing the body") and answers for it; the answer is our 413.
                return
            if message["type"] == "http.response.start":
                outcome["status"] = message["status"]
                for key, value in message.get("headers", ()):
                    if key == _GATE_REQUEST_ID:
                        outcome["gate_request_id"] = value.decode("latin-1")
                # Now, not after the body: the request's span ends with the last body message.
                self.tracing.name_request(scope.get("method", ""), _route_template(scope))
            await send(message)

        with contextlib.suppress(_BodyTooLarge):
            await self.app(scope, limited_receive, observed_send)
        if too_large:
            await self._too_large(send)
            outcome["status"] = 413
        self._observe(scope, outcome, started)

    async def _too_large(self, send: Send) -> None:
        body = _problem_body(
            413, "Request body too large", f"the body exceeds {self.max_body_bytes} bytes"
        )
        await send({
            "type": "http.response.start",
            "status": 413,
            "headers": [
                (b"content-type", b"application/problem+json"),
                (b"content-length", str(len(body)).encode()),
            ],
        })
        await send({"type": "http.response.body", "body": body})

    def _observe(self, scope: Scope, outcome: dict[str, Any], started: float) -> None:
        elapsed = time.perf_counter() - started
        status = outcome["status"]
        template = _route_template(scope)
        method = scope.get("method", "")
        self.metrics.requests.labels(method, template, str(status)).inc()
        self.metrics.latency.labels(method, template).observe(elapsed)
        if _access_log.isEnabledFor(logging.INFO):
            fields = {
                "event": "http_request", "request_id": correlation_id.get(), "method": method,
                "path": scope.get("path"), "route": template, "status": status,
                "duration_ms": round(elapsed * 1000, 3),
            }
            if outcome["gate_request_id"] is not None:
                fields["gate_request_id"] = outcome["gate_request_id"]
            _access_log.info("http_request", extra={"fields": fields})


def _route_template(scope: Scope) -> str:
    return getattr(scope.get("route"), "path", None) or "unmatched"


def install(app: FastAPI, metrics: Metrics, *, max_body_bytes: int,
            tracing: Tracing | None = None) -> None:
    """Add the middlewares (request ids outermost, then the tracing spans, when on) and
    `GET /metrics` to an app."""
    app.add_middleware(ObservabilityMiddleware, metrics=metrics, max_body_bytes=max_body_bytes,
                       tracing=tracing)
    (tracing or Tracing()).add_middleware(app)
    app.add_middleware(CorrelationIdMiddleware, header_name=REQUEST_ID_HEADER,
                       update_request_header=False, validator=acceptable_request_id)

    @app.get("/metrics", include_in_schema=False)
    def prometheus_metrics(_: Request) -> Response:
        return Response(metrics.exposition(), media_type=CONTENT_TYPE_LATEST)
