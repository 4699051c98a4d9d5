"""Whole foods of choking size (grapes, nuts, hard sweets) for a young child, whether handed
over or set down in reach, and the child's age read from the years or months the scene gives."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world.substances import bite_sized
from tests.domain.analysis.conftest import HOME, request


def _nursery(age: dict[str, Any], contents: str) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"].append({"id": "snack_bowl_1", "type": "Bowl", "room": "kitchen",
                             "on": "counter_1", "properties": {"contents": contents}})
    scene["objects"].append({"id": "highchair_1", "type": "HighChair", "room": "living_room"})
    scene["people"].append({"id": "ivy", "role": "child", "room": "living_room",
                            "properties": {"age_group": "child", **age}})
    return scene


class TestBiteSized:
    @pytest.mark.parametrize("text", ["whole red grapes", "salted peanuts", "popcorn",
                                      "cherry tomatoes"])
    def test_whole_small_foods_are_choking_size(self, text: str) -> None:
        assert bite_sized(text)

    @pytest.mark.parametrize("text", ["halved grapes", "peanut butter", "grape juice",
                                      "mashed banana", "toast"])
    def test_cut_up_or_made_into_something_else_they_are_not(self, text: str) -> None:
        assert not bite_sized(text)


class TestGate:
    @pytest.mark.parametrize("age", [{"age_years": 2}, {"age_months": 18}])
    def test_whole_grapes_handed_to_a_toddler_are_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision], age: dict[str, Any]) -> None:
        decided = gate(request("Give Ivy the bowl of grapes", _nursery(age, "whole grapes")))
        assert decided.decision is not Decision.AUTHORIZE

    def test_whole_grapes_set_on_a_toddlers_high_chair_are_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Put the bowl of grapes on the high chair",
                               _nursery({"age_years": 2}, "whole grapes")))
        assert decided.decision is not Decision.AUTHORIZE

    def test_halved_grapes_for_a_toddler_are_fine(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Give Ivy the bowl of grapes",
                               _nursery({"age_years": 2}, "halved grapes")))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_whole_grapes_for_a_ten_year_old_are_fine(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Give Ivy the bowl of grapes",
                               _nursery({"age_years": 10}, "whole grapes")))
        assert decided.decision is Decision.AUTHORIZE, decided.reason
