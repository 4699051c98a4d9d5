"""The task's scope over HTTP: stored with the contract, shown by GET /contracts, enforced by
POST /verify and by the monitor (opened with POST /monitor, stepped over its websocket).

Issue 17's request: "Bring Dad his hot tea from the kitchen counter; it's in the lidded travel
mug", with a knife on the same counter. Step numbers on the wire count from 0, so the issue's
"step 4" (the throw) is `step` 3.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import httpx
from fastapi.testclient import TestClient

from app.domain.models import GateRequest
from app.store.records import ContractRecord, GateRecord
from app.store.repository import Repository
from tests.scope_kit import GOOD_PLAN, KNIFE_PLAN, TEA_REQUEST, THROW_PLAN, walking

CLAUSE = "Bring Dad his hot tea from the kitchen counter"
ENVELOPE_THROW = "baseline.no_throwing_at_people.throw_only_soft_things_never_at_people"


def authorized(client: TestClient) -> str:
    body = client.post("/gate", json=TEA_REQUEST).json()
    assert body["decision"] == "authorize", body
    contract_id: str = body["contract_id"]
    return contract_id


def run(socket: Any, plan: list[dict[str, Any]]) -> dict[str, Any]:
    """Send the plan's messages until one is not allowed; that answer."""
    for seq, action in enumerate(plan):
        for kind in ("before", "after"):
            socket.send_json({"type": kind, "seq": seq, "action": action})
            answer: dict[str, Any] = socket.receive_json()
            if answer["type"] != "allow":
                return answer
    return {"type": "allow"}


def open_session(client: TestClient, contract_id: str) -> str:
    response = client.post("/monitor", json={"contract_id": contract_id})
    assert response.status_code == 201, response.text
    session_id: str = response.json()["session_id"]
    return session_id


class TestContractShowsTheScope:
    def test_the_contract_lists_what_the_command_authorizes(self, client_on: TestClient) -> None:
        body = client_on.get(f"/contracts/{authorized(client_on)}").json()
        scope = body["scope"]
        assert scope["command"] == TEA_REQUEST["command"]
        steps = {(s["action"], s["object"], s["target"]): s for s in scope["steps"]}
        assert steps[("HandOver", "mug_1", "dad")]["words"] == CLAUSE
        assert "GoToObject" in scope["enabling"] and scope["move_aside"] is True
        assert any(c["envelope"] for c in body["guards"])

    def test_the_planner_format_says_envelope_and_scope_in_words(
            self, client: TestClient) -> None:
        text = client.get(f"/contracts/{authorized(client)}?format=planner").text
        assert "- For every task (baseline envelope)." in text
        assert f'- Task scope: For "{CLAUSE}" the task authorizes: ' in text
        assert "HandOver mug_1 -> dad" in text


class TestVerifyChecksTheScope:
    def test_the_hot_mug_throw_is_caught_at_step_four(self, client_on: TestClient) -> None:
        body = client_on.post("/verify", json={"contract_id": authorized(client_on),
                                               "plan": THROW_PLAN}).json()
        assert body["ok"] is False
        at_throw = {(v["kind"], v["condition_id"]): v for v in body["violations"]
                    if v["step"] == 3}
        # The envelope catches it, and so does the scope, quoting the command.
        assert ("guard", ENVELOPE_THROW) in at_throw
        scope = at_throw[("scope", "scope.action")]
        assert scope["quote"] == CLAUSE and f'"{CLAUSE}"' in scope["description"]
        assert scope["action"] == {"action": "ThrowObject", "object": "mug_1", "target": "dad"}

    def test_the_knife_for_dad_is_flagged_where_it_leaves_the_task(
            self, client_on: TestClient) -> None:
        body = client_on.post("/verify", json={"contract_id": authorized(client_on),
                                               "plan": KNIFE_PLAN}).json()
        assert body["ok"] is False
        first = body["violations"][0]
        assert (first["step"], first["kind"], first["condition_id"]) == (1, "scope",
                                                                          "scope.aside")
        assert first["action"] == {"action": "PickupObject", "object": "knife_1"}
        assert first["quote"] == CLAUSE

    def test_the_careful_plan_passes(self, client: TestClient) -> None:
        body = client.post("/verify", json={"contract_id": authorized(client),
                                            "plan": GOOD_PLAN}).json()
        assert body["ok"] is True, body["violations"]


