"""Temporal and attendance facts of a command (who leaves, who sleeps, for how long)."""

from __future__ import annotations

import pytest

from app.domain.analysis.command import read_command
from app.domain.analysis.knowledge_base import Knowledge, load_knowledge


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


class TestLeavingHome:
    @pytest.mark.parametrize("command", [
        "Stick the roast in at 200, then lock up and come to the shops with me",
        "Leave the heater on while we're out",
        "Run the washing machine, I'm off to work",
        "Start the tumble dryer and come out with me for the evening",
    ])
    def test_home_empties(self, knowledge: Knowledge, command: str) -> None:
        assert read_command(command, knowledge).facts.leaves_home

    @pytest.mark.parametrize("command", [
        "Go out to the garage and fetch the drill",
        "Come with me to the kitchen",
        "Lock the back door, it's late",
    ])
    def test_moving_about_the_house_is_not_leaving(self, knowledge: Knowledge, command: str
                                                   ) -> None:
        assert not read_command(command, knowledge).facts.leaves_home


class TestTimeAndSleep:
    def test_clock_time_at_night(self, knowledge: Knowledge) -> None:
        facts = read_command("At 2am check the back door is locked", knowledge).facts
        assert facts.clock == "2am" and facts.time_of_day == "night"
        assert facts.people_asleep

    def test_afternoon_clock_is_not_night(self, knowledge: Knowledge) -> None:
        facts = read_command("At 4pm switch on the porch light", knowledge).facts
        assert facts.time_of_day == "afternoon" and not facts.people_asleep

    def test_everyone_in_bed(self, knowledge: Knowledge) -> None:
        facts = read_command("Leave the dishwasher running, everyone's in bed", knowledge).facts
        assert facts.people_asleep and facts.unattended

    def test_duration_phrase(self, knowledge: Knowledge) -> None:
        facts = read_command("Leave the heater on in the den for a few hours", knowledge).facts
        assert facts.unattended_for == "for a few hours"

    def test_plain_task_states_nothing(self, knowledge: Knowledge) -> None:
        facts = read_command("Wipe the kitchen counter", knowledge).facts
        assert not facts.unattended and facts.time_of_day is None and not facts.repeated


class TestRobotLeaves:
    def test_later_navigation_leaves_the_earlier_step(self, knowledge: Knowledge) -> None:
        parsed = read_command("Fill the basin, then nip up to the loft for a box", knowledge)
        assert parsed.facts.robot_leaves_room and parsed.facts.leaves_at_step == 0

    def test_while_you_clause_leaves_its_step(self, knowledge: Knowledge) -> None:
        parsed = read_command("Leave the pan on the hob while you fold the towels", knowledge)
        assert parsed.facts.robot_leaves_room and parsed.facts.leaves_at_step == 0

    def test_single_trip_does_not_leave_anything(self, knowledge: Knowledge) -> None:
        assert not read_command("Go to the hallway", knowledge).facts.robot_leaves_room


class TestPersonLeftAlone:
    def test_leave_a_person_to_it(self, knowledge: Knowledge) -> None:
        facts = read_command("Sit Grandpa in the bath and leave him to it", knowledge).facts
        assert facts.person_left_alone

    def test_leave_people_to_do_something(self, knowledge: Knowledge) -> None:
        facts = read_command("Put the toddlers in the paddling pool and leave them to play",
                             knowledge).facts
        assert facts.person_left_alone

    def test_leaving_an_object_is_not_leaving_a_person(self, knowledge: Knowledge) -> None:
        assert not read_command("Leave the parcel by the door", knowledge).facts.person_left_alone
