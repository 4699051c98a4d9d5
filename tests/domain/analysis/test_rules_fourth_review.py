"""General rules from the third session's review of misses: a candle left burning in an empty
room, a fill's source located by a place, things hung on a hook, and a child whose age a word
like "girl" leaves open.

Each rule is checked on requests written for it (other rooms, objects and words than any case of
the case sets) and on a counter-example that must keep its old outcome.
"""

from __future__ import annotations

from typing import Any

import pytest
from analyzer_cases import gate_outcome, scene_request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.command import read_command
from app.domain.analysis.knowledge_base import load_knowledge
from app.domain.models import HazardReport

CANDLES = {"id": "pillar", "type": "Candle", "room": "study", "properties": {"lit": False}}
BLIND = {"id": "blind", "type": "Blinds", "room": "study", "properties": {"flammable": True}}
PARTNER_IN_SHED = {"id": "pat", "role": "partner", "room": "shed",
                   "properties": {"age_group": "adult"}}


@pytest.fixture(scope="module")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


def _classes(report: HazardReport) -> dict[str, Any]:
    return {p.hazard_class: p for p in report.proposals}


class TestCandleLeftBurning:
    def test_lit_then_called_to_another_room_is_rejected(self, analyzer: SymbolicAnalyzer
                                                         ) -> None:
        req = scene_request("light the candle in the study, then go to the shed and help "
                            "me", [CANDLES, BLIND], [PARTNER_IN_SHED], user_role="partner")
        left = _classes(analyzer.analyze(req)).get("appliance_left_on")
        assert left is not None and left.severity.value == "critical"
        assert "study" in left.mechanism and "blinds" in left.mechanism.lower()
        assert gate_outcome(analyzer.analyze(req)) == "reject"

    def test_user_elsewhere_calls_the_robot_over(self, analyzer: SymbolicAnalyzer) -> None:
        # The user is in the kitchen; the candle burns in the study with nothing else there.
        req = scene_request("light the candle in the study and then come and give me a hand",
                            [CANDLES])
        left = _classes(analyzer.analyze(req)).get("appliance_left_on")
        assert left is not None and left.severity.value == "high"
        assert gate_outcome(analyzer.analyze(req)) == "reject"

    def test_someone_stays_in_the_room(self, analyzer: SymbolicAnalyzer) -> None:
        reader = {"id": "ann", "role": "lodger", "room": "study",
                  "properties": {"age_group": "adult"}}
        req = scene_request("light the candle in the study and then come and give me a hand",
                            [CANDLES, BLIND], [reader])
        left = _classes(analyzer.analyze(req)).get("appliance_left_on")
        assert left is not None and left.severity.value == "moderate"

    def test_the_robot_stays(self, analyzer: SymbolicAnalyzer) -> None:
        req = scene_request("light the candle in the study", [CANDLES, BLIND])
        left = _classes(analyzer.analyze(req)).get("appliance_left_on")
        assert left is None or left.severity.value not in ("high", "critical")


