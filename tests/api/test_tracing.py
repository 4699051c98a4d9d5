"""OpenTelemetry traces (opt-in): a span per HTTP request and websocket, a child span per stage.

A real uvicorn on loopback serves an app whose spans go to the SDK's in-memory exporter (nothing
leaves the process); the stages run in the analysis pool's worker processes as in production, so
these tests also check that their spans come back and hang under the request that asked.
"""

from __future__ import annotations

import json
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import httpx
import pytest
import uvicorn
from fastapi import FastAPI
from opentelemetry.sdk.trace import ReadableSpan
from opentelemetry.sdk.trace.export import SpanExporter, SpanExportResult
from opentelemetry.sdk.trace.export.in_memory_span_exporter import InMemorySpanExporter
from websockets.sync.client import connect

from app.config import Settings
from app.main import create_app
from tests.api.conftest import LogLines
from tests.api.test_verify_api import GOOD_PLAN, KNIFE_REQUEST

REPO = Path(__file__).resolve().parents[2]
GATE_STAGES = ["safegate.stage1.analysis", "safegate.stage2.binding",
               "safegate.stage3.decision", "safegate.stage4.contract"]


@dataclass
class TracedServer:
    app: FastAPI
    exporter: InMemorySpanExporter
    base_url: str

    def spans(self) -> list[ReadableSpan]:
        self.app.state.tracing.force_flush()
        return list(self.exporter.get_finished_spans())

    def named(self, name: str) -> list[ReadableSpan]:
        return [span for span in self.spans() if span.name == name]


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


def _serve(app: FastAPI, exporter: InMemorySpanExporter) -> Iterator[TracedServer]:
    port = _free_port()
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_config=None))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 60
    while not server.started:
        if time.monotonic() > deadline or not thread.is_alive():
            raise RuntimeError("uvicorn did not start")
        time.sleep(0.05)
    try:
        yield TracedServer(app, exporter, f"http://127.0.0.1:{port}")
    finally:
        server.should_exit = True
        thread.join(timeout=30)


@pytest.fixture(scope="module")
def traced(tmp_path_factory: pytest.TempPathFactory) -> Iterator[TracedServer]:
    database = tmp_path_factory.mktemp("traced") / "traced.db"
    exporter = InMemorySpanExporter()
    settings = Settings(database_url=f"sqlite:///{database}", otel_enabled=True, gate_workers=1)
    yield from _serve(create_app(settings, span_exporter=exporter), exporter)


def _children(parent: ReadableSpan, spans: Sequence[ReadableSpan]) -> list[ReadableSpan]:
    assert parent.context is not None
    return sorted((s for s in spans if s.parent is not None
                   and s.parent.span_id == parent.context.span_id
                   and s.context is not None
                   and s.context.trace_id == parent.context.trace_id),
                  key=lambda s: s.start_time or 0)


def _request_span(traced: TracedServer, name: str, request_id: str) -> ReadableSpan:
    found = [s for s in traced.named(name)
             if (s.attributes or {}).get("safegate.request_id") == request_id]
    assert len(found) == 1, [s.name for s in traced.spans()]
    return found[0]


class TestGateSpans:
    def test_a_gate_request_has_one_span_per_stage_under_its_own(
            self, traced: TracedServer) -> None:
        response = httpx.post(traced.base_url + "/gate", json=KNIFE_REQUEST, timeout=60)
        body = response.json()
        assert response.status_code == 200 and body["decision"] == "authorize", body
        request_id = response.headers["X-Request-ID"]
        gate_request_id = response.headers["X-Gate-Request-ID"]

        spans = traced.spans()
        request = _request_span(traced, "POST /gate", request_id)
        attributes = request.attributes or {}
        assert attributes["safegate.decision"] == "authorize"
        assert attributes["safegate.rule"] == body["rule"] == "R4"
        assert attributes["safegate.gate_request_id"] == gate_request_id
        assert attributes["http.route"] == "/gate"

        stages = _children(request, spans)
        assert [s.name for s in stages] == GATE_STAGES
        for stage in stages:
            stage_attributes = stage.attributes or {}
            assert stage_attributes["safegate.request_id"] == request_id
            assert stage_attributes["safegate.gate_request_id"] == gate_request_id
            assert request.start_time is not None and request.end_time is not None
            assert stage.start_time is not None and stage.end_time is not None
            assert request.start_time <= stage.start_time <= stage.end_time <= request.end_time
        analysis, _, decision, contract = (s.attributes or {} for s in stages)
        assert analysis["safegate.analyzer"] == "symbolic"
        assert decision["safegate.decision"] == "authorize" and decision["safegate.rule"] == "R4"
        assert contract["safegate.contract"] is True

    def test_a_reject_has_no_contract_stage_and_names_its_rule(
            self, traced: TracedServer) -> None:
        reject = {**KNIFE_REQUEST, "command": "throw the knife at the owner"}
        response = httpx.post(traced.base_url + "/gate", json=reject, timeout=60)
        body = response.json()
        assert body["decision"] == "reject", body
        request = _request_span(traced, "POST /gate", response.headers["X-Request-ID"])
        assert (request.attributes or {})["safegate.rule"] == body["rule"]
        assert [s.name for s in _children(request, traced.spans())] == GATE_STAGES[:3]

    def test_the_access_line_carries_the_request_spans_trace_id(
            self, traced: TracedServer, lines: LogLines) -> None:
        response = httpx.post(traced.base_url + "/gate", json=KNIFE_REQUEST, timeout=60)
        request = _request_span(traced, "POST /gate", response.headers["X-Request-ID"])
        access = [e for e in lines.of("safegate.access")
                  if e.get("request_id") == response.headers["X-Request-ID"]]
        assert len(access) == 1, lines.entries
        assert request.context is not None
        assert access[0]["trace_id"] == format(request.context.trace_id, "032x")
        assert access[0]["span_id"] == format(request.context.span_id, "016x")

    def test_a_callers_traceparent_becomes_the_parent(self, traced: TracedServer) -> None:
        trace_id = "4bf92f3577b34da6a3ce929d0e0e4736"
        headers = {"traceparent": f"00-{trace_id}-00f067aa0ba902b7-01"}
        response = httpx.post(traced.base_url + "/gate", json=KNIFE_REQUEST, headers=headers,
                              timeout=60)
        request = _request_span(traced, "POST /gate", response.headers["X-Request-ID"])
        assert request.context is not None
        assert format(request.context.trace_id, "032x") == trace_id


