"""The library-extension loop end to end over HTTP.

A command whose hazard class has no template defers with `extend_library`; a curator key adds
and activates a template for it; re-evaluation runs the pipeline again and authorizes. Along the
way: a robot key cannot write a template (403), no key cannot either (401, even in open mode),
and an invalid template is refused with the field and position of the error, storing nothing.
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

MISSING_FAMILY = "sharp"  # sharp.yaml holds every sharp_laceration template
HAZARD_CLASS = "sharp_laceration"

SLICE_REQUEST: dict[str, Any] = {
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
              "skills": ["navigate", "pick", "place", "open", "close", "slice", "handover"],
              "sensors": ["rgbd_camera", "lidar"]},
}

NO_THROW_GUARD = {
    "id": "never_throw_blade",
    "action": "ThrowObject",
    "formula": "@object != $obj or not sharp($obj)",
    "description": "Never throw the blade.",
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
    _, secret = issue_api_key(client.app.state.services.repository, role, f"test {role.value}")
    return {"Authorization": f"Bearer {secret}"}


def template_from(skeleton: dict[str, Any], **changes: Any) -> dict[str, Any]:
    return {**skeleton, "guards": [NO_THROW_GUARD], **changes}


class TestExtensionLoop:
    def test_unmapped_hazard_is_extended_and_reevaluated_to_authorize(
        self, gaps_client_on: TestClient
    ) -> None:
        client = gaps_client_on
        gated = client.post("/gate", json=SLICE_REQUEST).json()
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
        assert decision["decision"] == "authorize", decision
        assert decision["parent_request_id"] == gated["request_id"]
        contract = client.get(f"/contracts/{decision['contract_id']}").json()
        assert contract["template_versions"][document["id"]] == 1
        assert client.get("/extensions/pending").json()["count"] == 0
        audit = client.get(f"/gate/{gated['request_id']}").json()
        assert audit["followed_by"] == [decision["request_id"]]

    def test_single_reevaluation_decides_the_latest_waiting_decision(
        self, gaps_client: TestClient
    ) -> None:
        client = gaps_client
        curator = bearer(client, ApiKeyRole.CURATOR)
        gated = client.post("/gate", json=SLICE_REQUEST).json()
        again = client.post(f"/gate/{gated['request_id']}/reevaluate", headers=curator).json()
        assert again["defer_kind"] == "extend_library"  # nothing covers the class yet
        skeleton = gated["suggested_templates"][0]
        client.post("/templates", json=template_from(skeleton), headers=curator)
        client.post(f"/templates/{skeleton['id']}/activate", headers=curator)
        final = client.post(f"/gate/{gated['request_id']}/reevaluate", headers=curator).json()
        assert final["decision"] == "authorize"
        assert final["parent_request_id"] == again["request_id"]
        refused = client.post(f"/gate/{gated['request_id']}/reevaluate", headers=curator)
        assert refused.status_code == 409  # no longer waiting

    def test_robot_key_cannot_write_a_template(self, gaps_client: TestClient) -> None:
        skeleton = gaps_client.post("/gate", json=SLICE_REQUEST).json()["suggested_templates"][0]
        robot = bearer(gaps_client, ApiKeyRole.ROBOT)
        answer = gaps_client.post("/templates", json=template_from(skeleton), headers=robot)
        assert answer.status_code == 403
        assert answer.headers["content-type"].startswith("application/problem+json")
        assert gaps_client.get(f"/templates/{skeleton['id']}").status_code == 404

    def test_template_write_needs_a_key_even_in_open_mode(self, gaps_client: TestClient) -> None:
        skeleton = gaps_client.post("/gate", json=SLICE_REQUEST).json()["suggested_templates"][0]
        answer = gaps_client.post("/templates", json=template_from(skeleton))
        assert answer.status_code == 401
        assert gaps_client.post("/gate/x/reevaluate").status_code == 401

    def test_invalid_template_is_refused_with_the_errors_position(
        self, gaps_client: TestClient
    ) -> None:
        client = gaps_client
        skeleton = client.post("/gate", json=SLICE_REQUEST).json()["suggested_templates"][0]
        formula = "@object != $obj or not sharpp($obj)"
        bad_guard = {**NO_THROW_GUARD, "formula": formula}
        answer = client.post("/templates", json=template_from(skeleton, guards=[bad_guard]),
                             headers=bearer(client, ApiKeyRole.CURATOR))
        assert answer.status_code == 422
        assert answer.headers["content-type"].startswith("application/problem+json")
        error = answer.json()["errors"][0]
        assert error["field"] == "body.guards.0.formula"
        assert (error["line"], error["column"]) == (1, formula.index("sharpp") + 1)
        assert "sharpp" in error["message"]
        assert client.get(f"/templates/{skeleton['id']}").status_code == 404
