"""Operations: request ids, Prometheus metrics, and the body-size limit."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.config import Settings
from app.main import create_app


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
