"""The command parser: clauses, verb classes, objects, recipients, negation, conditions."""

from __future__ import annotations

import pytest

from app.domain.analysis.command import parse_command
from app.domain.analysis.knowledge_base import Knowledge, load_knowledge


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


class TestClauses:
    def test_commas_then_and_split_steps(self, knowledge: Knowledge) -> None:
        steps = parse_command("Fill the pot with water, put it on the back burner, then turn "
                              "the stove on and leave it on", knowledge)
        assert [s.action for s in steps] == ["pour", "place", "switch_on", "switch_on"]
        assert steps[3].keeps_state

    def test_and_between_nouns_does_not_split(self, knowledge: Knowledge) -> None:
        steps = parse_command("mix the bleach and the ammonia", knowledge)
        assert len(steps) == 1
        assert [o.substance for o in steps[0].objects] == ["bleach", "ammonia"]

    def test_after_that_splits(self, knowledge: Knowledge) -> None:
        steps = parse_command("wipe the table after that bring me a glass of water",
                              knowledge)
        assert [s.action for s in steps] == ["clean", "transport"]


class TestVerbs:
    @pytest.mark.parametrize(("command", "action"), [
        ("microwave the soup", "heat"), ("chop the onions", "cut"),
        ("toss the ball", "throw"), ("smash the vase", "break"),
        ("switch off the iron", "switch_off"), ("shut the door", "close"),
        ("shove the sofa against the wall", "push"), ("put away the dishes", "place"),
        ("spray the counter", "clean"), ("film the party", "record"),
        ("wake up grandpa", "wake"), ("unlock the back door", "unlock"),
        ("throw away the old letters", "remove"), ("hand over the scissors", "handover"),
    ])
    def test_verb_class(self, knowledge: Knowledge, command: str, action: str) -> None:
        assert parse_command(command, knowledge)[0].action == action

    def test_separated_particle(self, knowledge: Knowledge) -> None:
        step = parse_command("turn the kettle off", knowledge)[0]
        assert step.action == "switch_off"
        assert [o.head for o in step.objects] == ["kettle"]

    def test_preposition_on_is_not_a_particle(self, knowledge: Knowledge) -> None:
        step = parse_command("put the cup on the table", knowledge)[0]
        assert step.action == "place"
        assert step.destination is not None and step.destination.head == "table"

    def test_pushing_a_person_is_intimidation(self, knowledge: Knowledge) -> None:
        assert parse_command("push grandpa", knowledge)[0].action == "intimidate"

    def test_make_the_bed_is_not_cooking(self, knowledge: Knowledge) -> None:
        assert parse_command("make the bed", knowledge)[0].action != "heat"
        assert parse_command("make coffee", knowledge)[0].action == "heat"


class TestPhrases:
    def test_double_object_recipient(self, knowledge: Knowledge) -> None:
        step = parse_command("give grandma her pills", knowledge)[0]
        assert step.recipient is not None and step.recipient.role == "older_adult"
        assert step.objects[0].concept == "medication"
        assert step.objects[0].owner == "her"

    def test_possessive_owner(self, knowledge: Knowledge) -> None:
        step = parse_command("give grandma's pills to grandpa", knowledge)[0]
        assert step.objects[0].owner == "grandma"
        assert step.recipient is not None and step.recipient.head == "grandpa"

    def test_location_modifier_stays_on_the_object(self, knowledge: Knowledge) -> None:
        step = parse_command("get the stuff under the sink", knowledge)[0]
        assert step.destination is None
        location = step.objects[0].location
        assert location is not None and location[1].head == "sink"

    def test_contents_after_of(self, knowledge: Knowledge) -> None:
        step = parse_command("bring me a glass of wine", knowledge)[0]
        assert step.objects[0].head == "glass"
        assert step.objects[0].substance == "alcohol"

    def test_throw_at_is_a_target(self, knowledge: Knowledge) -> None:
        step = parse_command("throw the glass at him", knowledge)[0]
        assert step.target is not None and step.target.head == "him"

    def test_property_words_are_modifiers(self, knowledge: Knowledge) -> None:
        step = parse_command("hand me the big knife", knowledge)[0]
        assert step.objects[0].modifiers == ("big",)


class TestNegationAndConditions:
    def test_negated_step(self, knowledge: Knowledge) -> None:
        step = parse_command("don't turn off the stove", knowledge)[0]
        assert step.negated and step.action == "switch_off"

    def test_leading_condition_attaches_to_the_next_step(self, knowledge: Knowledge) -> None:
        steps = parse_command("if the baby is asleep, close the nursery door", knowledge)
        assert len(steps) == 1
        assert steps[0].condition == "if the baby is asleep"

    def test_trailing_condition_attaches_to_the_previous_step(self, knowledge: Knowledge
                                                              ) -> None:
        steps = parse_command("turn off the lights when grandma is in bed", knowledge)
        assert len(steps) == 1 and steps[0].condition is not None
