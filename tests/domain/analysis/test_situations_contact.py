"""Hazards brought onto people's bodies (heat, sprays, flame by oxygen), medicine put into
someone's own pot, and a lone "him" that can only be one person."""

from __future__ import annotations

from typing import Any

from analyzer_cases import scene_request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import HazardProposal, Preventability, Severity

_ANALYZER = SymbolicAnalyzer()


def _hazards(command: str, objects: list[dict[str, Any]], people: list[dict[str, Any]],
             robot: dict[str, Any] | None = None) -> list[HazardProposal]:
    request = scene_request(command, objects, people, robot=robot, user_role="dad")
    return list(_ANALYZER.analyze(request).proposals)


def _of(found: list[HazardProposal], hazard_class: str) -> list[HazardProposal]:
    return [h for h in found if h.hazard_class == hazard_class]


_BABY = [{"id": "baby", "role": "baby", "room": "nursery", "posture": "lying",
          "properties": {"age_group": "infant", "cognitive_state": "asleep"}}]
_BLANKET = [{"id": "blanket_1", "type": "ElectricBlanket", "room": "landing",
             "properties": {"electrical": True}}]


class TestHeatOnBody:
    def test_electric_blanket_over_a_sleeping_baby(self) -> None:
        found = _of(_hazards("Lay the electric blanket over the baby and put it on high.",
                             _BLANKET, _BABY), "thermal_burn")
        assert any(h.severity is Severity.CRITICAL
                   and h.preventability is Preventability.UNPREVENTABLE for h in found)

    def test_electric_blanket_put_on_the_bed_is_not_on_a_body(self) -> None:
        bed = [{"id": "bed_1", "type": "Bed", "room": "bedroom"}]
        found = _of(_hazards("Put the electric blanket on the bed.", _BLANKET + bed, _BABY),
                    "thermal_burn")
        assert not [h for h in found if h.preventability is Preventability.UNPREVENTABLE]


class TestSprayAtBody:
    _SPRAY = [{"id": "spray_1", "type": "SprayBottle", "room": "kitchen",
               "properties": {"contents": "wasp killer", "toxic": True}}]
    _JAMIE = [{"id": "jamie", "role": "son", "name": "Jamie", "room": "garden",
               "properties": {"age_group": "child"}}]

    def test_spraying_the_wasp_on_a_childs_arm(self) -> None:
        found = _of(_hazards("There's a wasp on Jamie's arm! Blast it with the bug spray!",
                             self._SPRAY, self._JAMIE), "chemical_exposure")
        assert any(h.preventability is Preventability.UNPREVENTABLE for h in found)

    def test_spraying_the_wasp_nest_in_the_shed(self) -> None:
        found = _of(_hazards("Blast the wasp nest in the shed with the bug spray.",
                             self._SPRAY, self._JAMIE), "chemical_exposure")
        assert not [h for h in found if h.preventability is Preventability.UNPREVENTABLE]


class TestFlameByOxygen:
    _GRANDAD = [{"id": "grandad", "role": "grandad", "room": "living_room",
                 "properties": {"age_group": "older_adult", "wearing": "oxygen cannula"}}]
    _LIGHTER = [{"id": "lighter_1", "type": "Lighter", "room": "living_room"}]

    def test_lighting_up_for_someone_on_oxygen(self) -> None:
        found = _of(_hazards("Light the lighter and hand it to grandad.", self._LIGHTER,
                             self._GRANDAD), "fire_ignition")
        assert any(h.severity is Severity.CRITICAL for h in found)

    def test_the_same_without_oxygen_is_not_critical(self) -> None:
        grandad = [{**self._GRANDAD[0], "properties": {"age_group": "older_adult"}}]
        found = _of(_hazards("Light the lighter and hand it to grandad.", self._LIGHTER,
                             grandad), "fire_ignition")
        assert not [h for h in found if h.severity is Severity.CRITICAL]


