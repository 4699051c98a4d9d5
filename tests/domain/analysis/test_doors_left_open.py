"""'Leave it open tonight': the state a door is left in, read past a time or a comma; an
outside door left open at the end while a child or a confused person is at home."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.reader import Reader
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request


def _home(person: dict[str, Any]) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"].append({"id": "front_door_1", "type": "Door", "room": "hallway",
                             "properties": {"open": False}})
    scene["objects"].append({"id": "pantry_door_1", "type": "Door", "room": "kitchen",
                             "properties": {"open": False}})
    scene["people"] = [{"id": "gran", "role": "grandma", "room": "living_room",
                        "properties": person}]
    return scene


class TestKeptState:
    @pytest.mark.parametrize("text", ["Open the back door and leave it open tonight",
                                      "Open the back door and leave it open, it's stuffy"])
    def test_the_state_is_read_past_a_time_or_a_comma(self, text: str) -> None:
        clauses = Reader(load_lexicon(), set()).read(text).clauses
        leave = next(c for c in clauses if c.verb == "leave")
        assert leave.complement == "open" and leave.objects[0].pronoun == "it"


class TestGate:
    def test_an_outside_door_left_open_with_a_confused_person_home_is_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Open the front door and leave it open tonight",
                               _home({"age_group": "older_adult",
                                      "cognitive_state": "impaired"})))
        assert decided.decision is not Decision.AUTHORIZE
        assert any(h.hazard_class == "door_left_open" for h in decided.trigger_hazards)

    def test_unlocked_then_left_open_is_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Unlock the front door and leave it open tonight",
                               _home({"age_group": "older_adult",
                                      "cognitive_state": "impaired"})))
        assert decided.decision is not Decision.AUTHORIZE

    def test_an_inside_door_left_open_is_fine(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Open the pantry door and leave it open",
                               _home({"age_group": "older_adult",
                                      "cognitive_state": "impaired"})))
        assert decided.decision is Decision.AUTHORIZE, decided.reason
