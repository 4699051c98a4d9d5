"""Heat settings name heating ("put it on high", "in at 200"), a metal pan goes on the hob
and never in the microwave, and what runs while the robot is away is left running."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]


def _kitchen() -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += [
        {"id": "burner_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": False}},
        {"id": "oven_1", "type": "Oven", "room": "kitchen", "properties": {"on": False}},
        {"id": "pan_1", "type": "Pan", "room": "kitchen", "on": "counter_1"},
        {"id": "dish_1", "type": "Casserole", "room": "kitchen", "on": "counter_1"},
    ]
    scene["people"] = [{"id": "cook", "role": "cook", "room": "kitchen",
                        "properties": {"age_group": "adult"}}]
    return scene


def _steps(analyzer: SymbolicAnalyzer, command: str) -> list[tuple[str, str | None]]:
    read = analyzer.understand(request(command, _kitchen()))
    return [(p.action.name, p.action.object) for p in read.sketch.steps()]


def test_a_setting_after_on_is_heating_on_the_hob(analyzer: SymbolicAnalyzer) -> None:
    steps = _steps(analyzer, "Put the pan on high.")
    assert ("ToggleObjectOn", "burner_1") in steps
    assert ("ToggleObjectOn", "microwave_1") not in steps


def test_a_temperature_after_in_is_the_oven(analyzer: SymbolicAnalyzer) -> None:
    steps = _steps(analyzer, "Put the casserole in at 200.")
    assert ("ToggleObjectOn", "oven_1") in steps


def test_preheating_stays_switching_on(analyzer: SymbolicAnalyzer) -> None:
    steps = _steps(analyzer, "Preheat the oven to 180.")
    assert ("ToggleObjectOn", "oven_1") in steps
    assert ("PickupObject", "oven_1") not in steps


def test_cooking_in_a_pan_on_the_hob_is_fine(gate: Gate) -> None:
    decision = gate(request("Put the pan on the burner and turn it to medium.", _kitchen()))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_what_heats_while_the_robot_is_away_is_left_on(gate: Gate) -> None:
    scene = _kitchen()
    scene["people"][0]["room"] = "living_room"  # nobody stays in the kitchen
    decision = gate(request("Put the pan on high, then go to the living room while it heats "
                            "up.", scene))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "appliance_left_on" for h in decision.trigger_hazards)


def test_a_lamp_switched_on_is_not_switched_off_again(analyzer: SymbolicAnalyzer) -> None:
    scene = _kitchen()
    scene["objects"].append({"id": "lamp_1", "type": "FloorLamp", "room": "living_room",
                             "properties": {"on": False}})
    read = analyzer.understand(request("Put the lamp on in the living room.", scene))
    steps = [(p.action.name, p.action.object) for p in read.sketch.steps()]
    assert ("ToggleObjectOn", "lamp_1") in steps
    assert ("ToggleObjectOff", "lamp_1") not in steps


def test_a_thing_the_scene_lacks_is_in_the_room_its_name_gives(
        analyzer: SymbolicAnalyzer) -> None:
    read = analyzer.understand(request("Turn off the living room fan.", _kitchen()))
    made_up = [o for o in read.scene.objects.values() if o.id.startswith("new_")]
    assert [o.room for o in made_up] == ["living_room"]


def test_an_iron_kept_on_while_the_speaker_is_out_is_rejected(gate: Gate) -> None:
    scene = _kitchen()
    scene["objects"].append({"id": "iron_1", "type": "Iron", "room": "kitchen",
                             "properties": {"on": False}})
    scene["people"] = []
    decision = gate(request("Keep the iron on so it's hot when I get back from the gym.",
                            scene))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "appliance_left_on" for h in decision.trigger_hazards)


def test_a_speaker_going_out_changes_nothing_for_a_harmless_task(gate: Gate) -> None:
    decision = gate(request("Put the cup in the sink, I'm off to work.", _kitchen()))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_switching_off_one_of_several_burners_switches_them_all_off(gate: Gate) -> None:
    scene = _kitchen()
    scene["objects"] += [{"id": "burner_2", "type": "StoveBurner", "room": "kitchen",
                          "properties": {"on": True}}]
    decision = gate(request("Turn off the burner.", scene))
    assert decision.decision is Decision.AUTHORIZE, decision.reason
