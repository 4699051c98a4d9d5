"""SafeGate's log lines: one JSON object a line on stderr, through python-json-logger.

In: log records from SafeGate's and uvicorn's loggers. Out: JSON with `ts` (ISO 8601 in UTC with
milliseconds, `2026-11-26T03:14:58.123Z`), `level`, `logger`, then the record's own fields: those
given as `extra={"fields": {...}}` (the access log), those of a message that is a JSON object,
or else `message`; any other `extra` keys; `exc_info` for an exception. Every line logged while
an HTTP request or a websocket is being served carries its `request_id` (the `X-Request-ID` that
`asgi-correlation-id` read or made), so a websocket's lines and a gate request's lines can be
found by one id; with tracing on, a line logged inside a span carries its `trace_id` and
`span_id` too. Fails: never; a value JSON cannot encode is written as its `str`.
"""

from __future__ import annotations

import json
import logging
import time
from typing import Any

from asgi_correlation_id import correlation_id
from pythonjsonlogger.core import RESERVED_ATTRS
from pythonjsonlogger.json import JsonFormatter

from app.adapters.tracing import current_trace_ids

# Not copied as extra keys: `fields` is merged itself, `color_message` is uvicorn's coloured copy.
_NOT_EXTRA = (*RESERVED_ATTRS, "fields", "color_message")


def utc_timestamp(created: float) -> str:
    """A record's creation time as ISO 8601 in UTC with milliseconds."""
    whole = int(created)
    millis = int((created - whole) * 1000)
    return f"{time.strftime('%Y-%m-%dT%H:%M:%S', time.gmtime(whole))}.{millis:03d}Z"


class JsonLogFormatter(JsonFormatter):
    """python-json-logger's formatter with SafeGate's fixed leading fields and request id."""

    def __init__(self) -> None:
        super().__init__(fmt=[], reserved_attrs=_NOT_EXTRA, json_default=str)

    def add_fields(
        self, log_data: dict[str, Any], record: logging.LogRecord, message_dict: dict[str, Any]
    ) -> None:
        log_data["ts"] = utc_timestamp(record.created)
        log_data["level"] = record.levelname.lower()
        log_data["logger"] = record.name
        fields = record.__dict__.get("fields")
        logged_a_dict = isinstance(record.msg, dict)  # its keys arrive in message_dict
        if not isinstance(fields, dict) and not logged_a_dict:
            fields = _json_object(record.message)
        if isinstance(fields, dict):
            log_data.update(fields)
        elif not logged_a_dict:
            log_data["message"] = record.message
        super().add_fields(log_data, record, message_dict)
        if "request_id" not in log_data and (request_id := correlation_id.get()):
            log_data["request_id"] = request_id
        if "trace_id" not in log_data and (ids := current_trace_ids()):
            log_data["trace_id"], log_data["span_id"] = ids


def _json_object(message: str) -> dict[str, Any] | None:
    if not message.startswith("{"):
        return None
    try:
        parsed = json.loads(message)
    except ValueError:
        return None
    return parsed if isinstance(parsed, dict) else None


def configure_logging(level: str) -> None:
    """Send SafeGate's and uvicorn's logs to stderr as JSON lines."""
    handler = logging.StreamHandler()
    handler.setFormatter(JsonLogFormatter())
    for name in ("safegate", "uvicorn", "uvicorn.error", "asgi_correlation_id"):
        logger = logging.getLogger(name)
        logger.handlers = [handler]
        logger.setLevel(level.upper())
        logger.propagate = False