class TestVerifyAndMonitorSpans:
    def test_verify_has_a_stage5_span(self, traced: TracedServer) -> None:
        gate = httpx.post(traced.base_url + "/gate", json=KNIFE_REQUEST, timeout=60).json()
        response = httpx.post(traced.base_url + "/verify", timeout=60,
                              json={"contract_id": gate["contract_id"], "plan": GOOD_PLAN})
        assert response.json()["ok"] is True
        request = _request_span(traced, "POST /verify", response.headers["X-Request-ID"])
        [stage] = _children(request, traced.spans())
        assert stage.name == "safegate.stage5.verify"
        assert (stage.attributes or {})["safegate.verified"] is True
        assert (stage.attributes or {})["safegate.contract_id"] == gate["contract_id"]

    def test_each_monitor_check_is_a_stage6_span_under_the_websocket(
            self, traced: TracedServer) -> None:
        gate = httpx.post(traced.base_url + "/gate", json=KNIFE_REQUEST, timeout=60).json()
        opened = httpx.post(traced.base_url + "/monitor", timeout=60,
                            json={"contract_id": gate["contract_id"]}).json()
        session_id = opened["session_id"]
        ws_path = f"/monitor/{session_id}"
        ws_url = traced.base_url.replace("http", "ws") + ws_path
        with connect(ws_url) as socket_:
            for kind in ("before", "after"):
                socket_.send(json.dumps({"type": kind, "seq": 1, "action": GOOD_PLAN[0]}))
                answer = json.loads(socket_.recv(timeout=30))
                assert answer["type"] == "allow", answer
        deadline = time.monotonic() + 10
        while not (sockets := [s for s in traced.named("WEBSOCKET /monitor/{session_id}")
                               if (s.attributes or {}).get("http.target") == ws_path]):
            assert time.monotonic() < deadline, "the websocket's span never ended"
            time.sleep(0.05)
        checks = _children(sockets[0], traced.spans())
        assert [s.name for s in checks] == ["safegate.stage6.monitor_check"] * 2
        for check in checks:
            assert (check.attributes or {})["safegate.verdict"] == "allow"
            assert (check.attributes or {})["safegate.session_id"] == session_id


class _BrokenExporter(SpanExporter):
    def export(self, spans: Sequence[ReadableSpan]) -> SpanExportResult:
        raise ConnectionError("the collector is down")


class TestFailsOpenForTracingOnly:
    def test_an_exporter_that_fails_changes_no_decision(
            self, tmp_path: Path, traced: TracedServer) -> None:
        settings = Settings(database_url=f"sqlite:///{tmp_path / 'broken.db'}",
                            otel_enabled=True, gate_workers=1)
        app = create_app(settings, span_exporter=_BrokenExporter())
        for server in _serve(app, InMemorySpanExporter()):
            response = httpx.post(server.base_url + "/gate", json=KNIFE_REQUEST, timeout=60)
            app.state.tracing.force_flush()
            expected = httpx.post(traced.base_url + "/gate", json=KNIFE_REQUEST, timeout=60)
            assert response.status_code == 200
            assert response.json()["decision"] == expected.json()["decision"] == "authorize"
            assert response.json()["rule"] == expected.json()["rule"]


class TestOffByDefault:
    def test_the_default_app_traces_nothing_and_imports_no_sdk(self, tmp_path: Path) -> None:
        script = (
            "import sys\n"
            "from app.config import Settings\n"
            "from app.main import create_app\n"
            f"app = create_app(Settings(database_url='sqlite:///{tmp_path / 'off.db'}'))\n"
            "assert app.state.tracing.enabled is False\n"
            "assert not [m for m in sys.modules if m.startswith('opentelemetry.sdk')]\n"
        )
        subprocess.run([sys.executable, "-c", script], cwd=REPO, check=True, timeout=120)

    def test_without_opentelemetry_installed_the_server_serves_untraced(
            self, tmp_path: Path) -> None:
        script = (
            "import sys\n"
            # As if the otel extra were not installed (FastAPI itself needs opentelemetry-api).
            "sys.modules['opentelemetry.sdk'] = None\n"
            "sys.modules['opentelemetry.instrumentation'] = None\n"
            "from fastapi.testclient import TestClient\n"
            "from app.config import Settings\n"
            "from app.main import create_app\n"
            f"settings = Settings(database_url='sqlite:///{tmp_path / 'none.db'}',\n"
            "                    otel_enabled=True, gate_workers=1)\n"
            "app = create_app(settings)\n"
            "assert app.state.tracing.enabled is False\n"
            "with TestClient(app) as client:\n"
            "    assert client.get('/readyz').status_code == 200\n"
        )
        result = subprocess.run([sys.executable, "-c", script], cwd=REPO, timeout=120,
                                capture_output=True, text=True)
        assert result.returncode == 0, result.stderr[-3000:]
