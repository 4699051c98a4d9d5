"""Critical unknowns about people: visitors' and infants' allergies and ages, the age of whom a
hot thing is for, where a person is, whether someone stays home, a frail person's condition,
whose medication it is and when it was last taken.

Every scene here is made up for these tests; each rule has a counter-example where the fact is
given or does not decide, which must not produce the unknown.
"""

from __future__ import annotations

from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import GateRequest

_ANALYZER = SymbolicAnalyzer()
_HOME = ["kitchen", "hallway", "living_room", "bedroom", "garage", "garden", "landing"]
_CARE = ["kitchen", "dining_hall", "resident_room", "lounge", "nurse_station"]
_ADULT = {"id": "me", "role": "homeowner", "room": "kitchen", "properties": {"age_group": "adult"}}


def _critical(command: str, objects: list[dict[str, Any]], people: list[dict[str, Any]],
              rooms: list[str] | None = None, unknowns: list[str] | None = None
              ) -> set[tuple[str, str | None]]:
    request = GateRequest.model_validate({
        "command": command,
        "scene": {"layout": {"rooms": rooms or _HOME, "connections": []},
                  "objects": objects, "people": people},
        "user": {"person_id": people[0]["id"], "age_group": "adult",
                 "unknowns": unknowns or []},
        "robot": {"name": "r", "room": "kitchen", "payload_kg": 5.0,
                  "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour",
                             "handover", "push"]}})
    return {(u.attribute, u.entity) for u in _ANALYZER.analyze(request).unknowns if u.critical}


def _obj(obj_id: str, kind: str, room: str = "kitchen", **props: Any) -> dict[str, Any]:
    return {"id": obj_id, "type": kind, "room": room, "properties": props}


def _person(pid: str, role: str, room: str | None, **props: Any) -> dict[str, Any]:
    found: dict[str, Any] = {"id": pid, "role": role, "properties": props}
    if room:
        found["room"] = room
    return found


class TestConsumerUnknowns:
    def test_peanuts_set_out_for_visitors(self) -> None:
        people = [_ADULT, _person("v1", "visitor", "living_room")]
        found = _critical("Set the peanuts out in the lounge for the visitors.",
                          [_obj("dish_2", "Bowl", contents="peanuts")], people)
        assert {("allergies", "v1"), ("age_group", "v1")} <= found

    def test_egg_fed_to_an_infant(self) -> None:
        people = [_ADULT, _person("bb", "baby", "kitchen", age_group="infant")]
        found = _critical("Feed the baby some scrambled egg.",
                          [_obj("egg_3", "Bowl", contents="scrambled eggs")], people)
        assert ("allergies", "bb") in found

    def test_known_adult_visitors_without_allergies(self) -> None:
        people = [_ADULT, _person("v1", "visitor", "living_room", age_group="adult",
                                  allergies=[])]
        found = _critical("Set the peanuts out in the lounge for the visitors.",
                          [_obj("dish_2", "Bowl", contents="peanuts")], people)
        assert not {a for a, e in found if e == "v1"}

    def test_household_partner_sharing_bread(self) -> None:
        people = [_ADULT, _person("pt", "partner", "kitchen", age_group="adult")]
        found = _critical("Toast the bread and serve lunch for the two of us.",
                          [_obj("bread_2", "Bread")], people)
        assert ("allergies", "pt") not in found


class TestRecipientAgeUnknown:
    def test_hot_chocolate_for_someone_of_unknown_age(self) -> None:
        people = [_ADULT, _person("jo", "friend", "living_room")]
        people[1]["name"] = "Jo"
        found = _critical("Make a hot chocolate for Jo.",
                          [_obj("mug_5", "Mug", contents="hot chocolate")], people)
        assert ("age_group", "jo") in found

    def test_stated_adult_is_not_asked(self) -> None:
        people = [_ADULT, _person("jo", "friend", "living_room", age_group="adult")]
        people[1]["name"] = "Jo"
        found = _critical("Make a hot chocolate for Jo.",
                          [_obj("mug_5", "Mug", contents="hot chocolate")], people)
        assert ("age_group", "jo") not in found


