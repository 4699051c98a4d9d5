"""Template writes over HTTP: drafts, versions, activation, deprecation and live validation."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient

from app.services.access import issue_api_key
from app.store.records import ApiKeyRole

SAFE_SCENE_REQUEST: dict[str, Any] = {
    "command": "Slice the sourdough on the board, four thick slices.",
    "scene": {
        "objects": [
            {"id": "countertop_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "bread_1", "type": "Bread", "room": "kitchen", "on": "board_1"},
            {"id": "board_1", "type": "CuttingBoard", "room": "kitchen", "on": "countertop_1"},
            {"id": "knife_1", "type": "BreadKnife", "room": "kitchen", "on": "countertop_1",
             "properties": {"sharp": True}},
        ],
        "people": [{"id": "p1", "role": "cook", "room": "kitchen",
                    "properties": {"age_group": "adult"}}],
    },
    "user": {"person_id": "p1", "age_group": "adult", "unknowns": []},
    "robot": {"room": "kitchen", "payload_kg": 3.0, "max_speed_mps": 1.0,
              "skills": ["navigate", "pick", "place", "slice"], "sensors": ["rgbd_camera"]},
}


def curator(client: TestClient) -> dict[str, str]:
    access = client.app.state.components.repositories.access  # type: ignore[attr-defined]
    _, secret = issue_api_key(access, ApiKeyRole.CURATOR, "cur")
    return {"Authorization": f"Bearer {secret}"}


def new_template(**changes: Any) -> dict[str, Any]:
    document: dict[str, Any] = {
        "id": "sharp.blade_left_on_edge",
        "name": "Blade left on a counter edge",
        "category": "physical",
        "hazard_class": "sharp_laceration",
        "description": "A knife left overhanging a counter edge falls on a foot.",
        "severity": "moderate",
        "preventability": "preventable",
        "variables": [{"name": "obj", "type": "object", "description": "the blade"}],
        "guards": [{"id": "never_drop_blade", "action": "DropHandObject",
                    "formula": "not holding(robot, $obj) or not sharp($obj)",
                    "description": "Never let go of a sharp blade in mid-air."}],
    }
    document.update(changes)
    return document


class TestTemplateWrites:
    def test_draft_is_stored_but_not_bound(self, client: TestClient) -> None:
        body = client.post("/templates", json=new_template(), headers=curator(client)).json()
        assert (body["status"], body["version"], body["source"]) == ("draft", 1, "user")
        index = client.app.state.components.templates.index()
        assert "sharp.blade_left_on_edge" not in {t.id for t in index.for_class("sharp_laceration")}

    def test_duplicate_hazard_class_is_a_warning_not_a_refusal(self, client: TestClient) -> None:
        answer = client.post("/templates", json=new_template(), headers=curator(client))
        assert answer.status_code == 201
        codes = {w["code"] for w in answer.json()["warnings"]}
        assert "duplicate_class" in codes

    def test_existing_id_is_a_conflict(self, client: TestClient) -> None:
        headers = curator(client)
        client.post("/templates", json=new_template(), headers=headers)
        assert client.post("/templates", json=new_template(), headers=headers).status_code == 409

    def test_new_version_keeps_the_old_one_readable(self, client: TestClient) -> None:
        headers = curator(client)
        client.post("/templates", json=new_template(), headers=headers)
        revised = client.put("/templates/sharp.blade_left_on_edge",
                             json=new_template(name="Blade left near an edge"), headers=headers)
        assert revised.json()["version"] == 2
        history = client.get("/templates/sharp.blade_left_on_edge").json()
        assert [v["version"] for v in history["versions"]] == [1, 2]
        first = client.get("/templates/sharp.blade_left_on_edge/versions/1").json()
        assert first["name"] == "Blade left on a counter edge"

    def test_revision_of_an_active_template_reaches_the_gate_and_its_contracts(
        self, client: TestClient
    ) -> None:
        headers = curator(client)
        client.post("/templates", json=new_template(), headers=headers)
        client.post("/templates/sharp.blade_left_on_edge/activate", headers=headers)
        client.put("/templates/sharp.blade_left_on_edge", json=new_template(), headers=headers)
        decided = client.post("/gate", json=SAFE_SCENE_REQUEST).json()
        assert decided["decision"] == "authorize", decided
        contract = client.get(f"/contracts/{decided['contract_id']}").json()
        assert contract["template_versions"]["sharp.blade_left_on_edge"] == 2

    def test_deprecated_templates_are_no_longer_bound(self, client: TestClient) -> None:
        decided = client.post("/gate", json=SAFE_SCENE_REQUEST).json()
        assert decided["decision"] == "authorize", decided
        contract = client.get(f"/contracts/{decided['contract_id']}").json()
        # carrying the blade is judged by them
        assert any(t.startswith("sharp.") for t in contract["template_versions"])
        headers = curator(client)
        ids = [t["id"] for t in client.get("/templates?hazard_class=sharp_laceration&status=active")
               .json()["templates"]]
        for template_id in ids:
            assert client.post(f"/templates/{template_id}/deprecate",
                               headers=headers).json()["status"] == "deprecated"
        # With nothing left to judge a blade in hand, the gate asks for the library, naming
        # the class, rather than authorizing what nothing judged.
        again = client.post("/gate", json=SAFE_SCENE_REQUEST).json()
        assert (again["decision"], again["defer_kind"]) == ("defer", "extend_library"), again
        unbound = [h for h in again["hazards"] if h["template_id"] is None]
        assert [h["hazard_class"] for h in unbound] == ["sharp_laceration"]

    def test_invalid_revision_changes_nothing(self, client: TestClient) -> None:
        headers = curator(client)
        client.post("/templates", json=new_template(), headers=headers)
        bad = new_template(invariants=[{"id": "x", "formula": "sharp($obj) and not sharp($obj)",
                                        "description": "contradictory"}])
        answer = client.put("/templates/sharp.blade_left_on_edge", json=bad, headers=headers)
        assert answer.status_code == 422
        assert answer.json()["errors"][0]["code"] == "contradiction"
        assert client.get("/templates/sharp.blade_left_on_edge").json()["version"] == 1

    def test_revision_must_keep_its_id(self, client: TestClient) -> None:
        headers = curator(client)
        client.post("/templates", json=new_template(), headers=headers)
        answer = client.put("/templates/sharp.blade_left_on_edge",
                            json=new_template(id="sharp.other"), headers=headers)
        assert answer.status_code == 422
        assert answer.json()["errors"][0]["field"] == "body.id"

    def test_unknown_template_is_404(self, client: TestClient) -> None:
        headers = curator(client)
        assert client.post("/templates/nope.nope/activate", headers=headers).status_code == 404
        assert client.put("/templates/nope.nope", json=new_template(id="nope.nope"),
                          headers=headers).status_code == 404

    def test_search_finds_templates_by_words(self, client: TestClient) -> None:
        found = client.get("/templates?q=hot liquid").json()["templates"]
        assert found
        for template in found:
            text = " ".join((template["id"], template["name"], template["hazard_class"],
                             template["description"])).lower()
            assert "hot" in text and "liquid" in text


class TestValidateEndpoint:
    def test_valid_template_validates_without_being_stored(self, client: TestClient) -> None:
        verdict = client.post("/templates/validate", json=new_template()).json()
        assert verdict["valid"] is True and verdict["errors"] == []
        assert client.get("/templates/sharp.blade_left_on_edge").status_code == 404

    def test_always_true_abort_is_an_error(self, client: TestClient) -> None:
        abort = {"id": "halt", "formula": "sharp($obj) or not sharp($obj)", "description": "x"}
        verdict = client.post("/templates/validate", json=new_template(aborts=[abort])).json()
        assert verdict["valid"] is False
        assert verdict["errors"][0]["field"] == "body.aborts.0.formula"
        assert verdict["errors"][0]["code"] == "valid_abort"

    def test_wrong_arity_points_at_the_call(self, client: TestClient) -> None:
        guard = {"id": "g", "action": "DropHandObject", "formula": "not sharp($obj, robot)",
                 "description": "x"}
        verdict = client.post("/templates/validate", json=new_template(guards=[guard])).json()
        error = verdict["errors"][0]
        assert (error["field"], error["code"], error["line"]) == (
            "body.guards.0.formula", "type", 1)

    def test_schema_error_names_the_field(self, client: TestClient) -> None:
        verdict = client.post("/templates/validate", json=new_template(severity="huge")).json()
        assert verdict["errors"][0]["field"] == "body.severity"
