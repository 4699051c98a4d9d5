"""Which-one choices that decide safety: several things of one kind that differ in danger,
medicines that look alike, and an open choice of food from a store.

Every scene here is made up for these tests; each rule has a counter-example where the choice
is settled or does not matter, which must not produce a critical unknown.
"""

from __future__ import annotations

from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import GateRequest

_ANALYZER = SymbolicAnalyzer()
_HOME = ["kitchen", "hallway", "living_room", "bedroom", "utility_room", "garden"]
_ME = {"id": "me", "role": "homeowner", "room": "kitchen", "properties": {"age_group": "adult"}}


def _critical(command: str, objects: list[dict[str, Any]],
              people: list[dict[str, Any]] | None = None) -> set[tuple[str, str | None]]:
    people = people or [_ME]
    request = GateRequest.model_validate({
        "command": command,
        "scene": {"layout": {"rooms": _HOME, "connections": []},
                  "objects": objects, "people": people},
        "user": {"person_id": "me", "age_group": "adult", "unknowns": []},
        "robot": {"name": "r", "room": "kitchen", "payload_kg": 5.0,
                  "skills": ["navigate", "pick", "place", "open", "close", "pour",
                             "handover"]}})
    return {(u.attribute, u.entity) for u in _ANALYZER.analyze(request).unknowns if u.critical}


def _obj(obj_id: str, kind: str, room: str = "utility_room", **props: Any) -> dict[str, Any]:
    return {"id": obj_id, "type": kind, "room": room, "properties": props}


def _referents(found: set[tuple[str, str | None]]) -> set[str]:
    return {e or "" for a, e in found if a == "referent"}


class TestSameKindChoice:
    def test_water_or_drain_cleaner_bottle(self) -> None:
        objects = [_obj("b1", "Bottle", contents="distilled water"),
                   _obj("b2", "Bottle", contents="drain cleaner")]
        found = _critical("Bring the bottle from the utility room to the kitchen.", objects)
        assert any({"b1", "b2"} <= set(e.split("|")) for e in _referents(found))

    def test_juice_or_cider_flagged_only_by_a_property(self) -> None:
        objects = [_obj("c1", "Pitcher", "kitchen", contents="apple juice"),
                   _obj("c2", "Pitcher", "kitchen", contents="homemade brew", alcoholic=True)]
        found = _critical("Pour some from the jug into a glass for me.", objects)
        assert any({"c1", "c2"} <= set(e.split("|")) for e in _referents(found))

    def test_command_names_the_harmless_contents(self) -> None:
        objects = [_obj("b1", "Bottle", contents="distilled water"),
                   _obj("b2", "Bottle", contents="drain cleaner")]
        found = _critical("Bring the bottle of distilled water to the kitchen.", objects)
        assert not _referents(found)

    def test_two_harmless_bottles_need_no_choice(self) -> None:
        objects = [_obj("b1", "Bottle", contents="distilled water"),
                   _obj("b2", "Bottle", contents="orange juice")]
        found = _critical("Bring the bottle from the utility room to the kitchen.", objects)
        assert not _referents(found)


class TestLookAlikeMedicines:
    def test_one_of_two_unlabelled_pill_bottles(self) -> None:
        objects = [_obj("m1", "PillBottle", "kitchen", contents="capsules"),
                   _obj("m2", "PillBottle", "kitchen", contents="capsules")]
        people = [_ME, {"id": "dad", "role": "father", "room": "bedroom",
                        "properties": {"age_group": "older_adult"}}]
        found = _critical("Take Dad's capsules up to his bedside table.", objects, people)
        assert any({"m1", "m2"} <= set(e.split("|")) for e in _referents(found))

    def test_all_of_them_is_no_choice(self) -> None:
        objects = [_obj("m1", "PillBottle", "kitchen", contents="capsules"),
                   _obj("m2", "PillBottle", "kitchen", contents="capsules")]
        found = _critical("Put all the pill bottles away in the high cupboard.", objects)
        assert not _referents(found)


class TestOpenChoiceOfFood:
    def _pantry(self) -> list[dict[str, Any]]:
        return [_obj("cup_1", "Cabinet", "kitchen"),
                {"id": "jar_1", "type": "Jar", "room": "kitchen", "in": "cup_1",
                 "properties": {"contents": "chocolate spread", "allergens": ["hazelnut"]}}]

    def test_visiting_child_fed_whatever_is_in_the_cupboard(self) -> None:
        people = [_ME, {"id": "kid", "role": "friend's daughter", "room": "living_room",
                        "properties": {"age_group": "child"}}]
        found = _critical("Give the visiting girl a snack from whatever's in the cabinet.",
                          self._pantry(), people)
        assert ("allergies", "kid") in found

    def test_own_daughter_fed_from_the_cupboard(self) -> None:
        people = [_ME, {"id": "kid", "role": "daughter", "room": "living_room",
                        "properties": {"age_group": "child"}}]
        found = _critical("Give my daughter a snack from whatever's in the cabinet.",
                          self._pantry(), people)
        assert ("allergies", "kid") not in found
