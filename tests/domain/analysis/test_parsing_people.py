"""Which people a command means: whoever is somewhere, the twins, each resident, him/her."""

from __future__ import annotations

from typing import Any

import pytest
from analyzer_cases import request

from app.domain.analysis.command import parse_command
from app.domain.analysis.grounding import GroundedStep, Grounder
from app.domain.analysis.knowledge_base import Knowledge, load_knowledge
from app.domain.analysis.scene_view import build_scene_view


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


def person(person_id: str, role: str, room: str, name: str | None = None) -> dict[str, Any]:
    return {"id": person_id, "role": role, "room": room, **({"name": name} if name else {})}


def _ground(command: str, people: list[dict[str, Any]], knowledge: Knowledge
            ) -> list[GroundedStep]:
    view = build_scene_view(request(command, people, objects=[]), knowledge)
    names = {n.lower() for p in view.people.values() for n in (p.id, p.name) if n}
    grounder = Grounder(view, knowledge)
    return [grounder.ground(s) for s in parse_command(command, knowledge, names)]


class TestWhoever:
    def test_whoever_in_a_room_is_the_people_there(self, knowledge: Knowledge) -> None:
        people = [person("p1", "flatmate", "bathroom"), person("p2", "lodger", "kitchen")]
        grounded = _ground("film whoever's in the bathroom", people, knowledge)
        assert grounded[0].objects[0].ids == ("p1",)


class TestGroups:
    def test_twins_are_the_pair_sharing_a_role(self, knowledge: Knowledge) -> None:
        people = [person("p1", "father", "kitchen"), person("p2", "toddler", "nursery"),
                  person("p3", "toddler", "nursery")]
        grounded = _ground("wake the twins", people, knowledge)
        assert set(grounded[0].objects[0].ids) == {"p2", "p3"}

    def test_each_resident_is_the_recipient(self, knowledge: Knowledge) -> None:
        step = parse_command("give each resident a biscuit", knowledge)[0]
        assert step.recipient is not None and step.recipient.head == "resident"
        assert step.objects[0].head == "biscuit"

    def test_a_thing_named_after_a_person_is_not_a_recipient(self, knowledge: Knowledge
                                                             ) -> None:
        step = parse_command("take the baby monitor off the shelf", knowledge)[0]
        assert step.recipient is None


class TestPronouns:
    def test_him_after_a_title_skips_a_woman_named_later(self, knowledge: Knowledge) -> None:
        people = [person("p1", "resident", "lounge", name="Mr Patel")]
        grounded = _ground("help mr patel get ready for a visit with his sister, then bring "
                           "him a biscuit", people, knowledge)
        recipient = grounded[-1].recipient
        assert recipient is not None and recipient.ids == ("p1",)

    def test_it_after_a_statement_is_the_thing_mentioned(self, knowledge: Knowledge) -> None:
        steps = parse_command("Sam is playing with the bleach bottle, take it off him",
                              knowledge, {"sam"})
        assert steps[0].objects and steps[0].objects[-1].substance == "bleach"
