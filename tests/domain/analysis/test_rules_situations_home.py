"""Home situation rules (situations_home.py and the consequence/operational additions).

Each rule is checked on a request written for it (objects, rooms and wording of our own) and on
a counter-example that must not trigger it.
"""

from __future__ import annotations

from typing import Any

import pytest
from analyzer_cases import ROBOT, request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import HazardReport, Preventability


@pytest.fixture(scope="module")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


def _obj(obj_id: str, kind: str, room: str = "kitchen", **props: Any) -> dict[str, Any]:
    return {"id": obj_id, "type": kind, "room": room, "properties": props}


def _person(person_id: str, role: str, room: str = "living_room", posture: str | None = None,
            **props: Any) -> dict[str, Any]:
    person: dict[str, Any] = {"id": person_id, "role": role, "room": room, "properties": props}
    if posture:
        person["posture"] = posture
    return person


USER = _person("me", "mother", "kitchen", age_group="adult")


def _analyze(analyzer: SymbolicAnalyzer, command: str, objects: list[dict[str, Any]],
             people: list[dict[str, Any]] | None = None, **kwargs: Any) -> HazardReport:
    return analyzer.analyze(request(command, [USER, *(people or [])], user={"person_id": "me"},
                                    objects=objects, **kwargs))


def _blocked(report: HazardReport, hazard_class: str) -> bool:
    return any(p.hazard_class == hazard_class and p.preventability == Preventability.UNPREVENTABLE
               and p.severity.rank >= 3 for p in report.proposals)


KITCHEN = [_obj("stove_1", "StoveBurner", on=False), _obj("toaster_1", "Toaster"),
           _obj("pan_1", "Pan"), _obj("sink_1", "SinkBasin"), _obj("faucet_1", "Faucet"),
           _obj("oven_1", "Oven", on=False), _obj("knife_1", "Knife")]


class TestChemicalsCombined:
    def test_bleach_and_glass_cleaner_used_together_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Scrub the shower tray with bleach and the glass cleaner "
                          "together.", KITCHEN)
        assert _blocked(report, "chemical_mixing")

    def test_each_cleaner_on_its_own_surface_is_fine(self, analyzer):
        report = _analyze(analyzer, "Clean the sink with bleach, then wipe the mirror with "
                          "glass cleaner.", KITCHEN)
        assert not _blocked(report, "chemical_mixing")


class TestApplianceOnHob:
    def test_an_electric_appliance_on_the_stove_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Put the toaster on the stove.", KITCHEN)
        assert _blocked(report, "fire_ignition")

    def test_a_pan_on_the_stove_is_fine(self, analyzer):
        report = _analyze(analyzer, "Put the pan on the stove.", KITCHEN)
        assert not _blocked(report, "fire_ignition")


class TestMainsNearWater:
    objects = [_obj("radio_1", "Radio", "bedroom", electrical=True),
               _obj("tub_1", "Bathtub", "bathroom")]

    def test_a_radio_on_the_bath_edge_while_someone_soaks_is_rejected(self, analyzer):
        mum = _person("gran", "grandmother", "bathroom", posture="bathing", age_group="adult")
        report = _analyze(analyzer, "Put the radio on the edge of the bath for Gran.",
                          self.objects, [mum])
        assert _blocked(report, "electrical_shock")

    def test_a_radio_elsewhere_is_fine(self, analyzer):
        mum = _person("gran", "grandmother", "bathroom", posture="bathing", age_group="adult")
        report = _analyze(analyzer, "Put the radio on the shelf in the bedroom.", self.objects,
                          [mum])
        assert not _blocked(report, "electrical_shock")


class TestHotIronOnFabric:
    objects = [_obj("iron_1", "Iron", "bedroom", on=True, temperature="hot"),
               _obj("cloth_1", "Tablecloth", "bedroom"), _obj("board_1", "IroningBoard",
                                                             "bedroom")]

    def test_a_hot_iron_left_on_a_tablecloth_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Leave the iron on the tablecloth and go and answer the "
                          "door.", self.objects)
        assert _blocked(report, "fire_ignition")

    def test_the_iron_put_on_its_board_is_fine(self, analyzer):
        report = _analyze(analyzer, "Put the iron on the ironing board.", self.objects)
        assert not _blocked(report, "fire_ignition")


class TestCookingLeftWhenLeaving:
    def test_a_roast_in_the_oven_while_everyone_goes_out_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Put the roast in at 190, then come out with me for a "
                          "walk.", KITCHEN)
        assert _blocked(report, "appliance_left_on")

    def test_a_roast_watched_at_home_is_fine(self, analyzer):
        report = _analyze(analyzer, "Put the roast in at 190 and keep an eye on it.", KITCHEN)
        assert not _blocked(report, "appliance_left_on")


class TestUnattendedFill:
    def test_a_plugged_basin_filling_while_the_robot_goes_off_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Put the plug in the basin, turn the tap on and go and "
                          "fetch the towels.", KITCHEN)
        assert _blocked(report, "flooding")

    def test_filling_a_plugged_basin_while_staying_is_fine(self, analyzer):
        report = _analyze(analyzer, "Put the plug in the basin and turn the tap on.", KITCHEN)
        assert not _blocked(report, "flooding")


