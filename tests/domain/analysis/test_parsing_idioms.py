"""Colloquial commands read as the plain actions they mean (idioms, phrasal verbs, ellipsis)."""

from __future__ import annotations

import pytest

from app.domain.analysis.command import parse_command, read_command
from app.domain.analysis.knowledge_base import Knowledge, load_knowledge


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


def _actions(command: str, knowledge: Knowledge) -> list[str | None]:
    return [s.action for s in parse_command(command, knowledge)]


class TestMotionIdioms:
    @pytest.mark.parametrize("command", ["Pop downstairs for me", "Dash outside",
                                         "nip round to the shed", "hop over to the study"])
    def test_quick_motion_verbs_mean_going(self, knowledge: Knowledge, command: str) -> None:
        assert _actions(command, knowledge) == ["navigate"]

    def test_pop_with_an_object_means_put(self, knowledge: Knowledge) -> None:
        step = parse_command("pop the milk in the fridge", knowledge)[0]
        assert step.action == "place" and step.destination is not None
        assert step.destination.head == "fridge"

    def test_cutting_through_a_room_is_a_route(self, knowledge: Knowledge) -> None:
        step = parse_command("cut across the dining room", knowledge)[0]
        assert step.action == "navigate"
        assert step.path is not None and step.path.room == "dining_room"

    def test_cutting_bread_stays_cutting(self, knowledge: Knowledge) -> None:
        assert _actions("cut the loaf in half", knowledge) == ["cut"]

    def test_run_something_to_a_place_is_carrying(self, knowledge: Knowledge) -> None:
        step = parse_command("run these plates over to the kitchen", knowledge)[0]
        assert step.action == "transport" and step.objects[0].head == "plates"

    def test_running_a_machine_is_not_carrying(self, knowledge: Knowledge) -> None:
        assert _actions("run the dishwasher", knowledge) == ["switch_on"]

    def test_go_do_takes_the_second_verb(self, knowledge: Knowledge) -> None:
        parsed = read_command("go wake the lodger", knowledge)
        assert [s.action for s in parsed.steps] == ["wake"]
        assert parsed.steps[0].objects[0].head == "lodger"

    def test_go_round_stays_a_phrasal_verb(self, knowledge: Knowledge) -> None:
        assert _actions("go round the garden", knowledge) == ["navigate"]

    def test_place_adverb_becomes_the_destination(self, knowledge: Knowledge) -> None:
        step = parse_command("scurry upstairs", knowledge)[0]
        assert step.destination is not None and step.destination.head == "upstairs"
        assert not step.objects


class TestRemovalAndScolding:
    def test_yanking_off_a_person_is_removal_from_them(self, knowledge: Knowledge) -> None:
        step = parse_command("whip the blanket off him", knowledge)[0]
        assert step.action == "remove" and step.objects[0].head == "blanket"
        assert step.source is not None and step.source.head == "him"

    def test_strip_a_coating_off_furniture(self, knowledge: Knowledge) -> None:
        step = parse_command("strip the varnish off the table", knowledge)[0]
        assert step.action == "remove" and step.source is not None

    def test_telling_off_is_intimidation(self, knowledge: Knowledge) -> None:
        assert _actions("tell the lodger off", knowledge) == ["intimidate"]

    def test_keep_doing_is_repeated(self, knowledge: Knowledge) -> None:
        parsed = read_command("keep nagging Dad until he eats", knowledge)
        assert parsed.steps[0].action == "intimidate"
        assert parsed.facts.repeated

    def test_telling_a_story_is_not_scolding(self, knowledge: Knowledge) -> None:
        assert _actions("tell grandad a story", knowledge) == ["play"]


