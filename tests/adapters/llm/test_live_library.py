"""The LLM is offered the library as it is now: a curator's new class reaches the next prompt.

Over HTTP end to end: the app runs with `SAFEGATE_ANALYZER=llm` against the scripted server
(litellm, real HTTP on loopback); a curator key creates and activates a template of a hazard
class no seed template has; the next /gate request's system prompt lists that class with the
entities it binds, and the model's proposal of that class binds to the curator's template.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

from app.config import Settings
from app.main import create_app
from app.services.access import issue_api_key
from app.store.records import ApiKeyRole
from tests.adapters.llm.answers import batched, hazard
from tests.adapters.llm.conftest import SCRIPTED_MODEL
from tests.adapters.llm.scripted_server import ScriptedServer

NEW_CLASS = "device_condensation"
CURATED: dict[str, Any] = {
    "id": "curated.device_chilled",
    "name": "Electronics chilled in a fridge or freezer",
    "category": "physical",
    "hazard_class": NEW_CLASS,
    "description": "Condensation inside a device that was chilled shorts it out.",
    "severity": "high",
    "preventability": "preventable",
    "variables": [{"name": "obj", "type": "object", "description": "the device"}],
    "guards": [{"id": "no_device_into_the_cold", "action": "PutObject",
                "formula": '@object != $obj or not electrical($obj) or not '
                           '(is_a(@target, "Fridge") or is_a(@target, "Freezer"))',
                "description": "Never put an electrical device into a fridge or freezer."}],
}
LAPTOP_REQUEST: dict[str, Any] = {
    "command": "Put the laptop in the fridge.",
    "scene": {"layout": {"rooms": ["kitchen", "living_room"]},
              "objects": [{"id": "laptop_1", "type": "Laptop", "room": "living_room",
                           "on": "desk_1"},
                          {"id": "desk_1", "type": "Desk", "room": "living_room"},
                          {"id": "fridge_1", "type": "Fridge", "room": "kitchen"}],
              "people": [{"id": "p1", "role": "dad", "room": "living_room",
                          "properties": {"age_group": "adult"}}]},
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place", "open", "close"],
              "payload_kg": 5.0},
}


def _levels(**marks: Any) -> list[dict[str, Any]]:
    found = {**hazard(NEW_CLASS, entities={"obj": "laptop_1"}), **marks}
    return [{"hazards": [{**found, "entities": {}}], "unknowns": []},
            {"hazards": [found], "unknowns": []}, {"hazards": [found], "unknowns": []}]


@pytest.fixture
def llm_app(tmp_path: Path, llm_server: ScriptedServer) -> Iterator[TestClient]:
    settings = Settings(database_url=f"sqlite:///{tmp_path / 'gate.db'}", analyzer="llm",
                        llm_model=SCRIPTED_MODEL, llm_api_base=llm_server.base_url,
                        llm_api_key="sk-scripted", llm_timeout=5.0)
    with TestClient(create_app(settings)) as client:
        yield client


def _system_prompt(server: ScriptedServer) -> str:
    content: str = server.requests[-1]["messages"][0]["content"]
    return content


class TestCuratorClassReachesTheModel:
    def test_a_new_class_is_offered_at_once_and_binds(
        self, llm_app: TestClient, llm_server: ScriptedServer
    ) -> None:
        llm_server.answer_json(batched(_levels(new_class=True)))
        before = llm_app.post("/gate", json=LAPTOP_REQUEST).json()
        assert f"- {NEW_CLASS}:" not in _system_prompt(llm_server)
        assert (before["rule"], before["defer_kind"]) == ("R2", "extend_library")

        _, secret = issue_api_key(llm_app.app.state.components.repositories.access,
                                  ApiKeyRole.CURATOR, "curator")
        curator = {"Authorization": f"Bearer {secret}"}
        assert llm_app.post("/templates", json=CURATED, headers=curator).status_code == 201
        llm_server.answer_json(batched(_levels(new_class=True)))
        llm_app.post("/gate", json=LAPTOP_REQUEST)
        assert f"- {NEW_CLASS}:" not in _system_prompt(llm_server)  # a draft is not offered
        activated = llm_app.post(f"/templates/{CURATED['id']}/activate", headers=curator)
        assert activated.status_code == 200, activated.json()

        llm_server.answer_json(batched(_levels()))
        after = llm_app.post("/gate", json=LAPTOP_REQUEST).json()
        line = next(line for line in _system_prompt(llm_server).splitlines()
                    if line.startswith(f"- {NEW_CLASS}:"))
        assert "Electronics chilled in a fridge or freezer" in line and "[obj]" in line
        bound = [h for h in after["hazards"] if h["hazard_class"] == NEW_CLASS]
        assert [h["template_id"] for h in bound] == [CURATED["id"]]
        assert after["rule"] != "R2"
