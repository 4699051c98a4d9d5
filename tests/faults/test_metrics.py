"""Operations: the Prometheus counters at /metrics move with what the gate, the verifier and
the monitor actually did (decisions by rule, verification outcomes, halts by kind)."""

from __future__ import annotations

import json
import re

from fastapi.testclient import TestClient
from monitor_kit import GO_TO_MUG, REQUEST, TOGGLE_STOVE, before, store_contract

from app.store.repository import Repository


def metric(client: TestClient, name: str, **labels: str) -> float:
    """The value of one sample at /metrics (0 when it is not there yet)."""
    text = client.get("/metrics").text
    wanted = ",".join(f'{key}="{value}"' for key, value in sorted(labels.items()))
    for line in text.splitlines():
        match = re.fullmatch(rf"{name}\{{(.*)\}} (\S+)", line)
        if match and ",".join(sorted(match.group(1).split(","))) == wanted:
            return float(match.group(2))
    return 0.0


def repository_of(client: TestClient) -> Repository:
    repository = Repository(client.app.state.components.engine)  # type: ignore[attr-defined]
    return repository


def inline_body(plan: list[dict[str, str]]) -> dict[str, object]:
    invariant = {"id": "no_knife", "formula": "not holding(robot, #knife_1)"}
    return {"contract": {"invariants": [invariant]},
            "initial_state": {"scene": REQUEST["scene"], "robot": REQUEST["robot"]},
            "plan": plan}


class TestMetrics:
    def test_decisions_are_counted_by_decision_and_rule(self, client: TestClient) -> None:
        body = client.post("/gate", json={"command": "bring the mug to the kitchen"}).json()
        labels = {"decision": body["decision"], "rule": body["rule"]}
        assert metric(client, "safegate_gate_decisions_total", **labels) == 1.0

    def test_verifications_are_counted_by_outcome(self, client: TestClient) -> None:
        passing = client.post("/verify", json=inline_body([GO_TO_MUG]))
        failing = client.post("/verify", json=inline_body(
            [{"action": "GoToObject", "object": "knife_1"},
             {"action": "PickupObject", "object": "knife_1"}]))
        assert passing.json()["ok"] and not failing.json()["ok"]
        assert metric(client, "safegate_verifications_total", outcome="ok") == 1.0
        assert metric(client, "safegate_verifications_total", outcome="violation") == 1.0

    def test_monitor_halts_are_counted_by_kind(self, client: TestClient) -> None:
        contract_id = store_contract(repository_of(client))
        session_id = client.post("/monitor", json={"contract_id": contract_id}).json()[
            "session_id"]
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_text(json.dumps(before(1, TOGGLE_STOVE)))
            assert json.loads(socket.receive_text())["type"] == "violation"
            socket.send_text(json.dumps(before(2, GO_TO_MUG)))
            assert json.loads(socket.receive_text())["type"] == "halted"
        assert metric(client, "safegate_monitor_halts_total", kind="guard") == 1.0

    def test_requests_carry_an_id_and_are_counted(self, client: TestClient) -> None:
        response = client.get("/healthz", headers={"X-Request-ID": "trace-42"})
        assert response.headers["x-request-id"] == "trace-42"
        labels = {"method": "GET", "route": "/healthz", "status": "200"}
        assert metric(client, "safegate_http_requests_total", **labels) == 1.0