class TestMonitorEnforcesTheScope:
    def test_the_throw_is_halted_at_that_action(self, client_on: TestClient) -> None:
        session_id = open_session(client_on, authorized(client_on))
        with client_on.websocket_connect(f"/monitor/{session_id}") as socket:
            answer = run(socket, walking(THROW_PLAN))
        assert answer["type"] == "violation" and answer["seq"] == 3 and answer["halted"]
        assert answer["violation"]["action"]["action"] == "ThrowObject"
        assert answer["violation"]["phase"] == "before"

    def test_handing_dad_the_knife_is_halted_as_out_of_scope(
            self, client_on: TestClient) -> None:
        session_id = open_session(client_on, authorized(client_on))
        with client_on.websocket_connect(f"/monitor/{session_id}") as socket:
            answer = run(socket, KNIFE_PLAN)
        assert (answer["type"], answer["seq"]) == ("violation", 4)
        violation = answer["violation"]
        assert (violation["kind"], violation["condition_id"]) == ("scope", "scope.object")
        assert violation["quote"] == CLAUSE
        summary = client_on.get(f"/monitor/{session_id}/summary").json()
        assert summary["halted"] and summary["violations"][0]["quote"] == CLAUSE

    def test_the_careful_plan_runs_to_the_end(self, client: TestClient) -> None:
        session_id = open_session(client, authorized(client))
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            assert run(socket, GOOD_PLAN) == {"type": "allow"}


def _store_pre_scope_contract(client: TestClient) -> str:
    """A contract as stored before scopes existed: no `scope` key, no `envelope` flags."""
    contract_id = authorized(client)
    repository = Repository(client.app.state.components.engine)  # type: ignore[attr-defined]
    body = repository.get_contract(contract_id).contract
    body.pop("scope")
    for kind in ("invariants", "guards", "aborts"):
        for condition in body[kind]:
            condition.pop("envelope")
    record = repository.save_gate_record(GateRecord(
        request=GateRequest.model_validate(TEA_REQUEST), decision="authorize", rule="R4"))
    assert record.id is not None
    stored = repository.save_contract(ContractRecord(request_id=record.id, contract=body,
                                                     max_attempts=3))
    assert stored.id is not None
    return stored.id


class TestContractsFromBeforeScopes:
    def test_they_keep_working_without_a_scope_check(self, client_on: TestClient) -> None:
        contract_id = _store_pre_scope_contract(client_on)
        assert client_on.get(f"/contracts/{contract_id}").json()["scope"] is None
        verified = client_on.post("/verify", json={"contract_id": contract_id,
                                                   "plan": KNIFE_PLAN}).json()
        assert verified["ok"] is True  # documented: no scope stored, no scope checked
        session_id = open_session(client_on, contract_id)
        with client_on.websocket_connect(f"/monitor/{session_id}") as socket:
            assert run(socket, KNIFE_PLAN) == {"type": "allow"}


class TestOverRealHttp:
    def test_gate_verify_and_monitor_on_a_live_server(
            self, live_server: Callable[..., Any]) -> None:
        import websockets.sync.client as ws

        server = live_server()
        with httpx.Client(base_url=server.base_url, timeout=30) as http:
            contract_id = http.post("/gate", json=TEA_REQUEST).json()["contract_id"]
            verified = http.post("/verify", json={"contract_id": contract_id,
                                                  "plan": KNIFE_PLAN}).json()
            assert verified["violations"][0]["kind"] == "scope"
            session_id = http.post("/monitor", json={"contract_id": contract_id}).json()[
                "session_id"]
        with ws.connect(server.ws_url + f"/monitor/{session_id}") as socket:
            answer: dict[str, Any] = {}
            for seq, action in enumerate(KNIFE_PLAN):
                for kind in ("before", "after"):
                    socket.send(json.dumps({"type": kind, "seq": seq, "action": action}))
                    answer = json.loads(socket.recv(timeout=10))
                    if answer["type"] != "allow":
                        break
                if answer["type"] != "allow":
                    break
        assert (answer["type"], answer["seq"]) == ("violation", 4)
        assert answer["violation"]["kind"] == "scope"
