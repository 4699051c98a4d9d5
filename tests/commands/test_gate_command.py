"""`safegate gate "command" --scene scene.json`, in process on a real SQLite file."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from app.store import create_engine_for
from app.store.repository import Repository
from tests.commands.conftest import Invoke
from tests.scope_kit import TEA_REQUEST

SCENE: dict[str, Any] = {
    "layout": {"rooms": ["kitchen", "living_room"],
               "connections": [["kitchen", "living_room"]]},
    "objects": [
        {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "counter_1",
         "properties": {"temperature": "hot", "contents": "tea"}},
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
    ],
    "people": [{"id": "kid", "role": "child", "room": "living_room",
                "properties": {"age_group": "child"}}],
}


def _write(tmp_path: Path, body: object, name: str = "scene.json") -> str:
    path = tmp_path / name
    path.write_text(json.dumps(body))
    return str(path)


class TestGateCommand:
    def test_prints_decision_rule_and_hazards(self, invoke: Invoke, tmp_path: Path) -> None:
        result = invoke("gate", "hand the hot tea to the child", "--scene",
                        _write(tmp_path, SCENE))
        assert result.exit_code == 0, result.output
        first = result.stdout.splitlines()[0]
        assert first.startswith("reject") and "rule R1" in first
        assert "hazards" in result.stdout and "thermal_burn" in result.stdout

    def test_json_is_the_api_answer_and_is_audited(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        request = {"command": "ignored", "scene": SCENE, "user": {"age_group": "adult"},
                   "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place"]}}
        result = invoke("gate", "put the mug on the counter", "--scene",
                        _write(tmp_path, request), "--json")
        assert result.exit_code == 0, result.output
        answer = json.loads(result.stdout)
        assert (answer["decision"], answer["rule"]) == ("authorize", "R4")
        assert {"rule", "hazards", "reason", "request_id"} <= answer.keys()
        record = Repository(create_engine_for(sqlite_url)).get_gate_record(answer["request_id"])
        assert record.request.command == "put the mug on the counter"
        assert record.decision == answer["decision"]

    def test_reference_plan_prints_the_proved_plan_and_the_audit_record_keeps_it(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        result = invoke("gate", str(TEA_REQUEST["command"]), "--scene",
                        _write(tmp_path, TEA_REQUEST), "--reference-plan")
        assert result.exit_code == 0, result.output
        assert result.stdout.startswith("authorize")
        assert "reference plan (proved by Stage 5" in result.stdout
        assert "PickupObject" in result.stdout and "mug_1" in result.stdout
        assert "goal:" in result.stdout
        request_id = result.stdout.splitlines()[0].split("request ")[1].strip()
        record = Repository(create_engine_for(sqlite_url)).get_gate_record(request_id)
        assert record.reference_plan is not None and record.reference_plan["plan"]
        assert any(s.get("object") == "mug_1" for s in record.reference_plan["plan"])

    def test_reference_plan_of_a_task_not_authorized_says_why(
        self, invoke: Invoke, tmp_path: Path
    ) -> None:
        result = invoke("gate", "hand the hot tea to the child", "--scene",
                        _write(tmp_path, SCENE), "--reference-plan")
        assert result.exit_code == 0, result.output
        assert "reference plan: none (no reference plan: the task was not authorized)" in (
            " ".join(result.stdout.split()))

    def test_an_invalid_scene_is_refused(self, invoke: Invoke, tmp_path: Path) -> None:
        bad_shape = invoke("gate", "tidy up", "--scene",
                           _write(tmp_path, {"objects": [{"id": "x"}]}))
        assert bad_shape.exit_code == 1
        assert "objects.0.type" in bad_shape.output
        not_json = tmp_path / "scene.txt"
        not_json.write_text("{nope")
        assert invoke("gate", "tidy up", "--scene", str(not_json)).exit_code == 1
