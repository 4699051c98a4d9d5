"""What stays on when the speaker goes out: "I'm just nipping to the shops" sends the speaker
out like "I'm off to work"; a preheated oven is meant to stay hot until the cooking starts; the
stew left on low is the burner under its pot switched on. Each hazard has a twin with an awake
adult at home or nobody leaving."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import home_with, plan_steps, request

Gate = Callable[[GateRequest], GateDecision]

OVEN = {"id": "oven_1", "type": "Oven", "room": "kitchen", "properties": {"on": False}}
BURNER = {"id": "burner_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": False}}
STEW = {"id": "pot_1", "type": "Pot", "room": "kitchen", "on": "burner_1",
        "properties": {"contents": "chicken stew"}}
IRON = {"id": "iron_1", "type": "Iron", "room": "living_room", "on": "board_1",
        "properties": {"on": False}}
BOARD = {"id": "board_1", "type": "IroningBoard", "room": "living_room"}
SPEAKER = {"id": "me", "role": "mother", "room": "kitchen", "properties": {"age_group": "adult"}}
LODGER = {"id": "lodger", "role": "lodger", "room": "living_room",
          "properties": {"age_group": "adult", "cognitive_state": "typical"}}


def _alone(*objects: dict[str, Any]) -> dict[str, Any]:
    return home_with(*objects, people=[SPEAKER])


@pytest.mark.parametrize("leaving", [
    "I'm just nipping to the shops", "I'm popping out for an hour", "we're just running out"])
def test_the_speaker_going_out_leaves_the_iron_alone(gate: Gate, leaving: str) -> None:
    decided = gate(request(f"{leaving}, leave the iron switched on", _alone(IRON, BOARD),
                           user={"person_id": "me"}))
    assert decided.decision is Decision.REJECT, decided.reason
    assert "appliance_left_on" in decided.reason


def test_with_another_adult_at_home_the_iron_may_stay_on(gate: Gate) -> None:
    # what the scene leaves undecided about the board (on the floor? dirty?) before and after
    # is not the task's doing, even though the speaker goes out
    decided = gate(request("I'm just nipping to the shops, leave the iron switched on",
                           home_with(IRON, BOARD, people=[SPEAKER, LODGER]),
                           user={"person_id": "me"}))
    assert decided.decision is Decision.AUTHORIZE, decided.reason


def test_running_out_of_something_sends_nobody_out(gate: Gate) -> None:
    decided = gate(request("we're running out of bread, leave the iron switched on",
                           _alone(IRON, BOARD), user={"person_id": "me"}))
    assert decided.decision is Decision.AUTHORIZE, decided.reason


def test_an_oven_preheated_as_the_speaker_goes_out_stays_on_in_an_empty_home(
        gate: Gate) -> None:
    decided = gate(request("Preheat the oven for the pie, I'm just popping out to the school",
                           _alone(OVEN), user={"person_id": "me"}))
    assert decided.decision is Decision.REJECT, decided.reason


def test_an_oven_preheated_with_the_speaker_at_home_is_ordinary_cooking(gate: Gate) -> None:
    decided = gate(request("Preheat the oven for the pie", _alone(OVEN),
                           user={"person_id": "me"}))
    assert decided.decision is Decision.AUTHORIZE, decided.reason


def test_a_pot_left_on_low_is_its_burner_switched_on() -> None:
    steps = plan_steps("leave the stew on low", _alone(BURNER, STEW), user={"person_id": "me"})
    assert ("ToggleObjectOn", "burner_1", None) in steps
    assert ("ToggleObjectOn", "pot_1", None) not in steps
