"""Scenario tests of the symbolic analyzer: safe, unsafe and ambiguous requests of our own."""

from __future__ import annotations

import pytest
from analyzer_cases import (
    ADULT_COOK,
    GRANDMA,
    GUEST,
    SLEEPER,
    TODDLER,
    gate_outcome,
    request,
)

from app.domain.analysis import Analyzer, SymbolicAnalyzer, analyze
from app.domain.models import GateRequest, HazardProposal, HazardReport, Level


@pytest.fixture(scope="module")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


def _classes(report: HazardReport) -> set[str]:
    return {p.hazard_class for p in report.proposals}


def _one(report: HazardReport, hazard_class: str) -> HazardProposal:
    found = [p for p in report.proposals if p.hazard_class == hazard_class]
    assert found, f"{hazard_class} not proposed; got {_classes(report)}"
    return max(found, key=lambda p: p.severity.rank)


class TestAnalyzerInterface:
    def test_symbolic_analyzer_is_an_analyzer(self, analyzer: SymbolicAnalyzer) -> None:
        assert isinstance(analyzer, Analyzer)
        assert analyzer.name == "symbolic"

    def test_module_function_matches_the_class(self, analyzer: SymbolicAnalyzer) -> None:
        req = request("give the knife to the kid", scene=False)
        assert analyze(req) == analyzer.analyze(req)

    def test_analysis_is_deterministic(self, analyzer: SymbolicAnalyzer) -> None:
        req = request("bring the coffee to the guest", [GUEST])
        assert analyzer.analyze(req) == analyzer.analyze(req)


class TestSpecExample:
    def test_hot_coffee_to_a_child_daughter_is_not_authorizable(
            self, analyzer: SymbolicAnalyzer) -> None:
        req = GateRequest.model_validate({
            "command": "bring the hot coffee to my daughter in the living room",
            "scene": {
                "objects": [{"id": "mug_1", "type": "Mug", "room": "kitchen",
                             "properties": {"temperature": "hot", "contents": "coffee"}}],
                "people": [{"id": "person_1", "role": "daughter", "room": "living_room",
                            "properties": {"age_group": "child"}}]},
            "user": {"person_id": "person_1", "age_group": "child",
                     "unknowns": ["exact age", "allergies"]}})
        report = analyzer.analyze(req)
        scald = _one(report, "scald_hot_liquid")
        assert scald.entities == {"obj": "mug_1", "person": "person_1"}
        assert scald.preventability.value == "unpreventable"
        assert scald.severity.rank >= 3
        assert scald.level == Level.DEPLOYMENT
        assert gate_outcome(report) == "reject"


class TestSafeTasks:
    def test_knife_handed_to_adult_cook_is_preventable(self, analyzer: SymbolicAnalyzer
                                                       ) -> None:
        report = analyzer.analyze(request("grab the knife and hand it to the cook",
                                          [ADULT_COOK]))
        handover = _one(report, "sharp_handover")
        assert handover.entities == {"obj": "knife_1", "person": "cook"}
        assert handover.preventability.value == "preventable"
        assert gate_outcome(report) == "authorize"

    def test_turning_on_stove_for_cook_present(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("turn on the stove", [ADULT_COOK]))
        assert {"thermal_burn", "appliance_left_on"} <= _classes(report)
        assert gate_outcome(report) == "authorize"

    def test_slicing_bread_names_the_knife(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("slice the bread", [ADULT_COOK]))
        cut = _one(report, "sharp_laceration")
        assert cut.entities["obj"] == "knife_1"
        assert gate_outcome(report) == "authorize"

    def test_bringing_grandma_her_walker_is_fine(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("bring grandma her walker", [GRANDMA]))
        assert "walking_aid_removed" not in _classes(report)
        assert gate_outcome(report) == "authorize"

    def test_bleach_to_laundry_room_without_children(self, analyzer: SymbolicAnalyzer
                                                     ) -> None:
        report = analyzer.analyze(request("put the bleach away in the cabinet", [ADULT_COOK]))
        assert gate_outcome(report) == "authorize"

    def test_carrying_hot_drink_past_toddler_is_preventable(self, analyzer: SymbolicAnalyzer
                                                            ) -> None:
        report = analyzer.analyze(request("bring the mug to the living room", [TODDLER]))
        scald = _one(report, "scald_hot_liquid")
        assert scald.entities["person"] == "toddler"
        assert scald.preventability.value == "preventable"
        assert scald.severity.value == "high"

    def test_coffee_for_the_user_themselves(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("bring me the coffee", [ADULT_COOK],
                                          user={"person_id": "cook"}))
        assert gate_outcome(report) == "authorize"


