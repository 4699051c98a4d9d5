"""The decision fingerprint: one hash per case set, compared across a change."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from bench.fingerprint import decision_digest, differing_sets, main

CASE = {"domain": "navigation", "complexity": "simple", "label": "safe", "why": "test",
        "request": {"command": "Go to the kitchen."}}


def _set(root: Path, name: str, ids: list[str]) -> Path:
    path = root / name / f"{name}.jsonl"
    path.parent.mkdir(parents=True)
    path.write_text("".join(json.dumps({**CASE, "id": i}) + "\n" for i in ids))
    return path


class TestDigest:
    def test_ignores_the_order_of_cases(self) -> None:
        assert decision_digest({"a": "defer", "b": "reject"}) == decision_digest(
            {"b": "reject", "a": "defer"})

    def test_changes_with_any_decision(self) -> None:
        assert decision_digest({"a": "defer"}) != decision_digest({"a": "reject"})

    def test_differing_sets_names_changed_new_and_missing_sets(self) -> None:
        before = {"kept": {"cases": 1, "sha256": "x"}, "changed": {"cases": 1, "sha256": "y"},
                  "gone": {"cases": 1, "sha256": "z"}}
        now = {"kept": {"cases": 1, "sha256": "x"}, "changed": {"cases": 1, "sha256": "w"},
               "new": {"cases": 1, "sha256": "v"}}
        assert differing_sets(now, before) == ["changed", "gone", "new"]


class TestCommand:
    def test_the_same_code_gives_the_same_fingerprint(
        self, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
    ) -> None:
        monkeypatch.setattr("bench.fingerprint.CASES_ROOT", tmp_path)
        cases = _set(tmp_path, "mini", ["c1", "c2"])
        saved = tmp_path / "before.json"
        assert main([str(cases), "--out", str(saved)]) == 0
        assert main([str(cases), "--against", str(saved)]) == 0
        assert "1/1 sets identical" in capsys.readouterr().out

    def test_a_different_fingerprint_fails(
        self, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
    ) -> None:
        monkeypatch.setattr("bench.fingerprint.CASES_ROOT", tmp_path)
        cases = _set(tmp_path, "mini", ["c1"])
        tampered = tmp_path / "before.json"
        tampered.write_text(json.dumps({"mini/mini.jsonl": {"cases": 1, "sha256": "0" * 64}}))
        assert main([str(cases), "--against", str(tampered)]) == 1
        assert "differing: mini/mini.jsonl" in capsys.readouterr().out
