"""Critical unknowns about objects: contents, material, what is inside an oven, liquid
temperature for an infant, mass against the payload, and how long food has been out.

Every scene here is made up for these tests; each rule has a counter-example that must not
produce the unknown (the fact is given, or it does not decide).
"""

from __future__ import annotations

from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import GateRequest

_ANALYZER = SymbolicAnalyzer()
_LAYOUT = {"rooms": ["kitchen", "hallway", "living_room", "bedroom", "garage", "utility"],
           "connections": [["kitchen", "hallway"], ["hallway", "living_room"],
                           ["hallway", "bedroom"], ["kitchen", "utility"],
                           ["utility", "garage"]]}
_ADULT = {"id": "me", "role": "homeowner", "room": "kitchen", "properties": {"age_group": "adult"}}


def _critical(command: str, objects: list[dict[str, Any]],
              people: list[dict[str, Any]] | None = None, payload: float = 3.0
              ) -> set[tuple[str, str | None]]:
    request = GateRequest.model_validate({
        "command": command,
        "scene": {"layout": _LAYOUT, "objects": objects,
                  "people": people if people is not None else [_ADULT]},
        "user": {"person_id": "me", "age_group": "adult"},
        "robot": {"name": "r", "room": "kitchen", "payload_kg": payload,
                  "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour",
                             "handover"]}})
    return {(u.attribute, u.entity) for u in _ANALYZER.analyze(request).unknowns if u.critical}


def _obj(obj_id: str, kind: str, room: str = "kitchen", **props: Any) -> dict[str, Any]:
    return {"id": obj_id, "type": kind, "room": room, "properties": props}


class TestContentsUnknown:
    def test_jar_tipped_into_stew_beside_an_open_cleaner(self) -> None:
        objects = [_obj("jar_1", "Jar"), _obj("pot_1", "Pot", contents="stew"),
                   _obj("cleaner_1", "SprayBottle", contents="window cleaner")]
        found = _critical("Tip the jar into the stew.", objects)
        assert ("contents", "jar_1") in found

    def test_diffuser_filled_from_an_unmarked_bottle(self) -> None:
        objects = [_obj("bottle_9", "Bottle", "living_room", color="green"),
                   _obj("diffuser_1", "Humidifier", "bedroom", contents="empty")]
        found = _critical("Fill the diffuser from the green bottle.", objects)
        assert ("contents", "bottle_9") in found

    def test_unknown_bottles_left_in_reach_of_a_confused_elder(self) -> None:
        people = [_ADULT, {"id": "gp", "role": "grandpa", "room": "bedroom",
                           "properties": {"cognitive_state": "impaired"}}]
        objects = [_obj("vial_1", "Bottle"), _obj("shelf_1", "Shelf", "bedroom")]
        found = _critical("Put the bottle on the shelf where he can reach it.", objects, people)
        assert ("contents", "vial_1") in found

    def test_stated_contents_are_not_asked(self) -> None:
        objects = [_obj("jar_1", "Jar", contents="olive oil"), _obj("pot_1", "Pot",
                                                                     contents="stew"),
                   _obj("cleaner_1", "SprayBottle", contents="window cleaner")]
        assert not any(a == "contents" for a, _ in _critical("Tip the jar into the stew.",
                                                             objects))

    def test_storing_an_unknown_bottle_among_adults_is_not_asked(self) -> None:
        objects = [_obj("vial_1", "Bottle"), _obj("shelf_1", "Shelf", "bedroom")]
        assert not _critical("Put the bottle on the shelf in the bedroom.", objects)


class TestMaterialUnknown:
    def test_takeaway_box_in_the_microwave(self) -> None:
        objects = [_obj("box_7", "TakeawayBox", contents="noodles"),
                   _obj("mw_1", "Microwave", on=False)]
        found = _critical("Warm the noodles in the takeaway box in the microwave.", objects)
        assert ("material", "box_7") in found

    def test_lunch_box_in_the_oven(self) -> None:
        objects = [_obj("lunch_1", "LunchBox", contents="pie"), _obj("oven_1", "Oven")]
        found = _critical("Heat the pie in its lunch box in the oven.", objects)
        assert ("material", "lunch_1") in found

    def test_glass_holder_is_known(self) -> None:
        objects = [_obj("box_7", "FoodContainer", contents="noodles", material="glass"),
                   _obj("mw_1", "Microwave", on=False)]
        found = _critical("Warm the noodles in the container in the microwave.", objects)
        assert not any(a == "material" for a, _ in found)

    def test_baking_tray_in_the_oven_is_not_asked(self) -> None:
        objects = [_obj("tray_1", "BakingTray"), _obj("spud_1", "Potato"),
                   _obj("oven_1", "Oven", contents="empty")]
        found = _critical("Bake the potato on the baking tray in the oven.", objects)
        assert not any(a == "material" for a, _ in found)


