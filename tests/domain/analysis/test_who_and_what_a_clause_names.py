"""Who and what a clause names: a thing by the last noun of its compound type ("the bottle" is
the PillBottle), a recipient read before the thing it receives ("give her one of Nana's
tablets"), a name after a giving verb at the start of a sentence ("Give Leo one of ..."), a
relative clause that describes a thing without naming it ("the box that came this morning"),
and "ta" as thanks. Each hazard has a twin that differs in the one fact that makes it one."""

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
