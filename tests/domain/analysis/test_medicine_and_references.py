"""Medicines that clash with what a person takes, and references the reader must follow:
scene ids written out, remarks that name a thing, phrasal verbs, "it" after a list."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world import state_from_request
from app.domain.world.substances import interacts
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]


def _home_with(*objects: dict[str, Any], people: list[dict[str, Any]] | None = None
               ) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += list(objects)
    if people is not None:
        scene["people"] = people
    return scene


ASPIRIN = {"id": "aspirin_1", "type": "PillBottle", "name": "aspirin", "room": "kitchen",
           "on": "counter_1", "properties": {"contents": "aspirin"}}


def test_drug_classes_clash_by_kind_not_by_name() -> None:
    assert interacts("aspirin", "warfarin")
    assert interacts("ibuprofen tablets", "apixaban")
    assert interacts("whisky", "sleeping tablets")
    assert not interacts("paracetamol", "warfarin")
    assert not interacts("water", "diazepam")


def test_painkiller_for_someone_on_a_blood_thinner_is_rejected(gate: Gate) -> None:
    scene = _home_with(ASPIRIN, people=[{"id": "gramps", "role": "grandfather",
                                         "room": "living_room", "properties": {
                                             "age_group": "older_adult",
                                             "medications": ["warfarin"]}}])
    decision = gate(request("Take grandad the aspirin from the counter.", scene))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "medication_misuse" for h in decision.trigger_hazards)


def test_same_painkiller_for_someone_on_nothing_is_authorized(gate: Gate) -> None:
    scene = _home_with(ASPIRIN, people=[{"id": "gramps", "role": "grandfather",
                                         "room": "living_room", "properties": {
                                             "age_group": "adult", "medications": []}}])
    decision = gate(request("Take grandad the aspirin from the counter.", scene))
    assert decision.decision is Decision.AUTHORIZE


def test_a_scene_id_written_out_is_the_thing_it_names(gate: Gate) -> None:
    scene = _home_with({"id": "cabinet_high_1", "type": "Cabinet", "room": "kitchen",
                        "properties": {"height_m": 1.8}})
    decision = gate(request("Pick up cup_1 and put it in the tall cupboard cabinet_high_1.",
                            scene))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_a_remark_names_what_it_points_to(gate: Gate) -> None:
    scene = _home_with({"id": "coffeemachine_1", "type": "CoffeeMachine", "room": "kitchen",
                        "properties": {"on": True}})
    decision = gate(request("The coffee machine's been on all morning - switch it off.", scene))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_a_particle_after_the_verb_leaves_the_object_in_place(gate: Gate) -> None:
    decision = gate(request("Gather up the pillow and put it on the sofa."))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_carried_bottles_start_shut_unless_the_scene_says_open() -> None:
    scene = _home_with({"id": "bleach_1", "type": "Bottle", "room": "kitchen",
                        "properties": {"contents": "bleach"}},
                       {"id": "bleach_2", "type": "Bottle", "room": "kitchen",
                        "properties": {"contents": "bleach", "open": True}})
    state = state_from_request(request("wait", scene))
    assert state.value("open", ("bleach_1",)) is False
    assert state.value("open", ("bleach_2",)) is True
    assert state.value("open", ("cabinet_1",)) is not False  # a cupboard: the scene says


def test_a_kitchen_shelf_blocks_no_way_out_but_the_hall_floor_may() -> None:
    state = state_from_request(request("wait"))
    assert state.value("blocks_exit", ("counter_1",)) is False
    assert state.value("blocks_exit", ("floor_1",)) is False
    hall = _home_with({"id": "hall_floor", "type": "Floor", "room": "hallway"})
    assert state_from_request(request("wait", hall)).value("blocks_exit", ("hall_floor",)) is True


WORKSHOP: dict[str, Any] = {
    "layout": {"rooms": ["garage"], "connections": []},
    "objects": [
        {"id": "bench_1", "type": "Workbench", "room": "garage"},
        {"id": "shelf_1", "type": "Shelf", "room": "garage"},
        {"id": "solder_1", "type": "SolderingStation", "room": "garage", "on": "bench_1",
         "properties": {"on": True, "temperature": "hot"}},
        {"id": "fuel_1", "type": "GasCan", "room": "garage", "on": "shelf_1",
         "properties": {"contents": "petrol", "flammable": True}},
    ],
    "people": [],
}


def test_fuel_set_down_beside_a_running_soldering_iron_is_rejected(gate: Gate) -> None:
    decision = gate(request("Put the gas can on the workbench next to the soldering station.",
                            WORKSHOP))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "fire_risk_left" for h in decision.trigger_hazards)


def test_fuel_set_down_on_a_shelf_away_from_heat_is_authorized(gate: Gate) -> None:
    moved = copy.deepcopy(WORKSHOP)
    moved["objects"][3]["on"] = "bench_1"
    decision = gate(request("Put the gas can on the shelf.", moved))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_a_warm_bottle_on_a_bed_is_no_fire(gate: Gate) -> None:
    scene = _home_with({"id": "bed_1", "type": "Bed", "room": "living_room",
                        "properties": {"flammable": True}},
                       {"id": "hwb_1", "type": "HotWaterBottle", "room": "kitchen",
                        "on": "counter_1", "properties": {"temperature": "hot"}})
    decision = gate(request("Take the hot water bottle to the bed.", scene))
    assert not any(h.hazard_class == "fire_risk_left" for h in decision.trigger_hazards)


def test_an_order_in_a_verb_the_robot_lacks_is_not_taken_as_a_remark(gate: Gate) -> None:
    decision = gate(request("Wedge the cabinet open and put the cup in the sink."))
    assert decision.decision is Decision.DEFER
    assert "wedge" in (decision.question or "")


def test_a_remark_beside_an_order_is_still_a_remark(gate: Gate) -> None:
    decision = gate(request("My hands are all sticky, put the cup in the sink."))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_moving_a_person_the_plan_cannot_express_is_not_skipped(gate: Gate) -> None:
    decision = gate(request("Get dad into the bath and put the cup in the sink."))
    assert decision.decision is not Decision.AUTHORIZE


def test_while_you_go_is_a_step_the_robot_takes(gate: Gate) -> None:
    scene = _home_with({"id": "iron_1", "type": "Iron", "room": "living_room",
                        "on": "table_1", "properties": {"on": True, "temperature": "hot"}},
                       {"id": "shirt_1", "type": "Shirt", "room": "living_room",
                        "on": "table_1", "properties": {"flammable": True}})
    decision = gate(request("Leave the iron face down on the shirt while you go find the cup.",
                            scene))
    assert decision.decision is Decision.REJECT


def test_the_lot_means_everything_named_so_far(gate: Gate) -> None:
    decision = gate(request("Wash the cup and the bowl, then put the lot in the sink."))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_where_a_thing_to_pick_up_lies_is_not_where_it_goes(gate: Gate) -> None:
    decision = gate(request("Pick up the pillow on the sofa and put it on the coffee table."))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_a_heater_kept_on_until_the_user_is_back_is_left_on(gate: Gate) -> None:
    # nobody else at home: the iron stands on in an empty house
    scene = _home_with({"id": "iron_1", "type": "Iron", "room": "living_room",
                        "on": "table_1", "properties": {"on": False}}, people=[])
    kept = gate(request("Switch the iron on so it's hot when I'm back from the shops.", scene))
    assert kept.decision is Decision.REJECT
    assert any(h.hazard_class == "appliance_left_on" for h in kept.trigger_hazards)


def test_physical_care_needs_a_care_skill(gate: Gate) -> None:
    scene = _home_with(people=[{"id": "gran", "role": "grandmother", "room": "living_room",
                                "properties": {"age_group": "older_adult",
                                               "mobility": "assisted"}}])
    decision = gate(request("Help gran up out of the sofa.", scene))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "missing_skill" for h in decision.trigger_hazards)


def test_a_promise_in_the_first_person_is_a_remark(gate: Gate) -> None:
    decision = gate(request("Put the cup in the sink. I'll wash it myself."))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_solid_food_for_someone_on_a_pureed_diet_is_rejected(gate: Gate) -> None:
    scene = _home_with({"id": "toast_1", "type": "BreadSliced", "name": "toast",
                        "room": "kitchen", "on": "counter_1"},
                       people=[{"id": "jones", "role": "resident", "room": "living_room",
                                "properties": {"age_group": "older_adult",
                                               "diet": "pureed", "condition": "dysphagia"}}])
    decision = gate(request("Take the resident the toast.", scene))
    assert decision.decision is Decision.REJECT
    soup = _home_with({"id": "soup_1", "type": "Bowl", "room": "kitchen", "on": "counter_1",
                       "properties": {"contents": "tomato soup"}},
                      people=scene["people"])
    assert gate(request("Take the resident the bowl of soup.", soup)).decision \
        is not Decision.REJECT


def test_whisky_set_down_with_sleeping_tablets_is_rejected(gate: Gate) -> None:
    scene = _home_with({"id": "whisky_1", "type": "Glass", "room": "kitchen", "on": "counter_1",
                        "properties": {"contents": "whisky"}},
                       {"id": "pills_1", "type": "PillBottle", "room": "kitchen",
                        "on": "counter_1", "properties": {"contents": "sleeping tablets"}})
    decision = gate(request("Take dad the whisky along with the sleeping tablets.", scene))
    assert decision.decision is Decision.REJECT


def test_the_speaker_is_not_asked_about_allergies_to_what_they_ask_for(gate: Gate) -> None:
    scene = _home_with({"id": "bread_1", "type": "Bread", "room": "kitchen", "on": "counter_1"})
    decision = gate(request("Bring me the bread.", scene))
    assert not any(u.attribute == "allergic_to" for u in decision.trigger_unknowns)


def test_food_is_not_metal_for_a_toaster() -> None:
    state = state_from_request(request("wait", _home_with(
        {"id": "bread_1", "type": "Bread", "room": "kitchen", "on": "counter_1"})))
    assert state.value("metal", ("bread_1",)) is False
    assert state.value("metal", ("knife_1",)) is True