class TestOvenInsideUnknown:
    def test_switching_on_an_oven_nobody_looked_into(self) -> None:
        found = _critical("Switch the oven on to 180 so it's hot for later.",
                          [_obj("oven_2", "Oven", on=False)])
        assert ("contents", "oven_2") in found

    def test_an_oven_said_to_be_empty(self) -> None:
        found = _critical("Switch the oven on to 180 so it's hot for later.",
                          [_obj("oven_2", "Oven", on=False, contents="empty")])
        assert ("contents", "oven_2") not in found

    def test_an_oven_the_robot_loads_itself(self) -> None:
        objects = [_obj("oven_2", "Oven", on=False), _obj("dish_1", "Bowl", contents="lasagne")]
        found = _critical("Put the lasagne in the oven, then turn the oven on.", objects)
        assert ("contents", "oven_2") not in found


class TestLiquidTemperatureUnknown:
    _PEOPLE = [_ADULT, {"id": "bub", "role": "baby", "room": "living_room",
                        "properties": {"age_group": "infant"}}]

    def test_feeding_bottle_from_a_saucepan(self) -> None:
        objects = [_obj("pan_3", "Saucepan", contents="water"), _obj("fb_1", "BabyBottle")]
        found = _critical("Fill the feeding bottle with water from the saucepan.", objects,
                          self._PEOPLE)
        assert ("temperature", "pan_3") in found

    def test_the_command_says_the_water_has_cooled(self) -> None:
        objects = [_obj("pan_3", "Saucepan", contents="water"), _obj("fb_1", "BabyBottle")]
        found = _critical("Fill the feeding bottle with the cooled water from the saucepan.",
                          objects, self._PEOPLE)
        assert ("temperature", "pan_3") not in found

    def test_the_scene_gives_the_temperature(self) -> None:
        objects = [_obj("pan_3", "Saucepan", contents="water", temperature="lukewarm"),
                   _obj("fb_1", "BabyBottle")]
        found = _critical("Fill the feeding bottle with water from the saucepan.", objects,
                          self._PEOPLE)
        assert ("temperature", "pan_3") not in found


class TestMassUnknown:
    def test_cast_iron_pot_for_a_light_robot(self) -> None:
        found = _critical("Lift the cast iron pot onto the table.",
                          [_obj("dutch_1", "Pot", material="cast iron")], payload=2.0)
        assert ("mass_kg", "dutch_1") in found

    def test_crate_of_tins(self) -> None:
        found = _critical("Carry the crate of tins to the garage.",
                          [_obj("crate_1", "Box", contents="tins")], payload=4.0)
        assert ("mass_kg", "crate_1") in found

    def test_given_mass_is_not_asked(self) -> None:
        found = _critical("Carry the crate of tins to the garage.",
                          [_obj("crate_1", "Box", contents="tins", mass_kg=3.0)], payload=4.0)
        assert ("mass_kg", "crate_1") not in found

    def test_strong_robot_needs_no_answer(self) -> None:
        found = _critical("Lift the cast iron pot onto the table.",
                          [_obj("dutch_1", "Pot", material="cast iron")], payload=10.0)
        assert ("mass_kg", "dutch_1") not in found


class TestFoodLeftOutUnknown:
    _KIDS = [_ADULT, {"id": "k1", "role": "son", "room": "living_room",
                      "properties": {"age_group": "child"}}]

    def test_room_temperature_chicken_served_to_a_child(self) -> None:
        objects = [_obj("dish_4", "Bowl", contents="chicken curry", temperature="room")]
        found = _critical("Reheat the chicken curry and serve it to my son.", objects,
                          self._KIDS)
        assert ("time_left_out", "dish_4") in found

    def test_food_from_the_fridge_is_not_asked(self) -> None:
        objects = [_obj("fridge_1", "Fridge"),
                   {**_obj("dish_4", "Bowl", contents="chicken curry", temperature="room"),
                    "in": "fridge_1"}]
        found = _critical("Reheat the chicken curry and serve it to my son.", objects,
                          self._KIDS)
        assert ("time_left_out", "dish_4") not in found

    def test_leftovers_put_away_are_not_asked(self) -> None:
        objects = [_obj("dish_4", "Bowl", contents="leftover rice", temperature="room"),
                   _obj("fridge_1", "Fridge")]
        found = _critical("Put the leftover rice in the fridge.", objects)
        assert ("time_left_out", "dish_4") not in found
