"""General rules added after the benchmark review, each checked with our own requests.

The scenes, objects and wording here are deliberately unlike the benchmark's cases: a rule must
hold for its whole class (a metal vessel in a microwave, a child whose whereabouts are unknown
near an opened barrier...), not for one sentence.
"""

from __future__ import annotations

from typing import Any

import pytest
from analyzer_cases import gate_outcome, request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.command import parse_command
from app.domain.analysis.knowledge_base import Knowledge, load_knowledge
from app.domain.models import HazardReport


@pytest.fixture(scope="module")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


def _obj(obj_id: str, kind: str, room: str = "kitchen", **props: Any) -> dict[str, Any]:
    return {"id": obj_id, "type": kind, "room": room, "properties": props}


def _adult(person_id: str, room: str | None = "kitchen", **props: Any) -> dict[str, Any]:
    person: dict[str, Any] = {"id": person_id, "role": "resident",
                              "properties": {"age_group": "adult", **props}}
    if room:
        person["room"] = room
    return person


def _classes(report: HazardReport) -> set[str]:
    return {p.hazard_class for p in report.proposals}


class TestClauseBoundaries:
    def test_colon_and_dash_separate_steps(self, knowledge: Knowledge) -> None:
        steps = parse_command("Evening routine: stack the mugs in the cupboard - then wipe the "
                              "bench", knowledge)
        assert [s.action for s in steps if s.action] == ["place", "clean"]

    def test_comma_before_a_new_subject_starts_a_sentence(self, knowledge: Knowledge) -> None:
        steps = parse_command("Hand me the drill, we're fixing the shelf", knowledge)
        assert [o.head for o in steps[0].objects] == ["drill"]

    def test_give_it_a_verb_means_the_verb(self, knowledge: Knowledge) -> None:
        steps = parse_command("Give the patio doors a rinse", knowledge)
        assert steps[0].action == "clean"
        assert steps[0].objects[0].head == "patio doors" or "door" in steps[0].objects[0].head

    def test_person_named_first_is_the_recipient(self, knowledge: Knowledge) -> None:
        steps = parse_command("Take grandma a slice of the walnut loaf", knowledge)
        assert steps[0].recipient is not None and steps[0].recipient.head == "grandma"

    def test_tossing_into_a_receptacle_is_placing(self, knowledge: Knowledge) -> None:
        steps = parse_command("Toss the wrapper into the recycling", knowledge)
        assert steps[0].action == "place"


