"""Operations: request ids, Prometheus metrics, and the body-size limit."""

from __future__ import annotations

import json
import logging
from collections.abc import Callable, Iterator
from pathlib import Path

import httpx
import pytest
from fastapi.testclient import TestClient

from app.api.logs import JsonLogFormatter
from app.config import Settings
from app.main import create_app
from tests.api.conftest import LiveServer


@pytest.fixture
def small_client(tmp_path: Path) -> Iterator[TestClient]:
    settings = Settings(database_url=f"sqlite:///{tmp_path / 'o.db'}", max_body_bytes=2048)
    with TestClient(create_app(settings)) as client:
        yield client


class TestRequestId:
    def test_every_answer_carries_a_request_id(self, client: TestClient) -> None:
        assert len(client.get("/healthz").headers["x-request-id"]) >= 16

    def test_the_callers_request_id_is_echoed(self, client: TestClient) -> None:
        response = client.get("/healthz", headers={"X-Request-ID": "trace-42"})
        assert response.headers["x-request-id"] == "trace-42"


class TestMetrics:
    def test_decisions_are_counted_by_rule(self, client: TestClient) -> None:
        decision = client.post("/gate", json={"command": "wave hello"}).json()
        text = client.get("/metrics").text
        label = f'decision="{decision["decision"]}",rule="{decision["rule"]}"'
        assert f"safegate_gate_decisions_total{{{label}}} 1.0" in text
        assert 'safegate_http_requests_total{method="POST",route="/gate",status="200"}' in text


class TestBodyLimit:
    def test_declared_oversized_body_is_refused_with_413(self, small_client: TestClient) -> None:
        response = small_client.post("/gate", json={"command": "x" * 5000})
        assert response.status_code == 413
        assert response.headers["content-type"] == "application/problem+json"

    def test_oversized_body_stores_nothing(self, small_client: TestClient) -> None:
        small_client.post("/gate", json={"command": "y" * 5000})
        assert "safegate_gate_decisions_total{" not in small_client.get("/metrics").text

    def test_a_body_within_the_limit_is_decided(self, small_client: TestClient) -> None:
        assert small_client.post("/gate", json={"command": "wave hello"}).status_code == 200

    def test_a_chunked_oversized_body_is_refused_with_413_not_422(
            self, small_client: TestClient) -> None:
        response = small_client.post("/gate", content=_chunks(json.dumps({"command": "z" * 5000})),
                                     headers={"content-type": "application/json"})
        assert response.status_code == 413, response.text
        assert response.headers["content-type"] == "application/problem+json"
        assert response.json()["status"] == 413
        assert "safegate_gate_decisions_total{" not in small_client.get("/metrics").text

    def test_a_chunked_body_within_the_limit_is_decided(self, small_client: TestClient) -> None:
        response = small_client.post("/gate", content=_chunks(json.dumps({"command": "wave"})),
                                     headers={"content-type": "application/json"})
        assert response.status_code == 200, response.text

    def test_a_chunked_oversized_body_gets_413_from_uvicorn(
            self, live_server: Callable[..., LiveServer]) -> None:
        server = live_server(SAFEGATE_MAX_BODY_BYTES="2048", SAFEGATE_LOG_LEVEL="warning")
        body = json.dumps({"command": "z" * 5000})
        for path in ("/gate", "/verify", "/templates/validate"):
            response = httpx.post(server.base_url + path, content=_chunks(body), timeout=30,
                                  headers={"content-type": "application/json"})
            assert response.status_code == 413, (path, response.text)
            assert response.headers["content-type"] == "application/problem+json"
            assert response.request.headers["transfer-encoding"] == "chunked"
        # The connection and the server are fine afterwards.
        assert httpx.get(server.base_url + "/healthz", timeout=10).status_code == 200


def _chunks(text: str, size: int = 512) -> Iterator[bytes]:
    """The body as a generator: httpx sends it chunked, with no Content-Length."""
    data = text.encode()
    for start in range(0, len(data), size):
        yield data[start:start + size]


class TestAccessLog:
    def test_each_request_is_one_json_line_with_its_id_route_and_status(
            self, client: TestClient, caplog: pytest.LogCaptureFixture) -> None:
        with caplog.at_level(logging.INFO, logger="safegate.access"):
            client.post("/gate", json={"command": "wave hello"}, headers={"X-Request-ID": "r-7"})
        records = [r for r in caplog.records if r.name == "safegate.access"]
        assert len(records) == 1
        line = JsonLogFormatter().format(records[0])
        entry = json.loads(line)
        assert "\n" not in line
        assert entry["event"] == "http_request"
        assert entry["request_id"] == "r-7"
        assert (entry["method"], entry["route"], entry["status"]) == ("POST", "/gate", 200)
        assert entry["duration_ms"] > 0
        assert entry["level"] == "info" and entry["logger"] == "safegate.access"

    def test_other_messages_keep_their_text_or_their_json_fields(self) -> None:
        def formatted(message: str) -> dict[str, object]:
            record = logging.LogRecord("uvicorn.error", logging.INFO, __file__, 1, message,
                                       None, None)
            parsed: dict[str, object] = json.loads(JsonLogFormatter().format(record))
            return parsed

        assert formatted("Started server process")["message"] == "Started server process"
        assert formatted('{"event": "ready", "port": 8000}')["port"] == 8000
