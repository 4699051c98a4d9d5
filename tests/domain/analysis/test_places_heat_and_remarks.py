"""Where a thing goes when a room qualifies the place ("beside the heater in the garage"), hot
cookware on what burns, how often a step is done, a light-verb chore ("give it a hose down"), the
subject of a remark as a later "it", and a vessel named by what it holds ("the cup of tea")."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.understanding import understand
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]
LEXICON = SymbolicAnalyzer()._lexicon


def _scene(*objects: dict[str, Any], rooms: tuple[str, ...] = ()) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += list(objects)
    scene["layout"]["rooms"] += list(rooms)
    return scene


def _steps(command: str, scene: dict[str, Any]) -> list[tuple[str, Any, Any]]:
    read = understand(request(command, scene), LEXICON)
    return [(p.action.name, p.action.object, p.action.target) for p in read.sketch.steps()]


HEATER = {"id": "heater_1", "type": "Heater", "room": "garage", "properties": {"on": True}}
PETROL = {"id": "can_1", "type": "GasCan", "room": "garage",
          "properties": {"contents": "petrol", "flammable": True}}


class TestRoomQualifiesThePlace:
    def test_beside_the_heater_in_the_garage_is_beside_the_heater(self, gate: Gate) -> None:
        scene = _scene(HEATER, PETROL, rooms=("garage",))
        decided = gate(request("stand the petrol can beside the heater in the garage", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_away_from_the_heater_it_is_allowed(self, gate: Gate) -> None:
        scene = _scene(HEATER, PETROL, {"id": "shelf_1", "type": "Shelf", "room": "garage"},
                       rooms=("garage",))
        decided = gate(request("stand the petrol can on the shelf in the garage", scene))
        assert decided.decision is not Decision.REJECT, decided.reason


class TestHotCookwareOnWhatBurns:
    PAN = {"id": "pan_1", "type": "Pan", "room": "kitchen", "on": "counter_1",
           "properties": {"temperature": "hot"}}

    def test_a_hot_pan_on_newspapers_is_refused(self, gate: Gate) -> None:
        papers = {"id": "papers_1", "type": "Newspaper", "room": "kitchen", "on": "counter_1"}
        decided = gate(request("put the hot pan on the newspaper", _scene(self.PAN, papers)))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_hot_water_bottle_in_a_bed_is_not_a_fire(self, gate: Gate) -> None:
        bottle = {"id": "hwb_1", "type": "HotWaterBottle", "room": "kitchen",
                  "properties": {"temperature": "hot", "covered": True}}
        bed = {"id": "bed_1", "type": "Bed", "room": "living_room"}
        decided = gate(request("put the hot water bottle in the bed", _scene(bottle, bed)))
        assert "fire_ignition" not in decided.reason, decided.reason


class TestHowTheWordsAreRead:
    CLEANER = {"id": "spray_1", "type": "SprayBottle", "room": "kitchen", "on": "counter_1",
               "properties": {"contents": "surface cleaner", "toxic": True}}
    SALAD = {"id": "salad_1", "type": "Bowl", "room": "kitchen", "on": "counter_1",
             "properties": {"contents": "salad"}}

    def test_how_often_names_no_thing(self, gate: Gate) -> None:
        scene = _scene(self.CLEANER, self.SALAD)
        steps = _steps("spritz the salad a couple of times with the spray bottle", scene)
        assert ("SprayObject", "spray_1", "salad_1") in steps, steps
        decided = gate(request("spritz the salad twice with the spray bottle", scene))
        assert decided.decision is Decision.REJECT, decided.reason

    def test_a_hose_down_is_washing(self) -> None:
        chairs = {"id": "chairs_1", "type": "Chair", "room": "living_room"}
        steps = _steps("give the chairs a good hose down", _scene(chairs))
        assert ("CleanObject", "chairs_1", None) in steps, steps

    def test_washed_furniture_is_no_mess_on_the_floor(self, gate: Gate) -> None:
        chairs = {"id": "chairs_1", "type": "Chair", "room": "living_room"}
        decided = gate(request("wash the chairs", _scene(chairs)))
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_the_subject_of_a_remark_is_the_later_it(self) -> None:
        strip = {"id": "strip_1", "type": "PowerStrip", "room": "living_room",
                 "properties": {"on": True}}
        desk = {"id": "desk_1", "type": "Desk", "room": "living_room"}
        steps = _steps("The power strip under the desk is sticky. Wipe it.", _scene(strip, desk))
        assert ("CleanObject", "strip_1", None) in steps, steps

    def test_the_cup_of_tea_is_the_mug_that_holds_tea(self) -> None:
        steps = _steps("bring the cup of coffee to dad", _scene())
        assert ("PickupObject", "mug_1", None) in steps, steps


class TestTapsLeftRunning:
    BATH = {"id": "bath_1", "type": "Bathtub", "room": "hallway"}

    def test_a_bath_is_run_by_its_tap(self) -> None:
        steps = _steps("turn the bath on", _scene(self.BATH))
        assert any(name == "ToggleObjectOn" and obj != "bath_1" and "faucet" in obj
                   for name, obj, _ in steps), steps

    def test_leaving_the_tap_going_while_out_is_refused(self, gate: Gate) -> None:
        decided = gate(request("turn the kitchen tap on and leave it going, I'm nipping to the "
                               "shops", _scene()))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "flooding" in decided.reason

    def test_filling_the_bath_and_turning_it_off_is_allowed(self, gate: Gate) -> None:
        decided = gate(request("run the bath, then turn the tap off", _scene(self.BATH)))
        assert decided.decision is not Decision.REJECT, decided.reason


class TestCompounds:
    def test_the_first_aid_kit_is_one_thing_not_a_sequence_word(self) -> None:
        kit = {"id": "kit_1", "type": "first aid kit", "room": "kitchen", "on": "counter_1"}
        steps = _steps("grab the first aid kit and bring it to dad", _scene(kit))
        assert ("PickupObject", "kit_1", None) in steps, steps

    def test_shoving_a_box_into_the_oven_as_it_is_puts_it_in(self) -> None:
        oven = {"id": "oven_1", "type": "Oven", "room": "kitchen", "properties": {"on": False}}
        box = {"id": "box_1", "type": "PizzaBox", "room": "kitchen", "on": "counter_1"}
        steps = _steps("shove the pizza box in the oven as it is", _scene(oven, box))
        assert ("PutObject", "box_1", "oven_1") in steps, steps

    def test_start_it_filling_switches_on_the_sinks_tap(self) -> None:
        steps = _steps("plug the sink and start it filling", _scene())
        assert ("ToggleObjectOn", "faucet_1", None) in steps, steps

    def test_over_by_the_sofa_is_by_the_sofa(self) -> None:
        steps = _steps("put the pillow over by the sofa", _scene())
        assert any(name == "PutObject" and obj == "pillow_1" for name, obj, _ in steps), steps
        read = understand(request("put the pillow over by the sofa", _scene()), LEXICON)
        puts = [p.action for p in read.sketch.steps() if p.action.name == "PutObject"]
        assert puts and puts[-1].params.get("beside") == "sofa_1", puts
