"""Operations at the edge: request ids, JSON access logs, Prometheus metrics, a body-size limit.

In: every HTTP request (a pure ASGI middleware, cheap enough for the gate's hot path).
Out: an `X-Request-ID` header on every answer (the caller's, or a new one), one JSON log line per
request on the `safegate.access` logger, metrics at `GET /metrics`, and a 413 problem+json for a
body larger than `max_body_bytes`, checked on the declared length and, for a chunked body (or a
declared length that lies), while it streams in: whatever the app made of the cut-off body is
dropped and the 413 sent in its place.
Fails: never blocks a request on logging or metrics.
"""

from __future__ import annotations

import contextlib
import json
import logging
import time
import uuid
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from fastapi import FastAPI, Request, Response
from prometheus_client import CONTENT_TYPE_LATEST, generate_latest

from app.metrics import Metrics

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

_access_log = logging.getLogger("safegate.access")


class _BodyTooLarge(Exception):
    pass


def _problem_body(status: int, title: str, detail: str) -> bytes:
    return json.dumps(
        {"type": "about:blank", "title": title, "status": status, "detail": detail}
    ).encode()


class ObservabilityMiddleware:
    """Request id, access log, metrics and body limit, for HTTP requests only."""

    def __init__(self, app: ASGIApp, *, metrics: Metrics, max_body_bytes: int) -> None:
        self.app = app
        self.metrics = metrics
        self.max_body_bytes = max_body_bytes

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        started = time.perf_counter()
        headers = {k.decode("latin-1").lower(): v for k, v in scope.get("headers", [])}
        request_id = headers.get("x-request-id", b"").decode("latin-1")[:128] or uuid.uuid4().hex
        scope.setdefault("state", {})["request_id"] = request_id
        status_holder = {"status": 500}

        declared = headers.get("content-length")
        if declared is not None and declared.isdigit() and int(declared) > self.max_body_bytes:
            await self._too_large(send, request_id)
            self._observe(scope, 413, started, request_id)
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

        async def tagged_send(message: Message) -> None:
            if too_large:
                # The app caught the overflow (FastAPI turns any error while reading a body
                # into "error parsing the body") and answers for it; the answer is our 413.
                return
            if message["type"] == "http.response.start":
                status_holder["status"] = message["status"]
                message.setdefault("headers", [])
                message["headers"] = [
                    *message["headers"], (b"x-request-id", request_id.encode("latin-1"))
                ]
            await send(message)

        with contextlib.suppress(_BodyTooLarge):
            await self.app(scope, limited_receive, tagged_send)
        if too_large:
            await self._too_large(send, request_id)
            status_holder["status"] = 413
        self._observe(scope, status_holder["status"], started, request_id)

    async def _too_large(self, send: Send, request_id: str) -> None:
        body = _problem_body(
            413, "Request body too large", f"the body exceeds {self.max_body_bytes} bytes"
        )
        await send({
            "type": "http.response.start",
            "status": 413,
            "headers": [
                (b"content-type", b"application/problem+json"),
                (b"content-length", str(len(body)).encode()),
                (b"x-request-id", request_id.encode("latin-1")),
            ],
        })
        await send({"type": "http.response.body", "body": body})

    def _observe(self, scope: Scope, status: int, started: float, request_id: str) -> None:
        elapsed = time.perf_counter() - started
        route = scope.get("route")
        template = getattr(route, "path", None) or "unmatched"
        method = scope.get("method", "")
        self.metrics.requests.labels(method, template, str(status)).inc()
        self.metrics.latency.labels(method, template).observe(elapsed)
        if _access_log.isEnabledFor(logging.INFO):
            _access_log.info("http_request", extra={"fields": {
                "event": "http_request", "request_id": request_id, "method": method,
                "path": scope.get("path"), "route": template, "status": status,
                "duration_ms": round(elapsed * 1000, 3),
            }})


def install(app: FastAPI, metrics: Metrics, *, max_body_bytes: int) -> None:
    """Add the middleware and `GET /metrics` to an app."""
    app.add_middleware(ObservabilityMiddleware, metrics=metrics, max_body_bytes=max_body_bytes)

    @app.get("/metrics", include_in_schema=False)
    def prometheus_metrics(_: Request) -> Response:
        return Response(generate_latest(metrics.registry), media_type=CONTENT_TYPE_LATEST)


class JsonLogFormatter(logging.Formatter):
    """One JSON object a line: time, level, logger, and the record's own fields: those given as
    `extra={"fields": {...}}` (the access log: no JSON text built only to be parsed again), or
    the message's if it is a JSON object, else the message."""

    def format(self, record: logging.LogRecord) -> str:
        entry: dict[str, Any] = {
            "ts": self.formatTime(record, "%Y-%m-%dT%H:%M:%S"),
            "level": record.levelname.lower(),
            "logger": record.name,
        }
        fields = record.__dict__.get("fields")
        message = record.getMessage()
        parsed: object = fields
        if not isinstance(fields, dict):
            try:
                parsed = json.loads(message)
            except ValueError:
                parsed = None
        if isinstance(parsed, dict):
            entry.update(parsed)
        else:
            entry["message"] = message
        if record.exc_info:
            entry["exception"] = self.formatException(record.exc_info)
        return json.dumps(entry, default=str)


def configure_logging(level: str) -> None:
    """Send SafeGate's and uvicorn's logs to stderr as JSON lines."""
    handler = logging.StreamHandler()
    handler.setFormatter(JsonLogFormatter())
    for name in ("safegate", "uvicorn", "uvicorn.error"):
        logger = logging.getLogger(name)
        logger.handlers = [handler]
        logger.setLevel(level.upper())
        logger.propagate = False
