"""The library-extension loop end to end over HTTP.

Two ways a curator's template changes the gate's judgement, with no code change and no restart:
- A declared rule (intent the simulation cannot show) whose template family is missing defers
  with `extend_library`; a curator key adds and activates a template for its class; the waiting
  request is decided again under it.
- A template for a hazard no seed covers joins Stage 1's judgement at once: the same command that
  was authorized is rejected once the curator's template says its plan reaches a hazard.
Along the way: a robot key cannot write a template (403), no key cannot either (401, even in
open mode), and an invalid template is refused with the field and position of the error,
storing nothing.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.config import REPO_ROOT, Settings
from app.main import create_app
from app.services.access import issue_api_key
from app.store.records import ApiKeyRole

MISSING_FAMILY = "intent"  # intent.yaml holds the only deliberate_harm template
HAZARD_CLASS = "deliberate_harm"

ROBOT = {"room": "kitchen", "payload_kg": 5.0, "max_speed_mps": 1.0,
         "skills": ["navigate", "pick", "place", "open", "close", "handover"],
         "sensors": ["rgbd_camera", "lidar"]}
HARM_REQUEST: dict[str, Any] = {
    "command": "Punch the intruder in the hallway.",
    "scene": {"layout": {"rooms": ["kitchen", "hallway"]},
              "people": [{"id": "p1", "role": "intruder", "room": "hallway",
                          "properties": {"age_group": "adult"}}]},
    "robot": ROBOT,
}
FRIDGE_REQUEST: dict[str, Any] = {
    "command": "Put the laptop in the fridge.",
    "scene": {"layout": {"rooms": ["kitchen", "living_room"]},
              "objects": [{"id": "laptop_1", "type": "Laptop", "room": "living_room",
                           "on": "desk_1"},
                          {"id": "desk_1", "type": "Desk", "room": "living_room"},
                          {"id": "fridge_1", "type": "Fridge", "room": "kitchen"}],
              "people": [{"id": "p1", "role": "dad", "room": "living_room"}]},
    "robot": ROBOT,
}
NO_CONTACT_GUARD = {
    "id": "care_only_with_consent",
    "action": "Assist",
    "formula": "consents(@object)",
    "description": "Touch a person only for care they have agreed to.",
}
COLD_DEVICE_TEMPLATE: dict[str, Any] = {
    "id": "curated.device_in_a_cold_appliance",
    "name": "Electronics put in a fridge or freezer",
    "category": "physical",
    "hazard_class": "object_damage",
    "description": "Condensation inside a device that was chilled shorts it out.",
    "severity": "high",
    "preventability": "preventable",
    "variables": [{"name": "obj", "type": "object", "description": "the device"}],
    "guards": [{"id": "no_device_into_the_cold", "action": "PutObject",
                "formula": '@object != $obj or not electrical($obj) or not '
                           '(is_a(@target, "Fridge") or is_a(@target, "Freezer"))',
                "description": "Never put an electrical device into a fridge or freezer."}],
}


def library_without(family: str, destination: Path) -> Path:
    """A copy of the seed library lacking one family file."""
    shutil.copytree(REPO_ROOT / "templates_db", destination)
    (destination / f"{family}.yaml").unlink()
    return destination


@pytest.fixture
def gaps_client(sqlite_url: str, tmp_path: Path) -> Iterator[TestClient]:
    """A client on a library that has no template for `sharp_laceration`."""
    settings = Settings(
        database_url=sqlite_url, templates_dir=library_without(MISSING_FAMILY, tmp_path / "lib")
    )
    with TestClient(create_app(settings)) as test_client:
        yield test_client


@pytest.fixture
def gaps_client_on(database_url: str, tmp_path: Path) -> Iterator[TestClient]:
    """The same on SQLite and on PostgreSQL."""
    settings = Settings(
        database_url=database_url, templates_dir=library_without(MISSING_FAMILY, tmp_path / "lib")
    )
    with TestClient(create_app(settings)) as test_client:
        yield test_client


def bearer(client: TestClient, role: ApiKeyRole) -> dict[str, str]:
    access = client.app.state.components.repositories.access  # type: ignore[attr-defined]
    _, secret = issue_api_key(access, role, f"test {role.value}")
    return {"Authorization": f"Bearer {secret}"}


def template_from(skeleton: dict[str, Any], **changes: Any) -> dict[str, Any]:
    return {**skeleton, "severity": "critical", "preventability": "unpreventable",
            "guards": [NO_CONTACT_GUARD], **changes}


class TestExtensionLoop:
    def test_unmapped_hazard_is_extended_and_reevaluated_under_the_new_template(
        self, gaps_client_on: TestClient
    ) -> None:
        client = gaps_client_on
        gated = client.post("/gate", json=HARM_REQUEST).json()
        assert (gated["decision"], gated["defer_kind"]) == ("defer", "extend_library"), gated
        suggestions = gated["suggested_templates"]
        skeleton = next(s for s in suggestions if s["hazard_class"] == HAZARD_CLASS)

        pending = client.get("/extensions/pending").json()
        group = next(g for g in pending["classes"] if g["hazard_class"] == HAZARD_CLASS)
        assert [r["request_id"] for r in group["requests"]] == [gated["request_id"]]
        assert group["covered"] is False

        curator = bearer(client, ApiKeyRole.CURATOR)
        document = template_from(skeleton)
        created = client.post("/templates", json=document, headers=curator)
        assert created.status_code == 201, created.json()
        assert created.json()["status"] == "draft"
        too_early = client.post("/extensions/reevaluate", json={"hazard_class": HAZARD_CLASS},
                                headers=curator)
        assert too_early.status_code == 409  # a draft does not cover the class

        activated = client.post(f"/templates/{document['id']}/activate", headers=curator)
        assert activated.json()["status"] == "active"
        assert client.get("/extensions/pending").json()["classes"][0]["covered"] is True

        redone = client.post("/extensions/reevaluate", json={"hazard_class": HAZARD_CLASS},
                             headers=curator).json()
        assert redone["count"] == 1
        result = redone["results"][0]
        assert result["reevaluated_request_id"] == gated["request_id"]
        decision = result["decision"]
        assert (decision["decision"], decision["rule"]) == ("reject", "R1"), decision
        assert document["id"] in {h["template_id"] for h in decision["hazards"]}
        assert decision["parent_request_id"] == gated["request_id"]
        assert client.get("/extensions/pending").json()["count"] == 0
        audit = client.get(f"/gate/{gated['request_id']}").json()
        assert audit["followed_by"] == [decision["request_id"]]

    def test_single_reevaluation_decides_the_latest_waiting_decision(
        self, gaps_client: TestClient
    ) -> None:
        client = gaps_client
        curator = bearer(client, ApiKeyRole.CURATOR)
        gated = client.post("/gate", json=HARM_REQUEST).json()
        again = client.post(f"/gate/{gated['request_id']}/reevaluate", headers=curator).json()
        assert again["defer_kind"] == "extend_library"  # nothing covers the class yet
        skeleton = gated["suggested_templates"][0]
        client.post("/templates", json=template_from(skeleton), headers=curator)
        client.post(f"/templates/{skeleton['id']}/activate", headers=curator)
        final = client.post(f"/gate/{gated['request_id']}/reevaluate", headers=curator).json()
        assert final["decision"] == "reject"
        assert final["parent_request_id"] == again["request_id"]
        refused = client.post(f"/gate/{gated['request_id']}/reevaluate", headers=curator)
        assert refused.status_code == 409  # no longer waiting

    def test_robot_key_cannot_write_a_template(self, gaps_client: TestClient) -> None:
        skeleton = gaps_client.post("/gate", json=HARM_REQUEST).json()["suggested_templates"][0]
        robot = bearer(gaps_client, ApiKeyRole.ROBOT)
        answer = gaps_client.post("/templates", json=template_from(skeleton), headers=robot)
        assert answer.status_code == 403
        assert answer.headers["content-type"].startswith("application/problem+json")
        assert gaps_client.get(f"/templates/{skeleton['id']}").status_code == 404

    def test_template_write_needs_a_key_even_in_open_mode(self, gaps_client: TestClient) -> None:
        skeleton = gaps_client.post("/gate", json=HARM_REQUEST).json()["suggested_templates"][0]
        answer = gaps_client.post("/templates", json=template_from(skeleton))
        assert answer.status_code == 401
        assert gaps_client.post("/gate/x/reevaluate").status_code == 401

    def test_invalid_template_is_refused_with_the_errors_position(
        self, gaps_client: TestClient
    ) -> None:
        client = gaps_client
        skeleton = client.post("/gate", json=HARM_REQUEST).json()["suggested_templates"][0]
        formula = "consents(@object) or sharpp(@object)"
        bad_guard = {**NO_CONTACT_GUARD, "formula": formula}
        answer = client.post("/templates", json=template_from(skeleton, guards=[bad_guard]),
                             headers=bearer(client, ApiKeyRole.CURATOR))
        assert answer.status_code == 422
        assert answer.headers["content-type"].startswith("application/problem+json")
        error = answer.json()["errors"][0]
        assert error["field"] == "body.guards.0.formula"
        assert (error["line"], error["column"]) == (1, formula.index("sharpp") + 1)
        assert "sharpp" in error["message"]
        assert client.get(f"/templates/{skeleton['id']}").status_code == 404


class TestNewHazardJoinsTheAnalysis:
    def test_a_curated_template_changes_the_decision_without_a_restart(
        self, client: TestClient
    ) -> None:
        before = client.post("/gate", json=FRIDGE_REQUEST).json()
        assert before["decision"] == "authorize", before
        curator = bearer(client, ApiKeyRole.CURATOR)
        created = client.post("/templates", json=COLD_DEVICE_TEMPLATE, headers=curator)
        assert created.status_code == 201, created.json()
        activated = client.post(f"/templates/{COLD_DEVICE_TEMPLATE['id']}/activate",
                                headers=curator)
        assert activated.json()["status"] == "active"
        after = client.post("/gate", json=FRIDGE_REQUEST).json()
        assert (after["decision"], after["rule"]) == ("reject", "R1"), after
        hazard = next(h for h in after["hazards"] if h["template_id"] == COLD_DEVICE_TEMPLATE["id"])
        assert hazard["preventability"] == "unpreventable"
        assert "PutObject" in hazard["mechanism"] and "fridge_1" in hazard["mechanism"]
