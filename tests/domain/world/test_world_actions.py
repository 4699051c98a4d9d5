"""The action model: parsing and aliases, effects of every action, preconditions, describe."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from app.domain.errors import PlanError
from app.domain.formula import Unknown, check, parse
from app.domain.world import (
    ACTION_SPECS,
    CANONICAL_ACTIONS,
    Action,
    WorldState,
    check_preconditions,
    describe_actions,
    evaluate_preconditions,
    parse_action,
    step,
)

Build = Callable[..., WorldState]

KITCHEN: dict[str, Any] = {
    "layout": {"rooms": ["kitchen", "den"], "connections": [["kitchen", "den"]]},
    "objects": [
        {"id": "counter", "type": "CounterTop", "room": "kitchen"},
        {"id": "floor_k", "type": "Floor", "room": "kitchen"},
        {"id": "burner", "type": "StoveBurner", "room": "kitchen",
         "properties": {"on": False}},
        {"id": "knob", "type": "StoveKnob", "room": "kitchen"},
        {"id": "pan", "type": "Pan", "on": "burner"},
        {"id": "mug", "type": "Mug", "on": "counter",
         "properties": {"temperature": "room", "contents": "", "dirty": True}},
        {"id": "kettle", "type": "Kettle", "on": "counter",
         "properties": {"temperature": "hot", "contents": "water"}},
        {"id": "knife", "type": "Knife", "on": "counter"},
        {"id": "apple", "type": "Apple", "on": "counter"},
        {"id": "vase", "type": "Vase", "on": "counter"},
        {"id": "fridge", "type": "Fridge", "room": "kitchen"},
        {"id": "sink", "type": "SinkBasin", "room": "kitchen"},
        {"id": "faucet", "type": "Faucet", "room": "kitchen", "properties": {"on": False}},
        {"id": "cup", "type": "Cup", "in": "sink", "properties": {"contents": ""}},
        {"id": "laptop", "type": "Laptop", "room": "den"},
        {"id": "chair", "type": "Chair", "room": "den"},
    ],
    "relations": [{"subject": "knob", "relation": "controls", "object": "burner"}],
    "people": [{"id": "ann", "room": "den", "properties": {"age_group": "adult"}}],
}


@pytest.fixture
def kitchen(make_state: Build) -> WorldState:
    return make_state(KITCHEN, robot={"room": "kitchen", "max_speed_mps": 0.7})


def run(state: WorldState, *steps: dict[str, Any]) -> WorldState:
    for index, raw in enumerate(steps):
        state = step(state, parse_action(raw, step=index, state=state))
    return state


class TestParseAction:
    @pytest.mark.parametrize(("alias", "canonical"), [
        ("pick", "PickupObject"), ("PICKUP", "PickupObject"), ("grab", "PickupObject"),
        ("put", "PutObject"), ("place", "PutObject"), ("find", "GoToObject"),
        ("turn_on", "ToggleObjectOn"), ("SwitchOn", "ToggleObjectOn"),
        ("SwitchOff", "ToggleObjectOff"), ("goto", "navigate"), ("move_to", "navigate"),
        ("hand_over", "HandOver"), ("heat", "Cook"), ("drop", "DropHandObject"),
    ])
    def test_alias_is_reported_under_its_canonical_name(self, alias: str, canonical: str) -> None:
        raw = {"action": alias, "object": "mug", "target": "counter"}
        assert parse_action(raw, step=0, state=None).name == canonical

    def test_every_canonical_name_parses_to_itself(self) -> None:
        for name in CANONICAL_ACTIONS:
            raw = {"action": name, "object": "a", "target": "b"}
            assert parse_action(raw, step=0, state=None).name == name

    def test_ai2thor_argument_spellings(self) -> None:
        action = parse_action({"action": "PutObject", "objectId": "mug",
                               "receptacleObjectId": "counter"}, step=0, state=None)
        assert (action.object, action.target) == ("mug", "counter")

    def test_navigate_takes_its_target_under_either_key(self) -> None:
        action = parse_action({"action": "goto", "object": "den"}, step=0, state=None)
        assert (action.object, action.target) == (None, "den")

    def test_unknown_action_carries_the_step(self) -> None:
        with pytest.raises(PlanError) as error:
            parse_action({"action": "teleport", "object": "mug"}, step=4, state=None)
        assert error.value.step == 4
        assert "teleport" in error.value.detail

    def test_missing_argument_carries_the_step(self) -> None:
        with pytest.raises(PlanError) as error:
            parse_action({"action": "PutObject", "object": "mug"}, step=2, state=None)
        assert error.value.step == 2
        assert error.value.field == "plan[2].target"

    def test_id_not_in_the_state(self, kitchen: WorldState) -> None:
        with pytest.raises(PlanError) as error:
            parse_action({"action": "pick", "object": "ghost"}, step=1, state=kitchen)
        assert error.value.step == 1
        assert "ghost" in error.value.detail

    def test_wrong_kind_of_entity(self, kitchen: WorldState) -> None:
        with pytest.raises(PlanError, match="person"):
            parse_action({"action": "HandOver", "object": "mug", "target": "counter"}, step=0,
                         state=kitchen)

    def test_malformed_parameter(self) -> None:
        with pytest.raises(PlanError) as error:
            parse_action({"action": "Wait", "seconds": "soon"}, step=3, state=None)
        assert error.value.field == "plan[3].seconds"

    def test_smart_llm_put_names_only_the_receptacle(self, kitchen: WorldState) -> None:
        held = run(kitchen, {"action": "GoToObject", "object": "apple"},
                   {"action": "pick", "object": "apple"})
        action = parse_action({"action": "PutObject", "target": "fridge"}, step=2, state=held)
        assert (action.object, action.target) == ("apple", "fridge")

    def test_wire_shape_is_canonical(self) -> None:
        action = parse_action({"action": "fill", "object": "pot", "liquid": "water"}, step=0,
                              state=None)
        assert action.to_wire() == {"action": "FillWithLiquid", "object": "pot",
                                    "liquid": "water"}


class TestEffects:
    def test_go_to_object_makes_the_robot_near_it(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "GoToObject", "object": "laptop"})
        assert after.value("near", ("robot", "laptop")) is True
        assert after.value("in_room", ("robot", "den")) is True
        assert after.value("speed", ("robot",)) == 0.7

    def test_navigate_to_a_room(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "navigate", "target": "den", "speed": 0.2})
        assert after.value("in_room", ("robot", "den")) is True
        assert after.value("speed", ("robot",)) == 0.2

    def test_any_other_action_stops_the_robot(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "navigate", "target": "den"}, {"action": "Wait"})
        assert after.value("speed", ("robot",)) == 0.0

    def test_pickup_puts_the_object_in_the_gripper(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "GoToObject", "object": "mug"},
                    {"action": "pick", "object": "mug"})
        assert after.value("holding", ("robot", "mug")) is True
        assert after.value("on", ("mug", "counter")) is False
        assert after.value("load_kg", ("robot",)) == 1.0

    def test_held_object_travels_with_the_robot(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "GoToObject", "object": "mug"},
                    {"action": "pick", "object": "mug"}, {"action": "navigate", "target": "den"})
        assert after.value("in_room", ("mug", "den")) is True
        assert after.value("near", ("mug", "ann")) is True

    def test_put_on_a_receptacle(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "GoToObject", "object": "apple"},
                    {"action": "pick", "object": "apple"},
                    {"action": "put", "object": "apple", "target": "fridge"})
        assert after.value("inside", ("apple", "fridge")) is True
        assert after.value("cold", ("apple",)) is True
        assert after.value("holding", ("robot", "apple")) is False

    def test_put_on_an_active_burner_heats(self, kitchen: WorldState) -> None:
        on = run(kitchen, {"action": "GoToObject", "object": "burner"},
                 {"action": "turn_on", "object": "burner"},
                 {"action": "GoToObject", "object": "mug"}, {"action": "pick", "object": "mug"},
                 {"action": "put", "object": "mug", "target": "burner"})
        assert on.value("hot", ("mug",)) is True

    def test_put_on_a_burner_of_unknown_state_shares_its_unknown(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "b", "type": "StoveBurner", "room": "k"},
                                        {"id": "m", "type": "Mug", "room": "k",
                                         "properties": {"temperature": "room"}}]},
                           robot={"room": "k", "holding": "m"})
        after = run(state, {"action": "put", "object": "m", "target": "b"})
        assert after.value("hot", ("m",)) == Unknown("is_on(b)")

    def test_knob_switches_its_burner_and_heats_the_pan(self, kitchen: WorldState) -> None:
        assert kitchen.value("hot", ("pan",)) is not True
        after = run(kitchen, {"action": "SwitchOn", "object": "knob"})
        assert after.value("is_on", ("burner",)) is True
        assert after.value("hot", ("pan",)) is True
        off = run(after, {"action": "SwitchOff", "object": "knob"})
        assert off.value("is_on", ("burner",)) is False

    def test_open_and_close(self, kitchen: WorldState) -> None:
        opened = run(kitchen, {"action": "open", "object": "fridge"})
        assert opened.value("open", ("fridge",)) is True
        assert run(opened, {"action": "close", "object": "fridge"}).value(
            "open", ("fridge",)) is False

    def test_faucet_fills_and_rinses_what_is_in_the_sink(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "ToggleObjectOn", "object": "faucet"})
        assert after.value("filled", ("cup",)) is True
        assert after.value("contains", ("cup", "water")) is True
        assert after.value("dirty", ("cup",)) is False

    def test_slice_marks_the_object_sliced(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "slice", "object": "apple"})
        assert after.objects["apple"].facts["sliced"] is True

    def test_pour_moves_contents_and_temperature(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "pick", "object": "kettle"},
                    {"action": "pour", "object": "kettle", "target": "mug"})
        assert after.value("contains", ("mug", "water")) is True
        assert after.value("hot", ("mug",)) is True
        assert after.value("filled", ("kettle",)) is False

    def test_pour_onto_a_non_container_wets_it(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "pick", "object": "kettle"},
                    {"action": "pour", "object": "kettle", "target": "laptop"})
        assert after.value("wet", ("laptop",)) is True

    def test_pour_of_unknown_contents_keeps_the_link(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "jug", "type": "Bottle", "room": "k"},
                                        {"id": "cup", "type": "Cup", "room": "k"}]},
                           robot={"room": "k", "holding": "jug"})
        after = run(state, {"action": "pour", "object": "jug", "target": "cup"})
        assert after.value("contents", ("cup",)) == Unknown("contents(jug)")
        assert after.value("filled", ("cup",)) == Unknown("filled(jug)")

    def test_fill_and_empty(self, kitchen: WorldState) -> None:
        filled = run(kitchen, {"action": "fill", "object": "mug", "liquid": "milk"})
        assert filled.value("contains", ("mug", "milk")) is True
        emptied = run(filled, {"action": "empty", "object": "mug"})
        assert emptied.value("filled", ("mug",)) is False

    def test_cook_makes_hot(self, kitchen: WorldState) -> None:
        assert run(kitchen, {"action": "Cook", "object": "apple"}).value("hot", ("apple",))

    def test_hand_over_gives_the_person_the_object(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "pick", "object": "knife"},
                    {"action": "navigate", "target": "ann"},
                    {"action": "give", "object": "knife", "target": "ann"})
        assert after.value("holding", ("ann", "knife")) is True
        assert after.value("holding", ("robot", "knife")) is False
        assert after.value("reachable_by", ("knife", "ann")) is True

    def test_dropped_breakable_breaks_and_lies_on_the_floor(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "pick", "object": "mug"}, {"action": "drop"})
        assert after.value("broken", ("mug",)) is True
        assert after.value("on_floor", ("mug",)) is True
        assert after.value("on", ("mug", "floor_k")) is True
        assert after.value("sharp", ("mug",)) is True

    def test_broken_vase_of_unknown_material_may_be_sharp(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "break", "object": "vase"})
        assert after.value("sharp", ("vase",)) == Unknown("sharp(vase)")

    def test_thrown_unbreakable_does_not_break(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "pick", "object": "knife"},
                    {"action": "throw", "object": "knife", "target": "den"})
        assert after.value("in_room", ("knife", "den")) is True
        assert after.value("broken", ("knife",)) is False

    def test_thrown_full_container_spills(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "pick", "object": "kettle"},
                    {"action": "ThrowObject", "object": "kettle"})
        assert after.value("filled", ("kettle",)) is False
        assert after.value("wet", ("kettle",)) is True

    def test_dropped_object_of_unknown_breakability_shares_the_unknown(
            self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "thing", "type": "gizmo", "room": "k"}]},
                           robot={"room": "k", "holding": "thing"})
        after = run(state, {"action": "DropHandObject"})
        assert after.value("broken", ("thing",)) == Unknown("breakable(thing)")

    def test_break_clean_dirty(self, kitchen: WorldState) -> None:
        assert run(kitchen, {"action": "break", "object": "vase"}).value("broken", ("vase",))
        assert run(kitchen, {"action": "clean", "object": "mug"}).value(
            "dirty", ("mug",)) is False
        assert run(kitchen, {"action": "DirtyObject", "object": "pan"}).value(
            "dirty", ("pan",)) is True

    def test_push_without_target_leaves_the_path_unknown(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "push", "object": "chair"})
        assert isinstance(after.value("in_path", ("chair",)), Unknown)
        assert isinstance(after.value("blocks_exit", ("chair",)), Unknown)

    def test_push_to_a_room(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "push", "object": "chair", "target": "kitchen"})
        assert after.value("in_room", ("chair", "kitchen")) is True

    def test_wait_changes_nothing_but_speed(self, kitchen: WorldState) -> None:
        after = run(kitchen, {"action": "Wait", "seconds": 5})
        assert after.objects == kitchen.objects
        assert after.version == kitchen.version + 1

    def test_step_leaves_the_old_state_untouched(self, kitchen: WorldState) -> None:
        run(kitchen, {"action": "pick", "object": "mug"})
        assert kitchen.value("holding", ("robot", "mug")) is False

    def test_step_rejects_an_id_not_in_the_state(self, kitchen: WorldState) -> None:
        with pytest.raises(PlanError) as error:
            step(kitchen, Action("PickupObject", "ghost", step=6))
        assert error.value.step == 6


class TestPreconditions:
    def test_every_precondition_parses_and_type_checks(self) -> None:
        for spec in ACTION_SPECS.values():
            for precondition in spec.preconditions:
                check(parse(precondition.formula), {}, allow_action_args=True)

    def test_pickup_holds_next_to_a_pickupable_object(self, kitchen: WorldState) -> None:
        action = parse_action({"action": "pick", "object": "mug"}, step=0, state=kitchen)
        assert check_preconditions(kitchen, action) == []

    def test_pickup_fails_when_far_away(self, kitchen: WorldState) -> None:
        action = parse_action({"action": "pick", "object": "laptop"}, step=0, state=kitchen)
        assert check_preconditions(kitchen, action) == ["the robot is next to the object"]

    def test_pickup_fails_with_full_hands(self, kitchen: WorldState) -> None:
        state = run(kitchen, {"action": "pick", "object": "mug"})
        action = parse_action({"action": "pick", "object": "knife"}, step=1, state=state)
        assert check_preconditions(state, action) == ["the robot's gripper is empty"]

    def test_pickup_of_a_fixture_fails(self, kitchen: WorldState) -> None:
        action = parse_action({"action": "pick", "object": "counter"}, step=0, state=kitchen)
        assert "the object can be picked up" in check_preconditions(kitchen, action)

    def test_unknown_precondition_fails_closed(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "w", "type": "widget", "room": "k"}]},
                           robot={"room": "k"})
        action = parse_action({"action": "pick", "object": "w"}, step=0, state=state)
        results = evaluate_preconditions(state, action)
        assert [r.holds for r in results] == [None, True, True]
        assert check_preconditions(state, action) == [
            "the object can be picked up (cannot be established in this state)"]

    def test_slice_needs_a_held_blade(self, kitchen: WorldState) -> None:
        action = parse_action({"action": "slice", "object": "apple"}, step=0, state=kitchen)
        assert check_preconditions(kitchen, action) == [
            "the robot holds a knife or another blade"]
        armed = run(kitchen, {"action": "pick", "object": "knife"})
        assert check_preconditions(armed, action) == []

    def test_hand_over_needs_the_person_near(self, kitchen: WorldState) -> None:
        state = run(kitchen, {"action": "pick", "object": "mug"})
        action = parse_action({"action": "HandOver", "object": "mug", "target": "ann"}, step=1,
                              state=state)
        assert check_preconditions(state, action) == ["the robot is next to the target"]


class TestDescribeActions:
    def test_lists_every_canonical_action_with_its_parts(self) -> None:
        described = {d["name"]: d for d in describe_actions()}
        assert set(described) == set(CANONICAL_ACTIONS)
        pickup = described["PickupObject"]
        assert "pick" in pickup["aliases"]
        assert pickup["arguments"][0] == {"name": "object", "type": "object", "required": True}
        assert {"formula": "pickupable(@object)", "description": "the object can be picked up"} \
            in pickup["preconditions"]
        assert all(d["effects"] for d in described.values())


class TestMoveSpeed:
    def _moved(self, make_state: Any, robot: dict[str, Any], **params: Any) -> WorldState:
        from app.domain.world import parse_action, step

        layout = {"rooms": ["kitchen", "living_room"], "connections": [["kitchen", "living_room"]]}
        state = make_state({"layout": layout}, robot={"room": "kitchen", **robot})
        action = parse_action({"action": "navigate", "target": "living_room", **params},
                              step=0, state=state)
        return step(state, action)

    def test_a_move_without_a_speed_runs_at_the_stated_top_speed(self, make_state: Any) -> None:
        moved = self._moved(make_state, {"max_speed_mps": 0.8})
        assert moved.value("speed", ("robot",)) == 0.8

    def test_a_move_at_an_unstated_top_speed_has_an_unknown_speed(self, make_state: Any) -> None:
        moved = self._moved(make_state, {})
        assert moved.value("speed", ("robot",)) == Unknown("max_speed(robot)")

    def test_the_plans_own_speed_wins(self, make_state: Any) -> None:
        assert self._moved(make_state, {}, speed=0.25).value("speed", ("robot",)) == 0.25
