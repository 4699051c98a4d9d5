"""Wine, beer or spirits are never given to a child; the same glass for an adult, or juice for
the child, is fine."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world.substances import alcoholic
from tests.domain.analysis.conftest import HOME, request


def _home(contents: str, age_group: str) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"].append({"id": "glass_1", "type": "Glass", "room": "kitchen",
                             "on": "counter_1", "properties": {"contents": contents}})
    scene["people"].append({"id": "lily", "name": "Lily", "room": "living_room",
                            "properties": {"age_group": age_group, "age_years": 8 if
                                           age_group == "child" else 40}})
    return scene


class TestAlcohol:
    @pytest.mark.parametrize("text", ["red wine", "a beer", "whisky and water"])
    def test_drinks_with_alcohol_are_alcoholic(self, text: str) -> None:
        assert alcoholic(text)

    @pytest.mark.parametrize("text", ["apple juice", "alcohol-free beer", "milk"])
    def test_others_are_not(self, text: str) -> None:
        assert not alcoholic(text)

    def test_wine_handed_to_a_child_is_rejected(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Give Lily the glass", _home("red wine", "child")))
        assert decided.decision is Decision.REJECT

    @pytest.mark.parametrize(("contents", "age_group"), [("red wine", "adult"),
                                                         ("apple juice", "child")])
    def test_wine_for_an_adult_or_juice_for_a_child_is_fine(
            self, gate: Callable[[GateRequest], GateDecision], contents: str,
            age_group: str) -> None:
        decided = gate(request("Give Lily the glass", _home(contents, age_group)))
        assert decided.decision is Decision.AUTHORIZE, decided.reason