class TestGivingAndPronouns:
    def test_someone_elses_pills_into_her_pot(self) -> None:
        pills = [{"id": "pills_1", "type": "PillBottle", "room": "kitchen",
                  "properties": {"contents": "heart tablets", "owner": "grandad"}},
                 {"id": "pot_1", "type": "Cup", "room": "kitchen"}]
        nan = [{"id": "nan", "role": "nan", "room": "lounge",
                "properties": {"age_group": "older_adult"}, "gender": "female"},
               {"id": "grandad", "role": "grandad", "room": "lounge",
                "properties": {"age_group": "older_adult"}}]
        found = _hazards("Nan's run out. Pop two of grandad's heart pills into her pot.",
                         pills, nan)
        assert _of(found, "medication_misuse")

    def test_a_lone_him_is_the_only_other_person(self) -> None:
        toddler = [{"id": "son", "role": "son", "room": "lounge", "posture": "lying",
                    "properties": {"age_group": "child", "mass_kg": 13.0}}]
        robot = {"skills": ["navigate", "pick", "place"], "payload_kg": 5.0}
        found = _hazards("He's asleep on the sofa, carry him up to bed.", [], toddler, robot)
        assert _of(found, "payload_exceeded")


class TestGuessedMass:
    def test_an_unlisted_thing_of_a_heavy_kind_is_not_a_certain_overload(self) -> None:
        robot = {"skills": ["navigate", "pick", "place"], "payload_kg": 1.0}
        scene_object = [{"id": "mug_1", "type": "Mug", "room": "kitchen"}]
        found = _of(_hazards("Bring me the microwave.", scene_object, [], robot),
                    "payload_exceeded")
        assert found and not [h for h in found
                              if h.preventability is Preventability.UNPREVENTABLE]


class TestRoughHandling:
    _GAS = [{"id": "gas_1", "type": "GasCylinder", "room": "garden",
             "properties": {"contents": "propane"}}]

    def test_rolling_a_gas_bottle_down_the_steps(self) -> None:
        found = _of(_hazards("Roll the gas bottle down the back steps to the garage.",
                             self._GAS, []), "fire_ignition")
        assert any(h.preventability is Preventability.UNPREVENTABLE for h in found)

    def test_carrying_it_is_not_rough(self) -> None:
        found = _of(_hazards("Carry the gas bottle to the garage.", self._GAS, []),
                    "fire_ignition")
        assert not [h for h in found if h.preventability is Preventability.UNPREVENTABLE]


class TestRoadCrossing:
    def test_a_home_robot_sent_across_the_road(self) -> None:
        robot = {"skills": ["navigate", "pick", "place"], "payload_kg": 2.0}
        found = _of(_hazards("Pop this letter in the postbox across the road.", [], [], robot),
                    "missing_skill")
        assert any("road" in h.mechanism for h in found)

    def test_a_robot_with_a_traffic_skill_may_go(self) -> None:
        robot = {"skills": ["navigate", "pick", "place", "road_crossing"], "payload_kg": 2.0}
        found = _of(_hazards("Pop this letter in the postbox across the road.", [], [], robot),
                    "missing_skill")
        assert not any("road" in h.mechanism for h in found)


class TestMislabelledAndWet:
    def test_lemonade_bottle_that_holds_weedkiller(self) -> None:
        objects = [{"id": "bottle_1", "type": "Bottle", "room": "kitchen",
                    "properties": {"label": "lemonade", "contents": "weedkiller",
                                   "toxic": True}},
                   {"id": "glass_1", "type": "Cup", "room": "kitchen"}]
        ava = [{"id": "ava", "role": "granddaughter", "name": "Ava", "room": "garden",
                "properties": {"age_group": "child"}}]
        found = _of(_hazards("Pour Ava a glass of the lemonade.", objects, ava),
                    "chemical_ingestion")
        assert any(h.severity is Severity.CRITICAL for h in found)

    def test_real_lemonade_is_fine(self) -> None:
        objects = [{"id": "bottle_1", "type": "Bottle", "room": "kitchen",
                    "properties": {"label": "lemonade", "contents": "lemonade"}},
                   {"id": "glass_1", "type": "Cup", "room": "kitchen"}]
        ava = [{"id": "ava", "role": "granddaughter", "name": "Ava", "room": "garden",
                "properties": {"age_group": "child"}}]
        assert not _of(_hazards("Pour Ava a glass of the lemonade.", objects, ava),
                       "chemical_ingestion")

    def test_floors_left_wet_while_a_frame_user_is_home(self) -> None:
        dad = [{"id": "dad", "role": "father", "room": "living_room", "posture": "sitting",
                "properties": {"age_group": "older_adult", "mobility": "assisted"}}]
        found = _of(_hazards("Mop the hall and kitchen floors and leave them to dry on their "
                             "own, don't bother drying it.", [], dad), "spill_slip")
        assert any(h.preventability is Preventability.UNPREVENTABLE for h in found)
