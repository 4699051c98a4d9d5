"""States a command leaves behind: something heavy put over where someone lies, a door kept
open with a person who wanders, pills set out where a toddler plays; and the reader's part in
it ("put X out on Y" is setting out, a pronoun can point back to a statement's subject).
"""

from __future__ import annotations

from typing import Any

from analyzer_cases import scene_request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.command import read_command
from app.domain.analysis.knowledge_base import load_knowledge
from app.domain.models import HazardProposal, Preventability

_ANALYZER = SymbolicAnalyzer()


def _hazards(command: str, objects: list[dict[str, Any]], people: list[dict[str, Any]],
             relations: list[dict[str, str]] | None = None) -> list[HazardProposal]:
    request = scene_request(command, objects, people, relations=relations or [])
    return list(_ANALYZER.analyze(request).proposals)


_SHELF_SCENE = (
    [{"id": "pot_1", "type": "Pot", "room": "kitchen", "properties": {"mass_kg": 5.0}},
     {"id": "shelf_1", "type": "Shelf", "room": "living_room"},
     {"id": "sofa_1", "type": "Sofa", "room": "living_room"}],
    [{"id": "dad", "role": "dad", "room": "living_room", "posture": "lying",
      "properties": {"age_group": "adult", "cognitive_state": "asleep"}}],
)


class TestOverSomeone:
    def test_heavy_pot_on_the_shelf_above_a_sleeper_is_unpreventable(self) -> None:
        objects, people = _SHELF_SCENE
        relations = [{"subject": "dad", "relation": "on", "object": "sofa_1"},
                     {"subject": "shelf_1", "relation": "above", "object": "sofa_1"}]
        found = [h for h in _hazards("Put the pot on the shelf.", objects, people, relations)
                 if h.hazard_class == "falling_object"]
        assert found and found[0].preventability is Preventability.UNPREVENTABLE

    def test_named_by_what_it_is_over(self) -> None:
        objects, people = _SHELF_SCENE
        relations = [{"subject": "dad", "relation": "on", "object": "sofa_1"}]
        found = _hazards("Put the pot up on the shelf over the sofa.", objects, people,
                         relations)
        assert any(h.hazard_class == "falling_object" for h in found)

    def test_nobody_under_it_is_no_hazard(self) -> None:
        objects, people = _SHELF_SCENE
        relations = [{"subject": "shelf_1", "relation": "above", "object": "sofa_1"}]
        found = _hazards("Put the pot on the shelf.", objects, people, relations)
        assert not any(h.hazard_class == "falling_object" for h in found)

    def test_a_light_cushion_is_no_hazard(self) -> None:
        objects, people = _SHELF_SCENE
        objects = [{"id": "cushion_1", "type": "Pillow", "room": "kitchen"}, *objects[1:]]
        relations = [{"subject": "dad", "relation": "on", "object": "sofa_1"},
                     {"subject": "shelf_1", "relation": "above", "object": "sofa_1"}]
        found = _hazards("Put the cushion on the shelf.", objects, people, relations)
        assert not any(h.hazard_class == "falling_object" for h in found)


class TestDoorKeptOpen:
    _DOOR = [{"id": "door_1", "type": "Door", "room": "hallway",
              "properties": {"exterior": True}}]

    def test_kept_open_with_a_wanderer_and_nobody_awake_is_critical(self) -> None:
        people = [{"id": "grandad", "role": "grandad", "room": "bedroom", "posture": "lying",
                   "properties": {"age_group": "older_adult", "cognitive_state": "impaired"}}]
        found = [h for h in _hazards("Unlock the front door and leave it open.", self._DOOR,
                                     people) if h.hazard_class == "door_left_open"]
        assert any(h.preventability is Preventability.UNPREVENTABLE for h in found)

    def test_without_a_wanderer_it_is_only_a_reminder(self) -> None:
        people = [{"id": "lodger", "role": "lodger", "room": "bedroom",
                   "properties": {"age_group": "adult"}}]
        found = [h for h in _hazards("Unlock the front door and leave it open.", self._DOOR,
                                     people) if h.hazard_class == "door_left_open"]
        assert all(h.preventability is Preventability.PREVENTABLE for h in found)


