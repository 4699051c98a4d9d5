"""A fact the caller's scene gives as unknown, on something the command acts on, is asked about;
the same word on an object the command leaves alone, or a known value, asks nothing. Also: the
reader gets past stacked openers ("oi robot, could you maybe") and run-together words ("gimme").
"""

from __future__ import annotations

from typing import Any

from analyzer_cases import scene_request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.command import read_command
from app.domain.analysis.knowledge_base import load_knowledge
from app.domain.models import UnknownFact

_ANALYZER = SymbolicAnalyzer()


def _unknowns(command: str, *objects: dict[str, Any]) -> list[UnknownFact]:
    request = scene_request(command, list(objects))
    return [u for u in _ANALYZER.analyze(request).unknowns if u.critical]


def _tub(**properties: Any) -> dict[str, Any]:
    return {"id": "tub_1", "type": "Bowl", "room": "kitchen", "properties": properties}


_MUG = {"id": "mug_1", "type": "Mug", "room": "kitchen", "properties": {"contents": "tea"}}


class TestDeclaredUnknowns:
    def test_unknown_contents_of_the_object_moved_are_asked(self) -> None:
        found = [u for u in _unknowns("Put the tub in the fridge.", _tub(contents="unknown"))
                 if u.attribute == "contents"]
        assert found and found[0].entity == "tub_1"
        assert found[0].question and "contents" in found[0].question

    def test_a_phrase_starting_with_unknown_counts(self) -> None:
        found = _unknowns("Put the tub in the fridge.", _tub(contents="unknown clear liquid"))
        assert any(u.attribute == "contents" for u in found)

    def test_a_label_given_as_none_is_asked_about(self) -> None:
        found = _unknowns("Put the tub in the fridge.", _tub(label="none"))
        assert any(u.attribute == "label" and u.entity == "tub_1" for u in found)

    def test_an_object_the_command_leaves_alone_asks_nothing(self) -> None:
        found = _unknowns("Put the mug in the sink.", _MUG, _tub(contents="unknown"))
        assert not [u for u in found if u.entity == "tub_1"]

    def test_known_values_ask_nothing(self) -> None:
        found = _unknowns("Put the tub in the fridge.", _tub(contents="soup", label="soup"))
        assert not [u for u in found if u.entity == "tub_1"]

    def test_none_is_unknown_only_for_a_label(self) -> None:
        found = _unknowns("Put the tub in the fridge.", _tub(lid="none"))
        assert not [u for u in found if u.attribute == "lid"]


class TestOpeners:
    def _first_step(self, command: str) -> tuple[str | None, str | None]:
        step = read_command(command, load_knowledge()).steps[0]
        return step.verb, step.action

    def test_stacked_openers_and_punctuation_are_skipped(self) -> None:
        assert self._first_step("Oi robot, could you maybe bring the mug")[1] == (
            self._first_step("Bring the mug")[1])

    def test_run_together_words_are_read_apart(self) -> None:
        assert self._first_step("Gimme the mug")[1] == self._first_step("Give me the mug")[1]
        assert self._first_step("Gimme the mug")[1] is not None


class TestVisitor:
    def test_letting_an_unidentified_someone_in_is_asked(self) -> None:
        door = {"id": "door_1", "type": "Door", "room": "hallway"}
        found = [u for u in _unknowns("Someone's at the door, go and let them in.", door)
                 if u.attribute == "visitor"]
        assert found and found[0].question

    def test_letting_the_named_plumber_in_is_not(self) -> None:
        door = {"id": "door_1", "type": "Door", "room": "hallway"}
        found = [u for u in _unknowns("The plumber is here, let him in.", door)
                 if u.attribute == "visitor"]
        assert not found


class TestWhichPerson:
    def test_her_with_two_girls_present_is_asked_and_not_rejected(self) -> None:
        request = scene_request(
            "Give her a spoon of the medicine before bed.",
            [{"id": "med_1", "type": "Bottle", "room": "bedroom",
              "properties": {"contents": "cough medicine", "owner": "grace"}}],
            [{"id": "grace", "role": "daughter", "name": "Grace", "room": "bedroom",
              "properties": {"age_group": "child"}},
             {"id": "ella", "role": "daughter", "name": "Ella", "room": "bedroom",
              "properties": {"age_group": "child"}}])
        report = _ANALYZER.analyze(request)
        assert any(u.attribute == "recipient" and u.critical for u in report.unknowns)
        assert not any(p.preventability.value == "unpreventable" for p in report.proposals
                       if p.entities.get("person") in ("grace", "ella"))


class TestVisitorsAndSupport:
    def test_nutty_bake_for_friends_who_are_not_listed(self) -> None:
        nuts = {"id": "nuts_1", "type": "Bag", "room": "kitchen",
                "properties": {"contents": "mixed nuts"}}
        found = [u for u in _unknowns("Bake flapjacks with the mixed nuts for when the "
                                      "friends come over.", nuts) if u.attribute == "allergies"]
        assert found and found[0].entity is None

    def test_the_same_bake_for_the_household_asks_nothing(self) -> None:
        nuts = {"id": "nuts_1", "type": "Bag", "room": "kitchen",
                "properties": {"contents": "mixed nuts"}}
        found = [u for u in _unknowns("Bake flapjacks with the mixed nuts for tea.", nuts)
                 if u.attribute == "allergies"]
        assert not found

    def test_a_hand_up_the_stairs_with_no_stated_payload(self) -> None:
        request = scene_request(
            "Give Dad a hand up the stairs.", people=[
                {"id": "dad", "role": "dad", "room": "hallway",
                 "properties": {"age_group": "older_adult"}}])
        report = _ANALYZER.analyze(request)
        assert any(u.attribute == "robot_payload" and u.critical and u.entity == "dad"
                   for u in report.unknowns)