class TestLocationUnknown:
    def test_garage_door_lowered_with_a_child_unplaced(self) -> None:
        people = [_ADULT, _person("kid", "daughter", None, age_group="child")]
        found = _critical("Lower the garage door.", [_obj("gd_1", "GarageDoor", "garage",
                                                          open=True)], people)
        assert ("person_location", "kid") in found

    def test_vacuuming_with_a_napping_infant_unplaced(self) -> None:
        people = [_ADULT, _person("bb", "baby", None, age_group="infant")]
        found = _critical("Vacuum the landing.", [_obj("vac_1", "VacuumCleaner", "landing")],
                          people)
        assert ("person_location", "bb") in found

    def test_racing_with_elders_unplaced(self) -> None:
        people = [_ADULT, _person("el", "grandma", None, mobility="assisted")]
        found = _critical("Go to the bedroom as fast as you can.", [], people)
        assert ("person_location", "el") in found

    def test_everyone_placed_needs_no_answer(self) -> None:
        people = [_ADULT, _person("kid", "daughter", "bedroom", age_group="child")]
        found = _critical("Lower the garage door.", [_obj("gd_1", "GarageDoor", "garage",
                                                          open=True)], people)
        assert ("person_location", "kid") not in found


class TestAttendanceUnknown:
    def test_stew_left_simmering_while_the_robot_is_elsewhere(self) -> None:
        people = [_person("me", "homeowner", None, age_group="adult")]
        found = _critical("Put the stew on to simmer and leave it going while you hoover.",
                          [_obj("pot_4", "Pot", contents="stew")], people)
        assert any(a == "presence" for a, _ in found)

    def test_someone_in_the_kitchen_watches_it(self) -> None:
        found = _critical("Put the stew on to simmer and leave it going while you hoover.",
                          [_obj("pot_4", "Pot", contents="stew")], [_ADULT])
        assert not any(a == "presence" for a, _ in found)

    def test_switching_the_hob_off_before_going_out(self) -> None:
        people = [_person("me", "homeowner", None, age_group="adult")]
        found = _critical("Turn the hob off before we go out.",
                          [_obj("hob_1", "StoveBurner", on=True)], people)
        assert not any(a == "presence" for a, _ in found)


class TestConditionUnknown:
    def test_hot_tea_to_a_care_resident(self) -> None:
        people = [_person("cw", "care assistant", "nurse_station", age_group="adult"),
                  _person("lee", "resident", "resident_room", age_group="older_adult")]
        people[1]["name"] = "Mr Lee"
        found = _critical("Take the hot tea to Mr Lee in his room.",
                          [_obj("cup_8", "Cup", "dining_hall", contents="tea",
                                temperature="hot")], people, rooms=_CARE)
        assert ("cognitive_state", "lee") in found

    def test_lidded_cup_needs_no_answer(self) -> None:
        people = [_person("cw", "care assistant", "nurse_station", age_group="adult"),
                  _person("lee", "resident", "resident_room", age_group="older_adult")]
        people[1]["name"] = "Mr Lee"
        found = _critical("Take the hot tea to Mr Lee in his room.",
                          [_obj("cup_8", "Cup", "dining_hall", contents="tea",
                                temperature="hot", lidded=True)], people, rooms=_CARE)
        assert ("cognitive_state", "lee") not in found

    def test_elder_left_alone_in_the_garden(self) -> None:
        people = [_ADULT, _person("gp", "grandpa", "living_room", age_group="older_adult")]
        found = _critical("Wheel grandpa into the garden and leave him there.", [], people)
        assert ("cognitive_state", "gp") in found

    def test_alert_elder_may_be_left(self) -> None:
        people = [_ADULT, _person("gp", "grandpa", "living_room", age_group="older_adult",
                                  cognitive_state="typical")]
        found = _critical("Wheel grandpa into the garden and leave him there.", [], people)
        assert ("cognitive_state", "gp") not in found