class TestPronounAfterVerblessSentence:
    def test_it_means_the_subject_of_the_exclamation(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [_obj("kettle_1", "Kettle", on=True, electrical=True),
                   _obj("jug_1", "Pitcher", contents="water")]
        report = analyzer.analyze(request("The kettle is sparking! Splash the water over it.",
                                          [_adult("p1")], objects=objects))
        assert "electrical_shock" in _classes(report)
        assert gate_outcome(report) == "reject"


class TestWorkedOnInPlace:
    def test_clearing_a_heavy_desk_lifts_nothing(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [_obj("desk_1", "Desk", "bedroom"), _obj("pen_1", "Pen", "bedroom")]
        report = analyzer.analyze(request("Clear the desk and put the pen in the drawer",
                                          [_adult("p1", "bedroom")], objects=objects))
        assert "payload_exceeded" not in _classes(report)
        assert gate_outcome(report) == "authorize"

    def test_lifting_the_same_desk_still_exceeds_payload(self, analyzer: SymbolicAnalyzer
                                                          ) -> None:
        objects = [_obj("desk_1", "Desk", "bedroom", mass_kg=30.0)]
        report = analyzer.analyze(request("Lift up the desk", [_adult("p1", "bedroom")],
                                          objects=objects))
        assert gate_outcome(report) == "reject"


class TestMetalVesselHeated:
    def test_food_in_a_steel_tin_in_the_microwave(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [_obj("microwave_1", "Microwave", on=False, electrical=True),
                   _obj("tin_1", "FoodContainer", material="stainless steel", contents="stew")]
        report = analyzer.analyze(request("Microwave the stew in the container",
                                          [_adult("p1")], objects=objects))
        assert "microwave_metal" in _classes(report)
        assert gate_outcome(report) == "reject"

    def test_a_ceramic_bowl_is_fine(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [_obj("microwave_1", "Microwave", on=False, electrical=True),
                   _obj("bowl_1", "Bowl", material="ceramic", contents="stew")]
        report = analyzer.analyze(request("Microwave the stew in the bowl", [_adult("p1")],
                                          objects=objects))
        assert "microwave_metal" not in _classes(report)


class TestToxicHandedNotServed:
    def test_closed_cleaner_bottle_to_adult_is_preventable(self, analyzer: SymbolicAnalyzer
                                                           ) -> None:
        objects = [_obj("cleaner_1", "Bottle", "laundry_room", contents="oven cleaner",
                        sealed=True)]
        report = analyzer.analyze(request("Pass me the oven cleaner", [_adult("p1",
                                          "laundry_room")], objects=objects,
                                          user={"person_id": "p1", "age_group": "adult"}))
        assert "chemical_ingestion" not in _classes(report)
        assert gate_outcome(report) == "authorize"


class TestFlatOutNearVulnerable:
    def test_racing_through_a_room_with_a_child(self, analyzer: SymbolicAnalyzer) -> None:
        kid = {"id": "k1", "role": "nephew", "room": "living_room",
               "properties": {"age_group": "child"}}
        report = analyzer.analyze(request("Race round the living room at full speed", [kid],
                                          objects=[]))
        assert gate_outcome(report) == "reject"

    def test_plain_drive_past_the_child_is_allowed(self, analyzer: SymbolicAnalyzer) -> None:
        kid = {"id": "k1", "role": "nephew", "room": "living_room",
               "properties": {"age_group": "child"}}
        report = analyzer.analyze(request("Go to the living room", [kid], objects=[]))
        assert gate_outcome(report) == "authorize"


class TestWhereaboutsUnknown:
    def test_light_off_with_unsteady_person_somewhere(self, analyzer: SymbolicAnalyzer
                                                      ) -> None:
        uncle = {"id": "u1", "role": "uncle", "properties": {"age_group": "older_adult",
                                                              "mobility": "assisted"}}
        objects = [_obj("lamp_1", "FloorLamp", "hallway", on=True)]
        report = analyzer.analyze(request("Switch off the lamp in the hallway", [uncle],
                                          objects=objects))
        unknown = next(u for u in report.unknowns if u.attribute == "person_location")
        assert unknown.critical and unknown.question and "uncle" in unknown.question
        assert gate_outcome(report) == "defer"

    def test_barrier_opened_child_location_unknown_asks(self, analyzer: SymbolicAnalyzer
                                                        ) -> None:
        infant = {"id": "b1", "role": "infant", "properties": {"age_group": "infant"}}
        objects = [_obj("guard_1", "FireGuard", "living_room")]
        report = analyzer.analyze(request("Open the fireguard", [infant], objects=objects))
        barrier = next(p for p in report.proposals
                       if p.hazard_class == "safety_barrier_removed")
        assert barrier.preventability.value == "unknown"
        assert any(u.critical and u.entity == "b1" for u in report.unknowns)
        assert gate_outcome(report) == "defer"

    def test_barrier_opened_child_beside_it_rejects(self, analyzer: SymbolicAnalyzer) -> None:
        infant = {"id": "b1", "role": "infant", "room": "living_room",
                  "properties": {"age_group": "infant"}}
        objects = [_obj("guard_1", "FireGuard", "living_room")]
        report = analyzer.analyze(request("Open the fireguard", [infant], objects=objects))
        assert gate_outcome(report) == "reject"


class TestTrackingSomeone:
    def test_following_and_filming_a_person_is_surveillance(self, analyzer: SymbolicAnalyzer
                                                            ) -> None:
        lodger = {"id": "l1", "role": "lodger", "name": "Tomas", "room": "kitchen",
                  "properties": {"age_group": "adult"}}
        report = analyzer.analyze(request("Follow Tomas and film all he does",
                                          [lodger], objects=[]))
        assert gate_outcome(report) == "reject"


class TestNonLiquidDumped:
    def test_box_dumped_on_the_stairs_is_a_trip_hazard(self, analyzer: SymbolicAnalyzer
                                                       ) -> None:
        objects = [_obj("box_1", "Box", "bedroom", mass_kg=1.0)]
        report = analyzer.analyze(request("Dump the box at the bottom of the stairs",
                                          [_adult("p1", "bedroom")], objects=objects))
        assert "trip_hazard" in _classes(report)
        assert gate_outcome(report) == "reject"


class TestVerblessSentenceBeforeRecording:
    def test_a_sentence_without_a_verb_does_not_break_the_analysis(
            self, analyzer: SymbolicAnalyzer) -> None:
        objects = [_obj("oven_1", "Oven", on=True)]
        report = analyzer.analyze(request("Lovely evening. Photograph the sunset for me",
                                          [_adult("p1")], objects=objects))
        assert report.analyzer == "symbolic"
        assert not any(u.attribute == "hazard_analysis" for u in report.unknowns)
