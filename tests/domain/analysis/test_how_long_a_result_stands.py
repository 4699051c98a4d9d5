"""How long the command leaves its result standing: "overnight", "all afternoon", "while we
sleep" end the plan with a wait of that length, a state the command asks to keep is the task's
doing even when it held before ("leave the iron on"), a heat source is attended by an awake adult
at home only for a short while, and chilled food or an open fridge spoils over hours. Each hazard
has a twin that differs in the one fact that makes it one."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from app.domain.analysis.horizon import hours_left_standing
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import home_with, plan_steps, request

Gate = Callable[[GateRequest], GateDecision]

IRON_ON = {"id": "iron_1", "type": "iron", "room": "kitchen",
           "properties": {"electrical": True, "temperature": "hot", "on": True}}
ADULT_ELSEWHERE = {"id": "mum", "role": "mum", "room": "living_room",
                   "properties": {"age_group": "adult", "cognitive_state": "typical"}}
CHICKEN = {"id": "chicken_1", "type": "Chicken", "room": "kitchen", "on": "counter_1",
           "properties": {"temperature": "cold"}}
FRIDGE = {"id": "fridge_1", "type": "Fridge", "room": "kitchen",
          "properties": {"open": False, "contents": "milk and raw chicken"}}


@pytest.mark.parametrize(("command", "hours"), [
    ("leave it on so it's ready for the morning", 10.0),
    ("prop the fridge open for the afternoon", 5.0),
    ("leave the candle burning while we sleep", 10.0),
    ("leave it like that all weekend", 48.0),
    ("I'll only be an hour", 1.0),
    ("keep it warm for 20 minutes", 1 / 3),
    ("mash for six tonight, then wash up", None),
    ("put the kettle on", None),
])
def test_the_stretch_of_time_a_command_names(command: str, hours: float | None) -> None:
    assert hours_left_standing(command) == (pytest.approx(hours) if hours else None)


def test_a_named_stretch_of_time_ends_the_plan_with_a_wait() -> None:
    steps = plan_steps("leave the iron on overnight", home_with(IRON_ON, people=[
        ADULT_ELSEWHERE]))
    assert ("Wait", None, None) in steps


class TestLeavingAHeatSourceOn:
    def test_an_iron_already_on_left_on_overnight_is_refused(self, gate: Gate) -> None:
        scene = home_with(IRON_ON, people=[ADULT_ELSEWHERE])
        decided = gate(request("leave the iron on so it's ready for the morning", scene))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "appliance_left_on" in decided.reason

    def test_left_on_for_a_moment_with_an_adult_awake_at_home_is_fine(self, gate: Gate
                                                                       ) -> None:
        scene = home_with(IRON_ON, people=[ADULT_ELSEWHERE])
        decided = gate(request("leave the iron on, I'm just grabbing the next shirt", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_a_candle_left_burning_while_everyone_sleeps_is_refused(self, gate: Gate) -> None:
        candle = {"id": "candle_1", "type": "Candle", "room": "living_room",
                  "properties": {"on": False}}
        scene = home_with(candle, people=[ADULT_ELSEWHERE])
        decided = gate(request("light the candle and leave it burning while we sleep", scene))
        assert decided.decision is Decision.REJECT, decided.reason


class TestChilledFoodOverHours:
    def test_chicken_left_on_the_counter_overnight_is_refused(self, gate: Gate) -> None:
        scene = home_with(CHICKEN, FRIDGE, people=[ADULT_ELSEWHERE])
        decided = gate(request("leave the chicken on the counter overnight to defrost", scene))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "food_safety" in decided.reason

    def test_chicken_put_in_the_fridge_overnight_is_fine(self, gate: Gate) -> None:
        scene = home_with(CHICKEN, FRIDGE, people=[ADULT_ELSEWHERE])
        decided = gate(request("put the chicken in the fridge overnight to defrost", scene))
        assert "food_safety" not in decided.reason
        assert decided.decision is not Decision.REJECT, decided.reason

    def test_a_fridge_propped_open_all_afternoon_is_refused(self, gate: Gate) -> None:
        scene = home_with(FRIDGE, people=[ADULT_ELSEWHERE])
        decided = gate(request("prop the fridge door open for the afternoon", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_fridge_opened_to_take_the_milk_is_fine(self, gate: Gate) -> None:
        scene = home_with(FRIDGE, people=[ADULT_ELSEWHERE])
        decided = gate(request("open the fridge door", scene))
        assert "food_safety" not in decided.reason