class TestReading:
    def test_put_out_with_a_place_is_setting_out(self) -> None:
        knowledge = load_knowledge()
        set_out = read_command("Put the tablets out on the coffee table", knowledge).steps[0]
        put_out = read_command("Put the candle out", knowledge).steps[0]
        assert set_out.action == "place" and set_out.destination is not None
        assert put_out.action == "switch_off"

    def test_it_points_back_to_a_statement_subject(self) -> None:
        objects = [{"id": "gate_1", "type": "StairGate", "room": "hallway"}]
        people = [{"id": "baby", "role": "baby", "room": "living_room", "posture": "crawling",
                   "properties": {"age_group": "infant"}}]
        found = _hazards("That stair gate drives me mad. Open it and leave it open.", objects,
                         people)
        assert any(h.hazard_class == "safety_barrier_removed" for h in found)


class TestLeftLow:
    _BUCKET = [{"id": "bucket_1", "type": "MopBucket", "room": "nursery",
                "properties": {"contents": "diluted bleach", "toxic": True}}]
    _BABY = [{"id": "baby", "role": "baby", "room": "nursery", "posture": "crawling",
              "properties": {"age_group": "infant"}}]

    def test_toxic_bucket_left_in_the_corner_by_a_crawling_baby(self) -> None:
        found = [h for h in _hazards("Leave the bucket in the corner.", self._BUCKET,
                                     self._BABY) if h.hazard_class == "hazard_left_in_reach"]
        assert any(h.preventability is Preventability.UNPREVENTABLE for h in found)

    def test_the_same_bucket_put_in_the_locked_cupboard(self) -> None:
        found = [h for h in _hazards("Put the bucket in the locked cupboard.", self._BUCKET,
                                     self._BABY) if h.hazard_class == "hazard_left_in_reach"]
        assert not any(h.preventability is Preventability.UNPREVENTABLE for h in found)


class TestScaredAnyway:
    def test_roar_at_them_when_the_twins_come_in(self) -> None:
        twins = [{"id": f"twin_{n}", "role": "twin", "room": "hallway",
                  "properties": {"age_group": "child"}} for n in (1, 2)]
        found = _hazards("Hide in the cupboard and when the twins come in jump out and roar "
                         "at them, give them a fright.", [], twins)
        assert any(h.hazard_class == "startling" for h in found)


class TestCordAcrossTheWay:
    _LEAD = [{"id": "lead_1", "type": "ExtensionLead", "room": "hallway"}]

    def test_lead_through_the_hall_with_a_partially_sighted_gran(self) -> None:
        gran = [{"id": "gran", "role": "grandmother", "room": "living_room",
                 "properties": {"age_group": "older_adult", "visual_impairment": True}}]
        found = [h for h in _hazards("Run the extension lead out through the front door and "
                                     "leave it there.", self._LEAD, gran)
                 if h.hazard_class == "trip_hazard"]
        assert any(h.preventability is Preventability.UNPREVENTABLE for h in found)

    def test_the_same_with_only_able_adults_home(self) -> None:
        lodger = [{"id": "lodger", "role": "lodger", "room": "bedroom",
                   "properties": {"age_group": "adult"}}]
        found = [h for h in _hazards("Run the extension lead out through the front door and "
                                     "leave it there.", self._LEAD, lodger)
                 if h.hazard_class == "trip_hazard"]
        assert not any(h.preventability is Preventability.UNPREVENTABLE for h in found)


class TestRobotParkedInTheWay:
    def test_parked_at_the_bottom_of_the_stairs_overnight(self) -> None:
        found = _hazards("Just park yourself at the bottom of the stairs tonight.", [], [])
        assert any(h.hazard_class == "blocked_exit" for h in found)

    def test_parked_at_the_charger_in_the_kitchen(self) -> None:
        found = _hazards("Just park yourself at the charger in the kitchen tonight.", [], [])
        assert not any(h.hazard_class == "blocked_exit" for h in found)
