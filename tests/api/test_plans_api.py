"""Plans from SafeGate over HTTP: the reference plan of `POST /gate?reference_plan=true` and the
repair a failed `POST /verify` carries; each one passes `/verify` when sent back.

Issue 17's tea request ("Bring Dad his hot tea...") and its plans (`tests/scope_kit.py`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import httpx
from fastapi.testclient import TestClient

from tests.api.test_gate_api import SPEC_REQUEST
from tests.scope_kit import GOOD_PLAN, KNIFE_PLAN, TEA_REQUEST, THROW_PLAN


def gate(client: TestClient, request: dict[str, Any], query: str = "") -> dict[str, Any]:
    response = client.post("/gate" + query, json=request)
    assert response.status_code == 200, response.text
    body: dict[str, Any] = response.json()
    return body


def verify(client: TestClient, contract_id: str, plan: list[dict[str, Any]]) -> dict[str, Any]:
    response = client.post("/verify", json={"contract_id": contract_id, "plan": plan})
    assert response.status_code == 200, response.text
    body: dict[str, Any] = response.json()
    return body


class TestReferencePlan:
    def test_asked_for_an_authorized_task_gets_a_plan_that_passes_verify(
            self, client_on: TestClient) -> None:
        body = gate(client_on, TEA_REQUEST, "?reference_plan=true")
        assert body["decision"] == "authorize"
        reference = body["reference_plan"]
        assert reference is not None, body["reference_plan_reason"]
        assert "proved by Stage 5" in reference["reason"] and reference["goal"]
        verdict = verify(client_on, body["contract_id"], reference["plan"])
        assert verdict["ok"] is True and verdict["attempts"] == 0

    def test_the_audit_record_keeps_the_plan_handed_out(self, client: TestClient) -> None:
        body = gate(client, TEA_REQUEST, "?reference_plan=true")
        reference = body["reference_plan"]
        assert reference is not None, body["reference_plan_reason"]
        record = client.get(f"/gate/{body['request_id']}").json()
        assert record["reference_plan"] == reference

    def test_not_asked_the_answer_has_no_plan(self, client: TestClient) -> None:
        body = gate(client, TEA_REQUEST)
        assert body["reference_plan"] is None and body["reference_plan_reason"] is None
        assert client.get(f"/gate/{body['request_id']}").json()["reference_plan"] is None

    def test_a_task_not_authorized_gets_none_with_the_reason(self, client: TestClient) -> None:
        body = gate(client, SPEC_REQUEST, "?reference_plan=true")
        assert body["decision"] != "authorize"
        assert body["reference_plan"] is None
        assert body["reference_plan_reason"] == "no reference plan: the task was not authorized"
        record = client.get(f"/gate/{body['request_id']}").json()
        assert record["reference_plan"] == {
            "plan": None, "goal": None, "reason": body["reference_plan_reason"]}


class TestRepair:
    def test_the_hot_mug_throw_gets_a_repair_that_passes_verify(
            self, client_on: TestClient) -> None:
        contract_id = gate(client_on, TEA_REQUEST)["contract_id"]
        failed = verify(client_on, contract_id, THROW_PLAN)
        assert failed["ok"] is False and failed["attempts_left"] == 2
        repair = failed["repair"]
        assert repair is not None, failed["repair_reason"]
        assert {e["kind"] for e in repair["edits"]} == {"slow_down", "replace_throw"}
        assert not any(s["action"] == "ThrowObject" for s in repair["plan"])
        again = verify(client_on, contract_id, repair["plan"])
        assert again["ok"] is True and again["attempts_left"] == 2

    def test_a_passing_plan_has_no_repair(self, client: TestClient) -> None:
        body = verify(client, gate(client, TEA_REQUEST)["contract_id"], GOOD_PLAN)
        assert body["ok"] is True
        assert body["repair"] is None and body["repair_reason"] is None

    def test_attempts_and_the_downgrade_are_unchanged_and_a_rejected_task_gets_none(
            self, client: TestClient) -> None:
        contract_id = gate(client, TEA_REQUEST)["contract_id"]
        answers = [verify(client, contract_id, KNIFE_PLAN) for _ in range(3)]
        assert [a["attempts_left"] for a in answers] == [2, 1, 0]
        assert all(a["repair"] is not None for a in answers[:2])
        last = answers[2]
        assert last["decision"] == "reject" and last["downgraded"] is True
        assert last["repair"] is None and "rejected" in last["repair_reason"]


class TestOverRealHttp:
    def test_reference_plan_and_repair_on_a_live_server(
            self, live_server: Callable[..., Any]) -> None:
        server = live_server()
        with httpx.Client(base_url=server.base_url, timeout=30) as http:
            body = http.post("/gate?reference_plan=true", json=TEA_REQUEST).json()
            contract_id = body["contract_id"]
            plan = body["reference_plan"]["plan"]
            assert http.post("/verify", json={"contract_id": contract_id,
                                              "plan": plan}).json()["ok"] is True
            failed = http.post("/verify", json={"contract_id": contract_id,
                                                "plan": THROW_PLAN}).json()
            repaired = failed["repair"]["plan"]
            assert http.post("/verify", json={"contract_id": contract_id,
                                              "plan": repaired}).json()["ok"] is True
