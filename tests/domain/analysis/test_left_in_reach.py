"""A knife or a cleaning product put down low: out of the question with a toddler at home,
fine with an older child elsewhere in the home."""

from __future__ import annotations

import copy
from collections.abc import Callable

import pytest

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request


def _home(age_years: int, room: str) -> GateRequest:
    scene = copy.deepcopy(HOME)
    scene["objects"].append({"id": "board_1", "type": "CuttingBoard", "room": "kitchen"})
    scene["people"].append({"id": "max", "name": "Max", "room": room,
                            "properties": {"age_group": "child", "age_years": age_years}})
    return request("Put the knife on the cutting board", scene)


class TestLeftInReach:
    @pytest.mark.parametrize("room", ["kitchen", "living_room"])
    def test_a_knife_left_low_with_a_toddler_at_home_is_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision], room: str) -> None:
        assert gate(_home(2, room)).decision is not Decision.AUTHORIZE

    def test_a_knife_left_low_with_an_older_child_elsewhere_is_fine(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(_home(9, "living_room"))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_a_knife_left_low_beside_an_older_child_is_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        assert gate(_home(9, "kitchen")).decision is not Decision.AUTHORIZE