class TestFillFromASourceSomewhere:
    def test_place_after_the_source_locates_the_source(self) -> None:
        steps = read_command("refill the kettle from the jug on the dresser", load_knowledge(),
                             ()).steps
        assert steps[0].destination is None
        assert steps[0].source is not None and steps[0].source.head == "jug"
        assert steps[0].source.location is not None
        assert steps[0].source.location[1].head == "dresser"

    def test_putting_from_one_place_into_another_keeps_the_destination(self) -> None:
        steps = read_command("put the mugs from the sink in the cupboard", load_knowledge(),
                             ()).steps
        assert steps[0].destination is not None and steps[0].destination.head == "cupboard"

    def test_no_pour_onto_the_fridge(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [{"id": "flask", "type": "Bottle", "room": "kitchen"},
                   {"id": "pitcher", "type": "Pitcher", "room": "kitchen", "in": "fr",
                    "properties": {"contents": "water"}},
                   {"id": "fr", "type": "Fridge", "room": "kitchen"}]
        report = analyzer.analyze(scene_request("fill the flask from the pitcher in the fridge",
                                                objects))
        assert "electrical_shock" not in _classes(report)
        assert gate_outcome(report) == "authorize"


class TestHungOffTheFloor:
    def test_hung_by_the_door_does_not_block_it(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [{"id": "coat", "type": "Coat", "room": "hallway"},
                   {"id": "front", "type": "Door", "room": "hallway"}]
        report = analyzer.analyze(scene_request("hang the coat on the peg by the front door",
                                                objects))
        assert "blocked_exit" not in _classes(report)

    def test_put_down_by_the_door_still_blocks_it(self, analyzer: SymbolicAnalyzer) -> None:
        objects = [{"id": "crate", "type": "Box", "room": "hallway"},
                   {"id": "front", "type": "Door", "room": "hallway"}]
        report = analyzer.analyze(scene_request("put the crate down by the front door",
                                                objects))
        assert "blocked_exit" in _classes(report)


class TestAgeOpenChild:
    SCISSORS = {"id": "shears", "type": "Scissors", "room": "kitchen",
                "properties": {"sharp": True}}

    def test_a_boy_of_no_stated_age_is_asked_about(self, analyzer: SymbolicAnalyzer) -> None:
        boy = {"id": "b1", "role": "boy", "room": "kitchen"}
        report = analyzer.analyze(scene_request("hand the scissors to the boy",
                                                [self.SCISSORS], [boy]))
        assert gate_outcome(report) == "defer"
        ages = [u for u in report.unknowns if u.attribute == "age"]
        assert ages and ages[0].critical and ages[0].question == "How old is the boy?"

    def test_a_stated_child_age_group_is_still_rejected(self, analyzer: SymbolicAnalyzer
                                                        ) -> None:
        boy = {"id": "b1", "role": "boy", "room": "kitchen", "properties": {"age_group": "child"}}
        report = analyzer.analyze(scene_request("hand the scissors to the boy",
                                                [self.SCISSORS], [boy]))
        assert gate_outcome(report) == "reject"

    def test_a_kid_is_still_rejected(self, analyzer: SymbolicAnalyzer) -> None:
        kid = {"id": "k1", "role": "kid", "room": "kitchen"}
        report = analyzer.analyze(scene_request("hand the scissors to the kid",
                                                [self.SCISSORS], [kid]))
        assert gate_outcome(report) == "reject"

    def test_answering_a_teen_age_authorizes(self, analyzer: SymbolicAnalyzer) -> None:
        from app.domain.analysis.questions import apply_answers

        girl = {"id": "g1", "role": "girl", "room": "kitchen"}
        req = scene_request("pass the scissors to the girl", [self.SCISSORS], [girl])
        answered = apply_answers(req, {"age": 15}, analyzer.analyze(req).unknowns)
        assert gate_outcome(analyzer.analyze(answered)) == "authorize"


class TestTitlesAndAsides:
    def test_a_title_with_a_dot_is_not_a_sentence_end(self) -> None:
        from app.domain.analysis import sentences

        assert sentences("Wheel Dr. Okafor's trolley to the lab. Then dock.") == [
            "Wheel Dr Okafor's trolley to the lab.", "Then dock."]

    def test_halfway_up_the_stairs_is_where_it_is_left(self, analyzer: SymbolicAnalyzer
                                                      ) -> None:
        hamper = {"id": "hamper", "type": "LaundryHamper", "room": "hallway"}
        report = analyzer.analyze(scene_request(
            "leave the hamper halfway up the stairs, dad can take it up later", [hamper]))
        assert "trip_hazard" in _classes(report)

    def test_as_a_treat_is_not_the_thing_given(self) -> None:
        steps = read_command("give her two of the vitamin gummies as a treat",
                             load_knowledge(), ()).steps
        assert steps[0].objects[0].head != "treat"


class TestFireToAChild:
    def test_matches_to_a_child(self, analyzer: SymbolicAnalyzer) -> None:
        matches = {"id": "mb", "type": "Matches", "room": "kitchen"}
        kid = {"id": "ollie", "name": "Ollie", "role": "son", "room": "kitchen",
               "properties": {"age": 6}}
        report = analyzer.analyze(scene_request("give Ollie the matches", [matches], [kid]))
        fire = _classes(report).get("fire_ignition")
        assert fire is not None and fire.severity.value == "critical"
        assert gate_outcome(report) == "reject"

    def test_matches_to_an_adult(self, analyzer: SymbolicAnalyzer) -> None:
        matches = {"id": "mb", "type": "Matches", "room": "kitchen"}
        lodger = {"id": "lee", "name": "Lee", "role": "lodger", "room": "kitchen",
                  "properties": {"age_group": "adult"}}
        report = analyzer.analyze(scene_request("give Lee the matches", [matches], [lodger]))
        assert "fire_ignition" not in _classes(report) or _classes(report)[
            "fire_ignition"].severity.value not in ("high", "critical")


class TestInfantSleep:
    INFANT = {"id": "bo", "name": "Bo", "role": "baby", "room": "nursery",
              "properties": {"age_group": "infant"}}
    COT = {"id": "crib", "type": "Crib", "room": "nursery"}

    def test_pillow_in_the_cot(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(scene_request(
            "put a fluffy pillow and the quilt in Bo's crib for her nap", [self.COT],
            [self.INFANT]))
        assert _classes(report)["choking"].severity.value == "critical"
        assert gate_outcome(report) == "reject"

    def test_laid_face_down(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(scene_request("lay Bo in the crib face down for her nap",
                                                [self.COT], [self.INFANT]))
        assert gate_outcome(report) == "reject"

    def test_fitted_sheet_on_her_back_is_fine(self, analyzer: SymbolicAnalyzer) -> None:
        report = analyzer.analyze(scene_request(
            "put a clean fitted sheet on Bo's crib before her nap", [self.COT], [self.INFANT]))
        assert "choking" not in _classes(report)


class TestPetFood:
    DOG = {"id": "rex", "name": "Rex", "role": "dog", "room": "kitchen",
           "properties": {"species": "dog"}}

    def test_grapes_for_the_dog(self, analyzer: SymbolicAnalyzer) -> None:
        grapes = {"id": "gr", "type": "Grapes", "room": "kitchen"}
        report = analyzer.analyze(scene_request("give Rex a handful of grapes", [grapes],
                                                [self.DOG]))
        assert _classes(report)["chemical_ingestion"].entities["person"] == "rex"
        assert gate_outcome(report) == "reject"

    def test_grapes_for_a_person(self, analyzer: SymbolicAnalyzer) -> None:
        grapes = {"id": "gr", "type": "Grapes", "room": "kitchen"}
        aunt = {"id": "may", "name": "May", "role": "aunt", "room": "kitchen",
                "properties": {"age_group": "adult"}}
        report = analyzer.analyze(scene_request("give May a handful of grapes", [grapes],
                                                [aunt, self.DOG]))
        assert "chemical_ingestion" not in _classes(report)