class TestKitchenIdioms:
    def test_in_at_a_temperature_switches_the_oven_on(self, knowledge: Knowledge) -> None:
        steps = parse_command("stick the lasagne in at 190", knowledge)
        assert [s.action for s in steps] == ["place", "switch_on"]
        assert steps[1].objects[0].head == "oven"

    def test_appliance_on_at_a_setting_is_switching(self, knowledge: Knowledge) -> None:
        steps = parse_command("Roast chicken: oven on at 180, then season the bird", knowledge)
        assert "switch_on" in [s.action for s in steps]

    def test_thing_on_a_surface_is_placing(self, knowledge: Knowledge) -> None:
        steps = parse_command("Get set up: laptop on the desk, mug on the coaster", knowledge)
        assert steps[-1].action == "place"

    def test_plugging_the_basin_puts_the_stopper_in(self, knowledge: Knowledge) -> None:
        step = parse_command("plug the basin", knowledge)[0]
        assert step.action == "place" and step.destination is not None
        assert step.destination.head == "basin"

    def test_plugging_in_a_lamp_is_still_switching_on(self, knowledge: Knowledge) -> None:
        assert _actions("plug the lamp in", knowledge) == ["switch_on"]

    def test_leave_it_bubbling_keeps_it_on(self, knowledge: Knowledge) -> None:
        step = parse_command("leave the stew bubbling", knowledge)[0]
        assert step.action == "switch_on" and step.keeps_state

    def test_prop_leaves_something_leaning(self, knowledge: Knowledge) -> None:
        step = parse_command("prop the ladder against the shed", knowledge)[0]
        assert step.action == "place" and step.keeps_state

    def test_boiling_implies_the_hob(self, knowledge: Knowledge) -> None:
        parsed = read_command("boil the potatoes", knowledge)
        assert parsed.devices == {0: "hob"}

    def test_named_device_is_not_implied(self, knowledge: Knowledge) -> None:
        assert read_command("boil the eggs in the pan on the stove", knowledge).devices == {}

    def test_filling_the_bath_implies_the_tap(self, knowledge: Knowledge) -> None:
        assert read_command("run a deep bath", knowledge).devices == {0: "tap"}


class TestActionNouns:
    def test_give_someone_a_wash_is_washing_them(self, knowledge: Knowledge) -> None:
        step = parse_command("give the toddler a quick wash", knowledge)[0]
        assert step.action == "clean" and step.objects[0].head == "toddler"

    def test_an_injection_is_not_a_handover(self, knowledge: Knowledge) -> None:
        step = parse_command("give Nan her flu jab", knowledge, {"nan"})[0]
        assert step.action == "assist"

    def test_giving_a_thing_stays_a_handover(self, knowledge: Knowledge) -> None:
        step = parse_command("give Tom the hammer from the shed", knowledge, {"tom"})[0]
        assert step.action == "handover" and step.objects[0].head == "hammer"

    def test_a_sip_of_something_is_the_something(self, knowledge: Knowledge) -> None:
        step = parse_command("give the toddler a sip of my coffee", knowledge)[0]
        assert step.objects[0].substance == "coffee"

    def test_feed_a_person_makes_them_the_recipient(self, knowledge: Knowledge) -> None:
        step = parse_command("feed him", knowledge)[0]
        assert step.action == "serve" and step.recipient is not None and not step.objects


class TestPurposeAndTime:
    def test_to_verb_is_a_purpose_not_a_destination(self, knowledge: Knowledge) -> None:
        step = parse_command("open the windows to let the smoke out", knowledge)[0]
        assert step.destination is None and step.purpose == "to let the smoke out"

    def test_to_a_place_stays_a_destination(self, knowledge: Knowledge) -> None:
        step = parse_command("take the mug to the kitchen", knowledge)[0]
        assert step.destination is not None and step.purpose is None

    def test_leading_clock_time_is_not_the_verb(self, knowledge: Knowledge) -> None:
        assert _actions("at 11pm switch off the porch light", knowledge) == ["switch_off"]

    def test_after_a_meal_then_a_verb(self, knowledge: Knowledge) -> None:
        steps = parse_command("after lunch wipe the table", knowledge)
        assert steps[0].action == "clean" and steps[0].condition == "after lunch"

    def test_speed_phrase_is_not_an_object(self, knowledge: Knowledge) -> None:
        step = parse_command("drive to the garage at top speed", knowledge)[0]
        assert step.destination is not None and step.destination.room == "garage"
        assert not step.objects
