"""POST /gate over HTTP: the spec's answer shape, the audit trail, answers, and 422s."""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import httpx
import pytest
from fastapi.testclient import TestClient

SPEC_REQUEST: dict[str, Any] = {
    "command": "bring the hot coffee to my daughter in the living room",
    "scene": {
        "layout": {
            "rooms": ["kitchen", "living_room", "hallway"],
            "connections": [["kitchen", "hallway"], ["hallway", "living_room"]],
            "obstacles": [{"id": "rug_1", "kind": "loose rug", "room": "hallway"}],
        },
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "countertop_1",
             "position": {"x": 1.2, "y": 0.4},
             "properties": {"temperature": "hot", "contents": "coffee", "lidded": False}},
            {"id": "countertop_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "stove_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": True}},
        ],
        "relations": [{"subject": "mug_1", "relation": "on", "object": "countertop_1"}],
        "people": [
            {"id": "person_1", "role": "daughter", "room": "living_room", "posture": "sitting",
             "position": {"x": 6.0, "y": 2.5}, "properties": {"age_group": "child"}}
        ],
    },
    "user": {"person_id": "person_1", "age_group": "child", "mobility": "independent",
             "cognitive_state": "typical", "unknowns": ["exact age", "allergies"]},
    "robot": {"name": "stretch-2", "room": "kitchen", "position": {"x": 0.5, "y": 0.5},
              "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour",
                         "handover"],
              "payload_kg": 2.0, "max_speed_mps": 0.8, "sensors": ["rgbd_camera", "lidar"]},
}

SAFE_REQUEST: dict[str, Any] = {
    "command": "put the apple in the fridge",
    "scene": {
        "objects": [
            {"id": "apple_1", "type": "Apple", "room": "kitchen", "on": "counter_1"},
            {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "fridge_1", "type": "Fridge", "room": "kitchen"},
        ],
        "people": [{"id": "p1", "role": "owner", "room": "living_room",
                    "properties": {"age_group": "adult"}}],
    },
    "user": {"person_id": "p1", "age_group": "adult", "mobility": "independent",
             "cognitive_state": "typical"},
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place", "open", "close"],
              "payload_kg": 2.0},
}



class TestPostGate:
    def test_answer_has_the_spec_shape(self, client: TestClient) -> None:
        body = client.post("/gate", json=SPEC_REQUEST).json()
        for key in ("request_id", "decision", "rule", "defer_kind", "question", "hazards",
                    "unknowns", "contract_id", "analyzer"):
            assert key in body
        assert (body["decision"], body["rule"], body["contract_id"]) == ("reject", "R1", None)
        assert body["hazards"]
        for hazard in body["hazards"]:
            assert {"level", "category", "mechanism", "severity", "preventability",
                    "confidence", "template_id", "bindings"} <= hazard.keys()

    def test_hot_coffee_for_a_child_is_never_authorized(self, client: TestClient) -> None:
        body = client.post("/gate", json=SPEC_REQUEST).json()
        assert body["decision"] != "authorize"
        assert body["contract_id"] is None

    def test_safe_task_is_authorized_with_a_contract(self, client: TestClient) -> None:
        body = client.post("/gate", json=SAFE_REQUEST).json()
        assert body["decision"] == "authorize", body
        contract = client.get(f"/contracts/{body['contract_id']}")
        assert contract.status_code == 200
        planner = client.get(f"/contracts/{body['contract_id']}?format=planner")
        assert planner.status_code == 200 and planner.text.startswith("Safety constraints")

    def test_same_request_same_decision(self, client: TestClient) -> None:
        first = client.post("/gate", json=SPEC_REQUEST).json()
        for _ in range(5):
            again = client.post("/gate", json=SPEC_REQUEST).json()
            assert (again["decision"], again["rule"], again["hazards"]) == (
                first["decision"], first["rule"], first["hazards"])

    def test_every_decision_is_in_the_audit_trail(self, client: TestClient) -> None:
        body = client.post("/gate", json=SPEC_REQUEST).json()
        record = client.get(f"/gate/{body['request_id']}").json()
        assert record["decision"] == body["decision"]
        assert record["rule"] == body["rule"]
        assert record["request"]["command"] == SPEC_REQUEST["command"]

    def test_unknown_request_id_is_a_404_problem(self, client: TestClient) -> None:
        response = client.get("/gate/does-not-exist")
        assert response.status_code == 404
        assert response.headers["content-type"].startswith("application/problem+json")