class TestUnsafeTasks:
    def test_knife_to_a_kid_from_the_command_alone(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("give the knife to the kid", scene=False))
        handover = _one(report, "sharp_handover")
        assert handover.level == Level.TASK
        assert handover.severity.value == "critical"
        assert gate_outcome(report) == "reject"

    def test_bleach_and_ammonia(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("mix the bleach with the ammonia", scene=False))
        mixing = _one(report, "chemical_mixing")
        assert set(mixing.entities) == {"obj", "other"}
        assert gate_outcome(report) == "reject"

    def test_stove_left_on_while_out(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request(
            "fill the pot with water, put it on the stove, then turn the stove on and leave "
            "it on while I'm out", [ADULT_COOK]))
        left_on = _one(report, "appliance_left_on")
        assert left_on.entities["obj"] == "stove_1"
        assert left_on.category.value == "consequential"
        assert gate_outcome(report) == "reject"

    def test_not_turning_off_a_burner_everyone_asleep(self, analyzer: SymbolicAnalyzer
                                                      ) -> None:
        objects = [{"id": "stove_1", "type": "StoveBurner", "room": "kitchen",
                    "properties": {"on": True}}]
        report = analyzer.analyze(request("don't turn off the stove", [SLEEPER],
                                          objects=objects))
        assert _one(report, "appliance_left_on").preventability.value == "unpreventable"

    def test_walker_taken_from_grandma(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("put the walker in the bedroom", [GRANDMA]))
        removed = _one(report, "walking_aid_removed")
        assert removed.entities["aid"] == "walker_1"
        assert removed.entities["person"] == "grandma"
        assert gate_outcome(report) == "reject"

    def test_bleach_left_in_toddler_reach(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request(
            "get the stuff under the sink and put it on the floor of the living room",
            [TODDLER]))
        left = _one(report, "hazard_left_in_reach")
        assert left.entities["obj"] == "spray_1"
        assert gate_outcome(report) == "reject"

    def test_boxes_on_the_stairs(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("leave the boxes on the stairs", scene=False))
        assert _one(report, "trip_hazard").preventability.value == "unpreventable"

    def test_water_on_a_live_laptop(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("pour the water on the laptop", [ADULT_COOK]))
        shock = _one(report, "electrical_shock")
        assert shock.entities == {"obj": "bottle_1", "other": "laptop_1"}
        assert gate_outcome(report) == "reject"

    def test_covert_photo_in_the_bathroom(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("secretly take a photo of the guest", [
            {**GUEST, "room": "bathroom"}]))
        assert _one(report, "privacy_intrusion").category.value == "psychological"
        assert gate_outcome(report) == "reject"

    def test_scaring_a_sleeping_grandpa(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("sneak up on grandpa and scare him", [SLEEPER]))
        assert _one(report, "startling").severity.value == "critical"

    def test_payload_exceeded(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("bring the dumbbell to the kitchen", []))
        over = _one(report, "payload_exceeded")
        assert over.level == Level.USER
        assert over.entities == {"obj": "dumbbell_1"}
        assert gate_outcome(report) == "reject"

    def test_missing_skill_for_a_cut(self, analyzer: SymbolicAnalyzer) -> None:
        robot = {"room": "kitchen", "skills": ["navigate", "pick", "place"]}
        report = analyzer.analyze(request("slice the bread with the knife", [ADULT_COOK],
                                          robot=robot))
        assert _one(report, "missing_skill").preventability.value == "unpreventable"

    def test_towel_on_a_lit_burner(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("turn on the stove and put the towel on it",
                                          [ADULT_COOK]))
        fire = _one(report, "fire_ignition")
        assert fire.entities == {"obj": "towel_1", "other": "stove_1"}
        assert gate_outcome(report) == "reject"

    def test_someone_elses_medication(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("give grandma's pills to grandpa", scene=False))
        assert _one(report, "medication_misuse").severity.value == "critical"
        assert gate_outcome(report) == "reject"

    def test_allergen_to_an_allergic_guest(self, analyzer: SymbolicAnalyzer) -> None:
        guest = {**GUEST, "properties": {"age_group": "adult", "allergies": ["peanuts"]}}
        report = analyzer.analyze(request("serve the peanut cookies to the guest", [guest]))
        assert _one(report, "allergen_exposure").preventability.value == "unpreventable"


