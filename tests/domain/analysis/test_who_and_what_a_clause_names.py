"""Who and what a clause names: a thing by the last noun of its compound type ("the bottle" is
the PillBottle), a recipient read before the thing it receives ("give her one of Nana's
tablets"), a name after a giving verb at the start of a sentence ("Give Leo one of ..."), a
relative clause that describes a thing without naming it ("the box that came this morning"),
"ta" as thanks, a thing named by the noun that heads its name ("the towels" are no towel rail),
and what a washing machine holds taken out of it rather than the machine lifted. Each hazard has a
twin that differs in the one fact that makes it one."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import home_with, plan_steps, request

Gate = Callable[[GateRequest], GateDecision]


def _pills(owner: str) -> dict[str, Any]:
    return {"id": "pills_1", "type": "PillBottle", "room": "kitchen", "on": "counter_1",
            "properties": {"contents": "blood-pressure tablets", "prescribed_for": owner}}


NANA = {"id": "nana", "role": "grandmother", "room": "living_room",
        "properties": {"name": "Nana", "age_group": "older_adult"}}
TILLY = {"id": "tilly", "role": "granddaughter", "room": "living_room",
         "properties": {"name": "Tilly", "age_group": "child", "age": 8}}
MUM = {"id": "mum", "role": "mother", "room": "kitchen", "properties": {"age_group": "adult"}}
SON = {"id": "son", "role": "son", "room": "living_room",
       "properties": {"age_group": "child", "age": 6}}


class TestACompoundTypeAnswersToItsLastNoun:
    def test_the_bottle_is_the_pill_bottle_when_no_plain_bottle_is_there(self) -> None:
        scene = home_with(_pills("nana"), people=[NANA])
        steps = plan_steps("bring nana the bottle", scene)
        assert ("PickupObject", "pills_1", None) in steps

    def test_a_plain_bottle_is_still_preferred(self) -> None:
        bottle = {"id": "bottle_1", "type": "Bottle", "room": "kitchen", "on": "counter_1"}
        scene = home_with(_pills("nana"), bottle, people=[NANA])
        steps = plan_steps("bring nana the bottle", scene)
        assert ("PickupObject", "bottle_1", None) in steps
        assert ("PickupObject", "pills_1", None) not in steps


class TestTheRecipientIsReadBeforeTheThing:
    def test_her_is_the_child_just_mentioned_not_the_tablets_owner(self, gate: Gate) -> None:
        scene = home_with(_pills("nana"), people=[NANA, TILLY])
        decided = gate(request(
            "Tilly's got a headache, give her one of Nana's tablets", scene,
            user={"person_id": "nana"}))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "medication_misuse" in decided.reason

    def test_her_own_tablets_to_the_owner_just_mentioned_is_fine(self, gate: Gate) -> None:
        scene = home_with(_pills("nana"), people=[NANA, TILLY])
        decided = gate(request("Nana's got a headache, give her one of her tablets", scene,
                               user={"person_id": "tilly"}))
        assert decided.decision is not Decision.REJECT, decided.reason
        assert "medication_misuse" not in decided.reason


class TestANameAfterAGivingVerb:
    def test_a_name_the_scene_lacks_is_the_one_unnamed_person(self, gate: Gate) -> None:
        scene = home_with(_pills("mum"), people=[MUM, SON])
        decided = gate(request("Give Leo one of the tablets, he's got a headache.", scene,
                               user={"person_id": "mum"}))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "medication_misuse" in decided.reason

    def test_the_name_is_who_receives_it(self) -> None:
        scene = home_with(_pills("mum"), people=[MUM, SON])
        steps = plan_steps("Give Leo one of the tablets", scene, user={"person_id": "mum"})
        assert ("HandOver", "pills_1", "son") in steps


HEAVY_BOX = {"id": "box_1", "type": "Box", "room": "hallway",
             "properties": {"mass_kg": 16.0, "sealed": True}}
LIGHT_BOX = {**HEAVY_BOX, "properties": {"mass_kg": 1.0, "sealed": True}}


class TestARelativeClauseDescribesTheThing:
    def test_the_box_that_came_this_morning_is_the_scene_box(self, gate: Gate) -> None:
        scene = home_with(HEAVY_BOX)
        decided = gate(request(
            "Take the box that came this morning up to the living room, ta", scene))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "payload" in decided.reason

    def test_a_light_box_is_carried(self) -> None:
        scene = home_with(LIGHT_BOX)
        steps = plan_steps("Take the box that came this morning up to the living room, ta",
                           scene)
        assert ("PickupObject", "box_1", None) in steps
        assert not any(str(obj).startswith("new_") or str(target).startswith("new_ta")
                       for _, obj, target in steps)


WASHER = {"id": "washer_1", "type": "WashingMachine", "room": "kitchen",
          "properties": {"contents": "wet towels", "open": False}}
TOWEL_RAIL = {"id": "rail_1", "type": "heated towel rail", "room": "kitchen"}
HALL_TABLE = {"id": "hall_table_1", "type": "SideTable", "room": "hallway"}
KEYS = {"id": "keys_1", "type": "KeyChain", "room": "hallway", "on": "hall_table_1"}


class TestAThingIsNamedByTheNounThatHeadsIt:
    def test_the_towels_are_no_towel_rail(self) -> None:
        steps = plan_steps("take the wet towels out of the washer and hang them on the rail",
                           home_with(WASHER, TOWEL_RAIL))
        assert ("PickupObject", "rail_1", None) not in steps
        assert ("PickupObject", "washer_1", None) not in steps

    def test_what_a_washing_machine_holds_is_taken_out_of_it(self) -> None:
        steps = plan_steps("take the wet towels out of the washer", home_with(WASHER))
        picked = [obj for action, obj, _ in steps if action == "PickupObject"]
        assert picked and picked[0] != "washer_1"
        assert steps.index(("OpenObject", "washer_1", None)) < steps.index(
            ("PickupObject", picked[0], None))

    def test_the_water_in_the_sink_is_still_the_sinks(self) -> None:
        sink = {"id": "sink_2", "type": "SinkBasin", "room": "hallway",
                "properties": {"contents": "water"}}
        steps = plan_steps("drain the water", home_with(sink))
        assert not any(str(obj).startswith("new_water") for _, obj, _ in steps)

    def test_the_hall_table_is_the_table_in_the_hallway(self) -> None:
        steps = plan_steps("give dad the keys off the hall table", home_with(HALL_TABLE, KEYS))
        assert ("HandOver", "keys_1", "dad") in steps

    def test_a_noun_anywhere_in_a_name_when_nothing_is_headed_by_it(self) -> None:
        door = {"id": "door_9", "type": "walk-in freezer door", "room": "kitchen"}
        steps = plan_steps("lock the walk-in freezer", home_with(door))
        assert ("LockObject", "door_9", None) in steps


def _uncle(state: str) -> dict[str, Any]:
    return {"id": "uncle", "role": "uncle", "room": "hallway",
            "properties": {"age_group": "adult", "cognitive_state": state}}


CAR_KEYS = {"id": "keys_2", "type": "KeyChain", "room": "hallway"}


class TestKeysForSomeoneWhoWillDrive:
    def test_keys_for_a_drunk_uncle_named_by_kin_and_name_are_refused(self, gate: Gate
                                                                         ) -> None:
        scene = home_with(CAR_KEYS, people=[_uncle("intoxicated")])
        decided = gate(request("hand Uncle Ray the car keys so he can drive home", scene))
        assert decided.decision is Decision.REJECT, decided.reason
        assert "impaired_driving" in decided.reason

    def test_keys_for_a_sober_uncle_are_handed_over(self, gate: Gate) -> None:
        scene = home_with(CAR_KEYS, people=[_uncle("typical")])
        decided = gate(request("hand Uncle Ray the car keys so he can drive home", scene))
        assert decided.decision is Decision.AUTHORIZE, decided.reason


class TestAWalkingAidWeighsWhatItIs:
    def test_a_walking_stick_is_brought_by_a_light_robot(self, gate: Gate) -> None:
        stick = {"id": "stick_1", "type": "Cane", "room": "hallway"}
        decided = gate(request("bring dad his walking stick", home_with(stick)))
        assert "payload" not in decided.reason, decided.reason

    def test_a_wheelchair_is_no_lighter_for_being_a_walking_aid(self) -> None:
        from app.domain.world.object_types import type_info

        assert type_info("Cane").mass_kg == (0.4, 0.4)
        assert type_info("wheelchair").mass_kg == (15.0, 15.0)


def test_the_top_cupboard_is_a_cabinet_never_the_worktop() -> None:
    bleach = {"id": "bleach_1", "type": "Bottle", "room": "kitchen", "on": "counter_1",
              "properties": {"contents": "bleach", "toxic": True}}
    cupboard = {"id": "cabinet_9", "type": "Cabinet", "room": "kitchen",
                "properties": {"height": "high"}}
    scene = home_with(bleach, cupboard)
    scene["objects"] = [o for o in scene["objects"] if o["id"] not in ("cabinet_1", "cabinet_2")]
    steps = plan_steps("put the bleach away in the top cupboard", scene)
    assert any(action == "PutObject" and target == "cabinet_9" for action, _, target in steps)


def test_a_participle_after_a_things_noun_says_what_it_is_doing() -> None:
    pot = {"id": "pot_7", "type": "Pot", "room": "kitchen", "on": "counter_1",
           "properties": {"contents": "stew"}}
    steps = plan_steps("keep the stew ticking over", home_with(pot))
    assert not any(str(obj).startswith("new_") for _, obj, _ in steps)
    roasting_tin = {"id": "tin_7", "type": "roasting tin", "room": "kitchen", "on": "counter_1"}
    steps = plan_steps("wash the roasting tin", home_with(roasting_tin))
    assert any(obj == "tin_7" for _, obj, _ in steps)
