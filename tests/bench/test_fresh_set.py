"""Tests for the fresh, independently written evaluation set (bench/cases/fresh/)."""

from __future__ import annotations

import copy
import json
from collections import Counter
from pathlib import Path
from typing import Any

import pytest

from app.domain.models import GateRequest
from bench.cases.fresh.build_fresh import OUTPUT, all_cases, problems_in
from bench.cases.fresh.kit import check_case

TARGET_MIX = {"safe": 30, "unsafe": 38, "ambiguous": 22}
TOLERANCE = 3


def _load() -> list[dict[str, Any]]:
    lines = Path(OUTPUT).read_text(encoding="utf-8").splitlines()
    return [json.loads(line) for line in lines if line.strip()]


class TestFreshFile:
    def test_every_request_is_a_gate_request(self) -> None:
        cases = _load()
        requests = [GateRequest.model_validate(case["request"]) for case in cases]
        assert len(requests) == len(cases) == 90
        assert [r.command for r in requests] == [c["request"]["command"] for c in cases]

    def test_ids_are_unique(self) -> None:
        ids = [case["id"] for case in _load()]
        assert len(ids) == len(set(ids))

    def test_label_mix_is_near_the_target(self) -> None:
        counts = Counter(case["label"] for case in _load())
        assert set(counts) == set(TARGET_MIX)
        for label, target in TARGET_MIX.items():
            assert abs(counts[label] - target) <= TOLERANCE, (label, counts[label])

    def test_every_domain_and_complexity_cell_is_filled(self) -> None:
        cells = Counter((case["domain"], case["complexity"]) for case in _load())
        for domain in ("manipulation", "navigation", "assistance"):
            for complexity in ("simple", "medium", "complex"):
                assert cells[(domain, complexity)] > 0, (domain, complexity)

    def test_all_hazard_categories_and_reasoning_kinds_appear(self) -> None:
        cases = _load()
        assert {"physical", "psychological", "operational", "consequential"} <= {
            case["category"] for case in cases}
        assert {"compositional", "incomplete_information", "consequential_state",
                "direct"} <= {case["reasoning"] for case in cases}


class TestCheckCase:
    @pytest.fixture()
    def good(self) -> dict[str, Any]:
        return copy.deepcopy(next(c for c in all_cases() if c["id"] == "fresh-man-01"))

    def test_consistent_case_passes(self, good: dict[str, Any]) -> None:
        assert check_case(good) == []

    def test_person_in_unknown_room_is_reported(self, good: dict[str, Any]) -> None:
        good["request"]["scene"]["people"][0]["room"] = "ballroom"
        assert any("unknown room" in msg for msg in check_case(good))

    def test_missing_room_outside_ambiguous_case_is_reported(
            self, good: dict[str, Any]) -> None:
        del good["request"]["scene"]["people"][0]["room"]
        assert any("no room" in msg for msg in check_case(good))

    def test_dangling_receptacle_is_reported(self, good: dict[str, Any]) -> None:
        good["request"]["scene"]["objects"][1]["on"] = "counter_99"
        assert any("unknown counter_99" in msg for msg in check_case(good))

    def test_complexity_must_follow_steps(self, good: dict[str, Any]) -> None:
        good["steps"] = 12
        assert any("step count" in msg for msg in check_case(good))

    def test_repeated_id_is_reported(self, good: dict[str, Any]) -> None:
        assert any("repeats" in msg for msg in problems_in([good, copy.deepcopy(good)]))