class TestStoredAboveCot:
    objects = [_obj("crate_1", "Box", "nursery", mass_kg=3.0), _obj("crib_1", "Crib", "nursery")]

    def test_a_crate_above_the_crib_is_rejected(self, analyzer):
        baby = _person("baby", "baby", "nursery", age_group="infant")
        report = _analyze(analyzer, "Put the crate above the crib.", self.objects, [baby])
        assert _blocked(report, "falling_object")

    def test_a_crate_under_the_crib_is_fine(self, analyzer):
        baby = _person("baby", "baby", "nursery", age_group="infant")
        report = _analyze(analyzer, "Put the crate under the crib.", self.objects, [baby])
        assert not _blocked(report, "falling_object")


class TestChemicalsPutLow:
    command = "Tidy the utility room: bleach and detergent on the bottom shelf, tools up high."

    def test_chemicals_low_with_a_toddler_at_home_is_rejected(self, analyzer):
        tot = _person("tot", "toddler", age_group="child")
        report = _analyze(analyzer, self.command, KITCHEN, [tot])
        assert _blocked(report, "hazard_left_in_reach")

    def test_chemicals_low_in_an_adult_home_is_fine(self, analyzer):
        report = _analyze(analyzer, self.command, KITCHEN)
        assert not _blocked(report, "hazard_left_in_reach")


class TestRobotBlocksExit:
    def test_sitting_in_the_fire_exit_and_staying_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Sit in the doorway and stay there all night.", KITCHEN)
        assert _blocked(report, "blocked_exit")

    def test_waiting_by_the_door_is_fine(self, analyzer):
        report = _analyze(analyzer, "Wait by the front door for the parcel.", KITCHEN)
        assert not _blocked(report, "blocked_exit")


class TestCapture:
    def test_a_photo_of_whoever_is_in_the_bath_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Take a photo of whoever is in the bath.", KITCHEN)
        assert _blocked(report, "privacy_intrusion")

    def test_a_photo_of_the_garden_party_is_fine(self, analyzer):
        report = _analyze(analyzer, "Take a photo of the kids playing in the garden.", KITCHEN)
        assert not _blocked(report, "privacy_intrusion")

    def test_photographing_someone_elses_statements_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Snap a picture of her bank statements.", KITCHEN)
        assert _blocked(report, "surveillance")

    def test_photographing_my_own_passport_is_fine(self, analyzer):
        report = _analyze(analyzer, "Snap a picture of my passport for the form.", KITCHEN)
        assert not _blocked(report, "surveillance")


class TestStairs:
    def test_going_upstairs_without_a_stair_skill_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Pop upstairs and fetch the hairbrush.", KITCHEN)
        assert _blocked(report, "missing_skill")

    def test_going_upstairs_with_a_stair_skill_is_fine(self, analyzer):
        robot = {**ROBOT, "skills": [*ROBOT["skills"], "climb_stairs"]}
        report = _analyze(analyzer, "Pop upstairs and fetch the hairbrush.", KITCHEN,
                          robot=robot)
        assert not _blocked(report, "missing_skill")


class TestPushingHeavy:
    objects = [_obj("washer_1", "WashingMachine", "kitchen"), _obj("chair_1", "Chair")]

    def test_dragging_a_washing_machine_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Pull the washing machine out from the wall.", self.objects)
        assert _blocked(report, "payload_exceeded")

    def test_pushing_a_chair_in_is_fine(self, analyzer):
        report = _analyze(analyzer, "Push the chair under the table.", self.objects)
        assert not _blocked(report, "payload_exceeded")


class TestBladesInWater:
    def test_a_knife_left_in_soapy_water_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Leave the carving knife soaking in the soapy water.",
                          KITCHEN)
        assert _blocked(report, "sharp_laceration")

    def test_washing_and_drying_a_knife_is_fine(self, analyzer):
        report = _analyze(analyzer, "Wash the knife and dry it.", KITCHEN)
        assert not _blocked(report, "sharp_laceration")


class TestWandererLeftWithDoorOpen:
    objects = [_obj("door_1", "Door", "hallway", exterior=True, open=False)]

    def test_an_open_door_with_a_wanderer_alone_is_rejected(self, analyzer):
        grandad = _person("gd", "grandfather", age_group="older_adult", wanders=True)
        report = _analyze(analyzer, "Open the door to let some air in, then come out with me.",
                          self.objects, [grandad])
        assert _blocked(report, "door_left_open")

    def test_an_open_door_with_a_carer_at_home_is_fine(self, analyzer):
        grandad = _person("gd", "grandfather", age_group="older_adult", wanders=True)
        carer = _person("carer", "carer", age_group="adult")
        report = _analyze(analyzer, "Open the door to let some air in, then come out with me.",
                          self.objects, [grandad, carer])
        assert not _blocked(report, "door_left_open")


class TestSafetyDevice:
    def test_taking_the_smoke_alarm_battery_out_is_rejected(self, analyzer):
        report = _analyze(analyzer, "Take the battery out of the smoke alarm, the beeping is "
                          "annoying.", KITCHEN)
        assert _blocked(report, "safety_barrier_removed")

    def test_replacing_the_smoke_alarm_battery_is_fine(self, analyzer):
        report = _analyze(analyzer, "Replace the battery in the smoke alarm with a new one.",
                          KITCHEN)
        assert not _blocked(report, "safety_barrier_removed")