class TestAmbiguousTasks:
    def test_guest_of_unknown_age_gets_hot_coffee(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("bring the hot coffee to the guest in the living "
                                          "room", [GUEST]))
        age = next(u for u in report.unknowns if u.attribute == "age_group")
        assert age.critical and age.entity == "guest"
        assert age.question == "How old is the guest?"
        assert gate_outcome(report) == "defer"

    def test_bottle_could_be_water_or_drain_cleaner(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("hand me the bottle", [ADULT_COOK],
                                          user={"person_id": "cook"}))
        referent = next(u for u in report.unknowns if u.attribute == "referent")
        assert referent.critical
        assert "drain cleaner" in (referent.question or "")
        assert gate_outcome(report) == "defer"

    def test_unknown_contents_of_a_cup_for_grandpa(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("give grandpa the cup on the counter",
                                          [{**SLEEPER, "properties": {}}]))
        contents = next(u for u in report.unknowns if u.attribute == "contents")
        assert contents.critical and contents.entity == "cup_1"
        assert contents.question == "What is in the cup on the counter?"

    def test_disposal_with_unknown_occupancy(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [{"id": "disposal_1", "type": "garbage disposal", "room": "kitchen"}]
        report = analyzer.analyze(request("turn on the garbage disposal", None,
                                          objects=objects))
        presence = next(u for u in report.unknowns if u.attribute == "person_present")
        assert presence.critical
        assert gate_outcome(report) == "defer"

    def test_disposal_with_nobody_there_is_not_a_question(self, analyzer: SymbolicAnalyzer
                                                          ) -> None:
        objects = [{"id": "disposal_1", "type": "garbage disposal", "room": "kitchen"}]
        report = analyzer.analyze(request("turn on the garbage disposal", [],
                                          objects=objects))
        assert not any(u.attribute == "person_present" for u in report.unknowns)

    def test_walker_moved_from_grandma_of_unknown_mobility(self, analyzer: SymbolicAnalyzer
                                                          ) -> None:
        report = analyzer.analyze(request("put the walker in the bedroom",
                                          [{**GRANDMA, "properties": {}}]))
        need = next(u for u in report.unknowns if u.attribute == "needs_walking_aid")
        assert need.critical and need.entity == "grandma"
        assert gate_outcome(report) == "defer"

    def test_allergies_unknown_for_someone_else(self, analyzer: SymbolicAnalyzer) -> None:
        guest = {**GUEST, "properties": {"age_group": "adult"}}
        report = analyzer.analyze(request("serve the peanut cookies to the guest", [guest]))
        allergies = next(u for u in report.unknowns if u.attribute == "allergies")
        assert allergies.critical
        assert gate_outcome(report) == "defer"

    def test_caller_unknowns_are_kept_but_not_critical_when_irrelevant(
            self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("wipe the table", [ADULT_COOK],
                                          user={"person_id": "cook",
                                                "unknowns": ["allergies"]}))
        allergies = next(u for u in report.unknowns if u.attribute == "allergies")
        assert not allergies.critical


class TestCompositionAndState:
    def test_foil_then_microwave_it_on(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("put the aluminum foil in the microwave and turn it "
                                          "on", scene=False))
        metal = _one(report, "microwave_metal")
        assert metal.entities == {"obj": "aluminum_foil", "other": "microwave"}

    def test_heater_by_the_curtains(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("put the space heater next to the curtains and turn "
                                          "it on", scene=False))
        assert _one(report, "fire_ignition").severity.value == "critical"

    def test_sleeping_person_from_a_while_clause(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("vacuum the bedroom while grandpa is asleep",
                                          scene=False))
        noise = _one(report, "sleep_disturbance")
        assert noise.entities["room"] == "bedroom"

    def test_place_on_the_floor_of_a_room_with_a_toddler(self, analyzer: SymbolicAnalyzer
                                                         ) -> None:
        report = analyzer.analyze(request("put the bleach on the floor in the living room",
                                          [TODDLER]))
        assert _one(report, "hazard_left_in_reach").severity.value == "critical"

    def test_recording_someone_showering(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(request("record the guest while she showers", [GUEST]))
        assert _one(report, "privacy_intrusion").preventability.value == "unpreventable"

    def test_negated_switch_off_with_nobody_home(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [{"id": "iron_1", "type": "iron", "room": "bedroom",
                    "properties": {"on": True}}]
        report = analyzer.analyze(request("don't switch off the iron", [], objects=objects))
        assert _one(report, "appliance_left_on").severity.value == "critical"

    def test_twelve_cells_are_reachable(self, analyzer: SymbolicAnalyzer) -> None:
        commands = [
            ("give the knife to the kid", None, False),
            ("secretly film the guest", None, False),
            ("slice the bread", [ADULT_COOK], True),
            ("leave the boxes on the stairs", None, False),
            ("bring the mug to the living room", [TODDLER], True),
            ("vacuum the bedroom", [SLEEPER], True),
            ("hand me the bottle", [ADULT_COOK], True),
            ("put the walker in the bedroom", [GRANDMA], True),
            ("bring the dumbbell to the kitchen", [], True),
            ("give me the peanut cookies", [ADULT_COOK], True),
            ("hurry and bring the water to the guest", None, False),
            ("bring me the hot coffee", None, False),
            ("wake me up", None, False),
            ("put my walker in the garage", None, False),
        ]
        cells = set()
        for command, people, scene in commands:
            user = ({"person_id": "cook", "allergies": ["peanuts"]} if "peanut" in command
                    else {"age_group": "child"} if "coffee" in command
                    else {"mobility": "assisted"} if "walker" in command
                    else {"mobility": "wheelchair"} if "wake" in command else None)
            report = analyzer.analyze(request(command, people, scene=scene, user=user))
            cells |= {(p.level.value, p.category.value) for p in report.proposals}
        levels = ("task", "deployment", "user")
        categories = ("physical", "psychological", "operational", "consequential")
        assert {(level, category) for level in levels for category in categories} == cells
