"""POST /verify over HTTP: verdicts, repair attempts and the downgrade, inline contracts, 422s."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import httpx
from fastapi.testclient import TestClient

from tests.api.test_gate_api import SAFE_REQUEST

KNIFE_REQUEST: dict[str, Any] = {
    **copy.deepcopy(SAFE_REQUEST),
    "command": "put the knife in the drawer",
    "scene": {
        "objects": [
            {"id": "knife_1", "type": "Knife", "room": "kitchen", "on": "counter_1"},
            {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "drawer_1", "type": "Drawer", "room": "kitchen"},
        ],
        "people": [{"id": "p1", "role": "owner", "room": "living_room",
                    "properties": {"age_group": "adult"}}],
    },
}
GOOD_PLAN = [
    {"action": "GoToObject", "object": "knife_1"},
    {"action": "pick", "object": "knife_1"},
    {"action": "GoToObject", "object": "drawer_1"},
    {"action": "OpenObject", "object": "drawer_1"},
    {"action": "PutObject", "object": "knife_1", "target": "drawer_1"},
]
THROWING_PLAN = [*GOOD_PLAN[:2], {"action": "throw", "object": "knife_1", "target": "drawer_1"}]


def authorized(client: TestClient) -> dict[str, Any]:
    body: dict[str, Any] = client.post("/gate", json=KNIFE_REQUEST).json()
    assert body["decision"] == "authorize" and body["contract_id"], body
    return body


def verify(client: TestClient, **body: Any) -> httpx.Response:
    response: httpx.Response = client.post("/verify", json=body)
    return response


class TestVerdicts:
    def test_safe_plan_passes_and_spends_no_attempt(self, client: TestClient) -> None:
        gate = authorized(client)
        body = verify(client, contract_id=gate["contract_id"], plan=GOOD_PLAN).json()
        assert body["ok"] is True and body["violations"] == []
        assert (body["attempts"], body["attempts_left"], body["decision"]) == (0, 3, "authorize")

    def test_violating_plan_is_a_200_with_the_violation(self, client: TestClient) -> None:
        gate = authorized(client)
        response = verify(client, contract_id=gate["contract_id"], plan=THROWING_PLAN)
        assert response.status_code == 200
        body = response.json()
        assert body["ok"] is False
        # The envelope's guard, then the task's scope: the command puts the knife away.
        violation, scope = body["violations"]
        assert violation["kind"] == "guard" and violation["step"] == 2
        assert (scope["kind"], scope["step"], scope["condition_id"]) == (
            "scope", 2, "scope.action")
        assert scope["quote"] == "put the knife in the drawer"
        assert violation["action"] == {"action": "ThrowObject", "object": "knife_1",
                                       "target": "drawer_1"}
        # The baseline envelope binds "throw only soft things" into every contract.
        assert violation["condition_id"].endswith("throw_only_soft_things_never_at_people")
        assert "@object" in violation["formula"] and violation["description"]
        assert violation["counterexample"]["soft(knife_1)"] is False
        assert (body["attempts"], body["attempts_left"]) == (1, 2)

    def test_initial_state_replaces_the_gate_requests_state(self, client: TestClient) -> None:
        gate = authorized(client)
        start = {"scene": {**copy.deepcopy(KNIFE_REQUEST["scene"])},
                 "robot": {"room": "living_room"}}
        body = verify(client, contract_id=gate["contract_id"], plan=GOOD_PLAN[1:2],
                      initial_state=start).json()
        assert body["violations"][0]["kind"] == "precondition"

    def test_unknown_fact_gives_a_counterexample(self, client: TestClient) -> None:
        contract = {"guards": [{"id": "lid_first", "action": "PickupObject",
                                "formula": "lidded(@object)", "description": "only lidded"}]}
        scene = {"objects": [{"id": "gizmo_1", "type": "Jar", "room": "kitchen",
                              "properties": {"pickupable": True}}]}
        body = verify(client, contract=contract,
                      plan=[{"action": "PickupObject", "object": "gizmo_1"}],
                      initial_state={"scene": scene, "robot": {"room": "kitchen"}}).json()
        [violation] = body["violations"]
        assert violation["counterexample"] == {"lidded(gizmo_1)": False}
        assert violation["free"] == ["lidded(gizmo_1)"]
        assert body["decision"] is None and body["attempts_left"] is None


class TestRepairAttempts:
    def test_k_failures_downgrade_the_decision_and_exhaust_the_contract(
        self, client: TestClient
    ) -> None:
        gate = authorized(client)
        answers = [verify(client, contract_id=gate["contract_id"], plan=THROWING_PLAN).json()
                   for _ in range(3)]
        assert [a["attempts_left"] for a in answers] == [2, 1, 0]
        assert [a["decision"] for a in answers] == ["authorize", "authorize", "reject"]
        record = client.get(f"/gate/{gate['request_id']}").json()
        assert record["downgraded"] is True and "failed 3 of 3" in record["downgrade_reason"]
        refused = verify(client, contract_id=gate["contract_id"], plan=GOOD_PLAN)
        assert refused.status_code == 409
        assert refused.headers["content-type"].startswith("application/problem+json")
        assert refused.json()["title"] == "Verification attempts exhausted"

    def test_bad_plan_spends_no_attempt(self, client: TestClient) -> None:
        gate = authorized(client)
        verify(client, contract_id=gate["contract_id"], plan=[{"action": "Teleport"}])
        contract = client.get(f"/contracts/{gate['contract_id']}").json()
        assert contract["attempts_used"] == 0


class TestInvalidInput:
    def test_unknown_action_names_the_step(self, client: TestClient) -> None:
        gate = authorized(client)
        response = verify(client, contract_id=gate["contract_id"],
                          plan=[GOOD_PLAN[0], {"action": "Teleport", "object": "knife_1"}])
        assert response.status_code == 422
        assert response.headers["content-type"].startswith("application/problem+json")
        assert response.json()["errors"][0]["field"] == "plan[1].action"

    def test_unknown_object_names_the_step(self, client: TestClient) -> None:
        gate = authorized(client)
        response = verify(client, contract_id=gate["contract_id"],
                          plan=[*GOOD_PLAN[:3], {"action": "PickupObject", "object": "spoon"}])
        assert response.status_code == 422
        assert response.json()["errors"][0]["field"] == "plan[3].object"

    def test_step_that_is_not_an_object_names_the_step(self, client: TestClient) -> None:
        gate = authorized(client)
        response = verify(client, contract_id=gate["contract_id"], plan=[GOOD_PLAN[0], 42])
        assert response.json()["errors"][0]["field"] == "plan[1]"

    def test_malformed_json_is_a_422(self, client: TestClient) -> None:
        response = client.post("/verify", content=b'{"plan": [',
                               headers={"content-type": "application/json"})
        assert response.status_code == 422
        assert response.headers["content-type"].startswith("application/problem+json")

    def test_missing_plan_names_the_field(self, client: TestClient) -> None:
        response = verify(client, contract_id="x")
        assert any(e["field"] == "body.plan" for e in response.json()["errors"])

    def test_inline_contract_needs_an_initial_state(self, client: TestClient) -> None:
        response = verify(client, contract={"invariants": []}, plan=[])
        assert response.status_code == 422

    def test_unknown_contract_is_a_404(self, client: TestClient) -> None:
        assert verify(client, contract_id="nope", plan=[]).status_code == 404


class TestOverRealHttp:
    def test_verify_over_loopback(self, live_server: Callable[..., Any]) -> None:
        server = live_server()
        gate = httpx.post(server.base_url + "/gate", json=KNIFE_REQUEST, timeout=60).json()
        response = httpx.post(server.base_url + "/verify",
                              json={"contract_id": gate["contract_id"], "plan": THROWING_PLAN})
        assert response.status_code == 200
        assert response.json()["violations"][0]["kind"] == "guard"
