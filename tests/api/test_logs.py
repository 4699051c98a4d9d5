"""Log lines: ISO 8601 UTC timestamps with milliseconds, one request id from the HTTP request or
websocket through every line it logs, and the gate's audit id on the request's access line."""

from __future__ import annotations

import json
import logging
import re
import sys
from datetime import UTC, datetime
from pathlib import Path

from fastapi.testclient import TestClient

from app.api.logs import JsonLogFormatter, utc_timestamp
from app.store.repository import Repository
from tests.api.conftest import LogLines

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import GO_TO_MUG, before, store_contract

_ISO_UTC_MS = re.compile(r"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$")


class TestTimestamps:
    def test_iso_8601_utc_with_milliseconds(self) -> None:
        record = logging.LogRecord("safegate", logging.INFO, __file__, 1, "hi", None, None)
        entry = json.loads(JsonLogFormatter().format(record))
        assert _ISO_UTC_MS.match(entry["ts"]), entry["ts"]
        parsed = datetime.fromisoformat(entry["ts"].replace("Z", "+00:00"))
        assert abs(parsed.timestamp() - record.created) < 0.001
        assert list(entry)[:3] == ["ts", "level", "logger"]

    def test_milliseconds_are_truncated_not_rounded_into_the_next_second(self) -> None:
        moment = datetime(2026, 11, 26, 3, 14, 58, 999_900, tzinfo=UTC).timestamp()
        assert utc_timestamp(moment) == "2026-11-26T03:14:58.999Z"

    def test_an_exception_keeps_its_message_and_traceback(self) -> None:
        try:
            raise ValueError("bad")
        except ValueError:
            record = logging.LogRecord("safegate", logging.ERROR, __file__, 1, "failed %s",
                                       ("x",), sys.exc_info())
        entry = json.loads(JsonLogFormatter().format(record))
        assert entry["message"] == "failed x"
        assert "ValueError: bad" in entry["exc_info"]


class TestRequestIds:
    def test_the_gate_answer_and_its_access_line_link_both_ids(
        self, client: TestClient, lines: LogLines
    ) -> None:
        response = client.post("/gate", json={"command": "wave hello"},
                               headers={"X-Request-ID": "trace-77"})
        audit_id = response.json()["request_id"]
        assert response.headers["x-request-id"] == "trace-77"
        assert response.headers["x-gate-request-id"] == audit_id
        (access,) = lines.of("safegate.access")
        assert (access["request_id"], access["gate_request_id"]) == ("trace-77", audit_id)
        assert client.get(f"/gate/{audit_id}").status_code == 200

    def test_a_request_that_decides_nothing_has_no_audit_id(
        self, client: TestClient, lines: LogLines
    ) -> None:
        response = client.get("/healthz")
        assert "x-gate-request-id" not in response.headers
        (access,) = lines.of("safegate.access")
        assert "gate_request_id" not in access
        assert access["request_id"] == response.headers["x-request-id"]

    def test_an_unusable_caller_id_is_replaced(self, client: TestClient) -> None:
        too_long = "x" * 200
        response = client.get("/healthz", headers={"X-Request-ID": too_long})
        assert response.headers["x-request-id"] not in ("", too_long)

    def test_websocket_lines_carry_the_request_and_session_ids(
        self, client: TestClient, lines: LogLines
    ) -> None:
        repository = Repository(client.app.state.components.engine)  # type: ignore[attr-defined]
        contract_id = store_contract(repository)
        session_id = client.post("/monitor", json={"contract_id": contract_id}).json()[
            "session_id"]
        with client.websocket_connect(f"/monitor/{session_id}",
                                      headers={"X-Request-ID": "ws-9"}) as socket:
            socket.send_json(before(1, GO_TO_MUG))
            assert socket.receive_json()["type"] == "allow"
        with client.websocket_connect("/monitor/nope/events") as socket:
            assert socket.receive_json()["type"] == "error"
        sockets = lines.of("safegate.websocket")
        assert [(e["event"], e["channel"]) for e in sockets] == [
            ("websocket_open", "runtime"), ("websocket_close", "runtime"),
            ("websocket_refused", "events")]
        assert {e["request_id"] for e in sockets[:2]} == {"ws-9"}
        assert {e["session_id"] for e in sockets[:2]} == {session_id}
        assert sockets[1]["messages"] == 1
        assert sockets[2]["request_id"] not in ("", "ws-9")