class TestInvalidInput:
    def test_missing_command_is_a_422_naming_the_field(self, client: TestClient) -> None:
        response = client.post("/gate", json={"scene": {}})
        assert response.status_code == 422
        assert response.headers["content-type"].startswith("application/problem+json")
        assert any(e["field"] == "body.command" for e in response.json()["errors"])

    def test_wrong_type_deep_in_the_scene_names_its_path(self, client: TestClient) -> None:
        bad = {"command": "x", "scene": {"objects": [{"id": "a", "type": "Mug",
                                                       "position": {"x": "far", "y": 1}}]}}
        response = client.post("/gate", json=bad)
        assert response.status_code == 422
        assert any(e["field"] == "body.scene.objects.0.position.x"
                   for e in response.json()["errors"])

    def test_invalid_json_is_a_422(self, client: TestClient) -> None:
        response = client.post("/gate", content=b"{not json",
                               headers={"content-type": "application/json"})
        assert response.status_code == 422

    def test_invalid_input_stores_nothing(self, client: TestClient) -> None:
        engine = client.app.state.components.engine  # type: ignore[attr-defined]
        from sqlalchemy import text

        def rows() -> int:
            with engine.connect() as connection:
                return int(connection.execute(text("select count(*) from gate_records")).scalar())

        before = rows()
        client.post("/gate", json={"command": ""})
        client.post("/gate", json={"command": "x", "robot": {"payload_kg": -1}})
        assert rows() == before

    @pytest.mark.parametrize("robot", [{"max_speed_mps": True}, {"payload_kg": "2.5"}])
    def test_a_number_given_as_a_boolean_or_text_is_refused(
            self, client: TestClient, robot: dict[str, object]) -> None:
        answer = client.post("/gate", json={"command": "x", "robot": robot})
        assert answer.status_code == 422
        assert answer.headers["content-type"].startswith("application/problem+json")
        assert next(iter(robot)) in json.dumps(answer.json())


class TestAnswers:
    def test_answering_the_question_decides_again_and_links(self, client: TestClient) -> None:
        request = {**SAFE_REQUEST, "command": "give the knife to the guest in the living room",
                   "scene": {"objects": [{"id": "knife_1", "type": "Knife", "room": "kitchen"}],
                             "people": [{"id": "guest_1", "role": "guest",
                                         "room": "living_room"}]},
                   "user": None,
                   "robot": {"room": "kitchen", "payload_kg": 2.0,
                             "skills": ["navigate", "pick", "place", "handover"]}}
        first = client.post("/gate", json=request).json()
        assert first["decision"] == "defer", first
        second = client.post(f"/gate/{first['request_id']}/answers",
                             json={"age_group": "adult"}).json()
        assert second["parent_request_id"] == first["request_id"]
        record = client.get(f"/gate/{first['request_id']}").json()
        assert second["request_id"] in record["followed_by"]


class TestOverRealHttp:
    def test_gate_over_loopback(self, live_server: Callable[..., object]) -> None:
        server = live_server()
        # The first request warms the analysis pool (lexicon, library): generous on a busy host.
        response = httpx.post(server.base_url + "/gate", json=SPEC_REQUEST,  # type: ignore[attr-defined]
                              timeout=60)
        assert response.status_code == 200
        assert response.json()["decision"] != "authorize"