class TestMedicationUnknowns:
    _WARD = [_person("cw", "nurse", "nurse_station", age_group="adult"),
             _person("r1", "resident", "lounge", age_group="older_adult"),
             _person("r2", "resident", "resident_room", age_group="older_adult")]

    def test_unlabelled_pill_pots_for_the_residents(self) -> None:
        found = _critical("Take the pill pots to the residents.",
                          [_obj("pp_1", "PillCup", "nurse_station", contents="tablets")],
                          self._WARD, rooms=_CARE)
        assert ("medication_owner", "pp_1") in found

    def test_labelled_pill_pot_is_not_asked(self) -> None:
        found = _critical("Take the pill pots to the residents.",
                          [_obj("pp_1", "PillCup", "nurse_station", contents="tablets",
                                prescribed_for="r1")], self._WARD, rooms=_CARE)
        assert ("medication_owner", "pp_1") not in found

    def test_ibuprofen_dose_without_the_last_one_known(self) -> None:
        people = [_ADULT, _person("gm", "grandma", "living_room", age_group="older_adult")]
        found = _critical("Give Grandma two of her ibuprofen.",
                          [_obj("ib_1", "PillBottle", contents="ibuprofen",
                                prescribed_for="gm")], people)
        assert ("last_dose", "ib_1") in found

    def test_dose_from_the_organiser_slot_is_scheduled(self) -> None:
        people = [_ADULT, _person("gm", "grandma", "living_room", age_group="older_adult")]
        found = _critical("Give Grandma her ibuprofen from the Tuesday slot.",
                          [_obj("ib_1", "PillBottle", contents="ibuprofen",
                                prescribed_for="gm")], people)
        assert ("last_dose", "ib_1") not in found


class TestAllergiesWhoseAreUnknown:
    def test_caller_says_they_do_not_know_the_childs_allergies(self) -> None:
        people = [_ADULT, _person("ch", "boy", "living_room", age_group="child")]
        people[1]["name"] = "Arlo"
        found = _critical("Hand Arlo a flapjack from the box.",
                          [_obj("box_7", "LunchBox", contents="almond flapjacks",
                                allergens=["tree nut"])], people,
                          unknowns=["Arlo's allergies"])
        assert ("allergies", "ch") in found

    def test_own_child_with_nothing_said_is_not_asked(self) -> None:
        people = [_ADULT, _person("ch", "son", "living_room", age_group="child")]
        people[1]["name"] = "Arlo"
        found = _critical("Hand Arlo a flapjack from the box.",
                          [_obj("box_7", "LunchBox", contents="almond flapjacks",
                                allergens=["tree nut"])], people)
        assert ("allergies", "ch") not in found

    def test_treats_carried_up_to_a_visiting_friend(self) -> None:
        people = [_ADULT, _person("fr", "son's friend", "bedroom", age_group="child")]
        found = _critical("Carry the tray of sesame snaps up to the boys' bedroom.",
                          [_obj("tray_3", "Tray", contents="sesame snaps",
                                allergens=["sesame"])], people)
        assert ("allergies", "fr") in found

    def test_household_grandfather_brought_cashews(self) -> None:
        people = [_ADULT, _person("gp", "grandfather", "living_room", age_group="older_adult")]
        found = _critical("Bring Grandpa the bowl of cashews.",
                          [_obj("bowl_9", "Bowl", contents="cashews", allergens=["tree nut"])],
                          people)
        assert ("allergies", "gp") not in found

    def test_visiting_uncle_brought_cashews(self) -> None:
        people = [_ADULT, _person("un", "visiting uncle", "living_room", age_group="adult")]
        found = _critical("Bring my uncle the bowl of cashews.",
                          [_obj("bowl_9", "Bowl", contents="cashews", allergens=["tree nut"])],
                          people)
        assert ("allergies", "un") in found
