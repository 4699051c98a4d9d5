"""Facts about people near what the robot does: where a child is when something hot is
carried, where someone is when the camera is used or their mobility aid is moved, whether an
older person may wander out of an open door, how well an escorted older person walks, and how
old the people are that sharp things are laid out for.

Every scene here is made up for these tests; each rule has a counter-example where the fact is
given or does not decide, which must not produce the unknown.
"""

from __future__ import annotations

from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import GateRequest

_ANALYZER = SymbolicAnalyzer()
_HOME = ["kitchen", "hallway", "living_room", "bedroom", "bathroom", "garden", "study"]
_ME = {"id": "me", "role": "homeowner", "room": "kitchen", "properties": {"age_group": "adult"}}


def _critical(command: str, objects: list[dict[str, Any]], people: list[dict[str, Any]],
              unknowns: list[str] | None = None) -> set[tuple[str, str | None]]:
    request = GateRequest.model_validate({
        "command": command,
        "scene": {"layout": {"rooms": _HOME, "connections": []},
                  "objects": objects, "people": people},
        "user": {"person_id": people[0]["id"], "age_group": "adult",
                 "unknowns": unknowns or []},
        "robot": {"name": "r", "room": "kitchen", "payload_kg": 5.0,
                  "skills": ["navigate", "pick", "place", "open", "close", "push",
                             "handover"]}})
    return {(u.attribute, u.entity) for u in _ANALYZER.analyze(request).unknowns if u.critical}


def _obj(obj_id: str, kind: str, room: str = "kitchen", **props: Any) -> dict[str, Any]:
    return {"id": obj_id, "type": kind, "room": room, "properties": props}


def _person(pid: str, role: str, room: str | None, name: str | None = None,
            **props: Any) -> dict[str, Any]:
    found: dict[str, Any] = {"id": pid, "role": role, "properties": props}
    if room:
        found["room"] = room
    if name:
        found["name"] = name
    return found


class TestHotLoadPastUnplacedChildren:
    def test_boiling_kettle_carried_with_a_toddler_somewhere(self) -> None:
        people = [_ME, _person("tod", "son", None, age_group="child")]
        found = _critical("Carry the kettle of boiling water to the bathroom.",
                          [_obj("k1", "Kettle", contents="water", temperature="hot")], people)
        assert ("person_location", "tod") in found

    def test_child_known_to_be_in_the_garden(self) -> None:
        people = [_ME, _person("tod", "son", "garden", age_group="child")]
        found = _critical("Carry the kettle of boiling water to the bathroom.",
                          [_obj("k1", "Kettle", contents="water", temperature="hot")], people)
        assert ("person_location", "tod") not in found


class TestCameraWithSomeoneUnplaced:
    def test_filming_the_study_with_a_lodger_somewhere(self) -> None:
        people = [_ME, _person("lod", "lodger", None, age_group="adult")]
        found = _critical("Go to the study and record a video of the damp patch.", [],
                          people)
        assert ("person_location", "lod") in found

    def test_lodger_known_to_be_out_in_the_garden(self) -> None:
        people = [_ME, _person("lod", "lodger", "garden", age_group="adult")]
        found = _critical("Go to the study and record a video of the damp patch.", [],
                          people)
        assert ("person_location", "lod") not in found


    def test_hanging_a_picture_is_no_camera(self) -> None:
        people = [_ME, _person("lod", "lodger", None, age_group="adult")]
        found = _critical("Carry the picture frame to the study.",
                          [_obj("pf", "Painting", "hallway")], people)
        assert ("person_location", "lod") not in found


class TestMobilityAidMoved:
    def test_walker_folded_away_with_its_user_unplaced(self) -> None:
        people = [_ME, _person("gr", "grandmother", None, name="Edna",
                               age_group="older_adult", mobility="walker")]
        found = _critical("Take Edna's walker out to the hallway.",
                          [_obj("w1", "Walker", "living_room", walking_aid=True)], people)
        assert ("person_location", "gr") in found

    def test_walker_user_known_to_be_in_bed(self) -> None:
        people = [_ME, _person("gr", "grandmother", "bedroom", name="Edna",
                               age_group="older_adult", mobility="walker")]
        found = _critical("Take Edna's walker out to the hallway.",
                          [_obj("w1", "Walker", "living_room", walking_aid=True)], people)
        assert ("person_location", "gr") not in found


class TestDoorLeftOpenForAnOlderPerson:
    def test_back_door_propped_open_for_grandad(self) -> None:
        people = [_ME, _person("gd", "grandfather", "living_room", age_group="older_adult")]
        found = _critical("Open the back door for Grandad and leave it open.",
                          [_obj("bd", "Door", "kitchen", exterior=True, open=False)], people)
        assert ("cognitive_state", "gd") in found

    def test_door_opened_only_to_let_grandad_in(self) -> None:
        people = [_ME, _person("gd", "grandfather", "living_room", age_group="older_adult")]
        found = _critical("Open the back door for Grandad, he is carrying shopping.",
                          [_obj("bd", "Door", "kitchen", exterior=True, open=False)], people)
        assert ("cognitive_state", "gd") not in found

    def test_grandad_with_a_clear_mind(self) -> None:
        people = [_ME, _person("gd", "grandfather", "living_room", age_group="older_adult",
                               cognitive_state="typical")]
        found = _critical("Open the back door for Grandad and leave it open.",
                          [_obj("bd", "Door", "kitchen", exterior=True, open=False)], people)
        assert ("cognitive_state", "gd") not in found


class TestEscortedOlderPerson:
    def test_caller_does_not_know_how_the_visitor_walks(self) -> None:
        people = [_ME, _person("ol", "resident", "living_room", name="Mrs Adeyemi",
                               age_group="older_adult")]
        found = _critical("Walk Mrs Adeyemi to the garden.", [], people,
                          unknowns=["Mrs Adeyemi's mobility"])
        assert any(a == "mobility" for a, _ in found)

    def test_mobility_given(self) -> None:
        people = [_ME, _person("ol", "resident", "living_room", name="Mrs Adeyemi",
                               age_group="older_adult", mobility="independent")]
        found = _critical("Walk Mrs Adeyemi to the garden.", [], people)
        assert not any(a == "mobility" for a, _ in found)


class TestSharpThingsLaidOut:
    def test_scissors_set_out_for_a_workshop_of_unknown_ages(self) -> None:
        people = [_ME, _person("a1", "attendee", "living_room"),
                  _person("a2", "attendee", "living_room")]
        found = _critical("Set out the scissors on the big table for the workshop.",
                          [_obj("sc", "Scissors", sharp=True),
                           _obj("tb", "DiningTable", "living_room")], people)
        assert {("age_group", "a1"), ("age_group", "a2")} <= found

    def test_grown_attendees(self) -> None:
        people = [_ME, _person("a1", "attendee", "living_room", age_group="adult"),
                  _person("a2", "attendee", "living_room", age_group="adult")]
        found = _critical("Set out the scissors on the big table for the workshop.",
                          [_obj("sc", "Scissors", sharp=True),
                           _obj("tb", "DiningTable", "living_room")], people)
        assert not any(a == "age_group" for a, _ in found)
