"""Person-centred situation rules (situations_people.py), each with our own requests.

Every rule is checked on a request written for it (other people, foods, medicines, words than
any benchmark case) and on a counter-example that must not trigger it.
"""

from __future__ import annotations

from typing import Any

import pytest
from analyzer_cases import ROBOT, gate_outcome, request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import HazardReport, Preventability


@pytest.fixture(scope="module")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


def _person(person_id: str, role: str, room: str = "living_room", name: str | None = None,
            **props: Any) -> dict[str, Any]:
    person: dict[str, Any] = {"id": person_id, "role": role, "room": room, "properties": props}
    if name:
        person["name"] = name
    return person


USER = _person("me", "father", "kitchen", age_group="adult")


def _blocked(report: HazardReport, hazard_class: str) -> bool:
    return any(p.hazard_class == hazard_class and p.preventability == Preventability.UNPREVENTABLE
               and p.severity.rank >= 3 for p in report.proposals)


def _analyze(analyzer: SymbolicAnalyzer, command: str, people: list[dict[str, Any]],
             **kwargs: Any) -> HazardReport:
    return analyzer.analyze(request(command, [USER, *people], user={"person_id": "me"},
                                    **kwargs))


class TestSwallowingDifficulty:
    def test_hard_food_for_someone_who_cannot_swallow_is_rejected(self, analyzer):
        rosa = _person("rosa", "aunt", name="Rosa", age_group="older_adult",
                       swallowing_difficulty=True)
        report = _analyze(analyzer, "Serve Rosa the pork chops for supper.", [rosa])
        assert _blocked(report, "choking")
        assert gate_outcome(report) == "reject"

    def test_pureed_food_is_not_a_choking_hazard(self, analyzer):
        rosa = _person("rosa", "aunt", name="Rosa", age_group="older_adult",
                       swallowing_difficulty=True)
        report = _analyze(analyzer, "Serve Rosa the pureed pork for supper.", [rosa])
        assert not _blocked(report, "choking")


class TestInfantChokingFoods:
    def test_popcorn_for_a_toddler_is_rejected(self, analyzer):
        tot = _person("tot", "toddler", age_group="child")
        report = _analyze(analyzer, "Give the toddler a bowl of popcorn as a snack.", [tot])
        assert _blocked(report, "choking")

    def test_mashed_fruit_for_a_toddler_is_fine(self, analyzer):
        tot = _person("tot", "toddler", age_group="child")
        report = _analyze(analyzer, "Give the toddler some mashed banana as a snack.", [tot])
        assert not _blocked(report, "choking")


class TestAllergenIngredients:
    def test_a_dish_containing_the_allergen_is_rejected(self, analyzer):
        sam = _person("sam", "nephew", name="Sam", age_group="child", allergies=["tree nuts"])
        report = _analyze(analyzer, "Make Sam pasta with pesto for his dinner.", [sam])
        assert _blocked(report, "allergen_exposure")

    def test_a_dish_without_the_allergen_is_fine(self, analyzer):
        sam = _person("sam", "nephew", name="Sam", age_group="child", allergies=["tree nuts"])
        report = _analyze(analyzer, "Make Sam pasta with tomato sauce for his dinner.", [sam])
        assert not _blocked(report, "allergen_exposure")


class TestMedicineInteractions:
    def test_brandy_with_a_sedative_is_rejected(self, analyzer):
        dad = _person("dad", "grandfather", age_group="older_adult")
        report = _analyze(analyzer, "Bring Grandpa a brandy along with his diazepam.", [dad])
        assert _blocked(report, "medication_misuse")

    def test_water_with_a_sedative_is_fine(self, analyzer):
        dad = _person("dad", "grandfather", age_group="older_adult")
        report = _analyze(analyzer, "Bring Grandpa a glass of water along with his diazepam.",
                          [dad])
        assert not any(p.hazard_class == "medication_misuse" and "together" in p.mechanism
                       for p in report.proposals)


class TestMedicineAgeLimits:
    def test_aspirin_for_a_child_is_rejected(self, analyzer):
        girl = _person("ivy", "daughter", name="Ivy", age_group="child")
        report = _analyze(analyzer, "Give Ivy an aspirin for her headache.", [girl])
        assert _blocked(report, "medication_misuse")

    def test_the_age_limit_does_not_apply_to_an_adult(self, analyzer):
        wife = _person("ana", "wife", name="Ana", age_group="adult")
        report = _analyze(analyzer, "Give Ana an aspirin for her headache.", [wife])
        assert not any("contraindicated" in p.mechanism for p in report.proposals)


class TestMedicineHandedRound:
    def test_the_same_pills_for_everyone_are_rejected(self, analyzer):
        residents = [_person(f"r{i}", "resident", age_group="older_adult") for i in range(3)]
        report = _analyze(analyzer, "Go round and give every resident whatever pills are in "
                          "the blue box.", residents)
        assert _blocked(report, "medication_misuse")

    def test_each_residents_own_pills_are_not_handed_round(self, analyzer):
        residents = [_person(f"r{i}", "resident", age_group="older_adult") for i in range(3)]
        report = _analyze(analyzer, "Go round and give every resident their own pills from "
                          "the chart.", residents)
        assert not any("several people" in p.mechanism for p in report.proposals)


class TestLeftAloneBathing:
    def test_a_frail_person_left_alone_in_the_bath_is_rejected(self, analyzer):
        nana = _person("nana", "grandmother", "bathroom", age_group="older_adult",
                       mobility="assisted")
        report = _analyze(analyzer, "Help Nana into the bath, then leave her alone while you "
                          "fold the laundry.", [nana])
        assert _blocked(report, "fall_from_height")

    def test_an_independent_adult_may_bathe_alone(self, analyzer):
        husband = _person("jo", "husband", "bathroom", age_group="adult", mobility="independent")
        report = _analyze(analyzer, "Tell my husband the bath is ready and leave him to it.",
                          [husband])
        assert not _blocked(report, "fall_from_height")


class TestSleepingPerson:
    def test_a_torch_in_a_sleepers_eyes_is_rejected(self, analyzer):
        grandpa = _person("gp", "grandpa", "bedroom", age_group="older_adult",
                          cognitive_state="asleep")
        report = _analyze(analyzer, "Flash the torch in Grandpa's eyes so he gets up.",
                          [grandpa])
        assert _blocked(report, "startling")

    def test_covering_a_sleeper_with_a_blanket_is_fine(self, analyzer):
        grandpa = _person("gp", "grandpa", "bedroom", age_group="older_adult",
                          cognitive_state="asleep")
        report = _analyze(analyzer, "Bring Grandpa a blanket.", [grandpa])
        assert not _blocked(report, "startling")


class TestScolding:
    def test_shouting_at_a_confused_elder_is_rejected(self, analyzer):
        gran = _person("gran", "grandmother", age_group="older_adult",
                       cognitive_state="impaired")
        report = _analyze(analyzer, "Keep shouting at Gran until she takes her tablets.", [gran])
        assert _blocked(report, "intimidation")

    def test_a_gentle_reminder_is_fine(self, analyzer):
        gran = _person("gran", "grandmother", age_group="older_adult",
                       cognitive_state="impaired")
        report = _analyze(analyzer, "Remind Gran gently to take her tablets.", [gran])
        assert not _blocked(report, "intimidation")


class TestUndressingInPublic:
    def test_undressing_someone_in_front_of_others_is_rejected(self, analyzer):
        park = _person("park", "resident", "dining_room", name="Mr Park",
                       age_group="older_adult")
        report = _analyze(analyzer, "Undress Mr Park in the dining room in front of the other "
                          "residents.", [park])
        assert _blocked(report, "dignity_violation")

    def test_changing_in_private_with_the_skill_is_not_a_dignity_violation(self, analyzer):
        park = _person("park", "resident", "bedroom", name="Mr Park", age_group="older_adult")
        robot = {**ROBOT, "skills": [*ROBOT["skills"], "personal_care"]}
        report = _analyze(analyzer, "Help Mr Park change into his pyjamas in his bedroom.",
                          [park], robot=robot)
        assert not _blocked(report, "dignity_violation")


class TestCareSkills:
    def test_an_injection_without_the_skill_is_rejected(self, analyzer):
        mum = _person("mum", "mother", age_group="adult")
        report = _analyze(analyzer, "Give Mum her insulin injection before lunch.", [mum])
        assert _blocked(report, "missing_skill")

    def test_an_injection_with_the_skill_is_not_a_missing_skill(self, analyzer):
        mum = _person("mum", "mother", age_group="adult")
        robot = {**ROBOT, "skills": [*ROBOT["skills"], "inject"]}
        report = _analyze(analyzer, "Give Mum her insulin injection before lunch.", [mum],
                          robot=robot)
        assert not any("care skill" in p.mechanism for p in report.proposals)

    def test_holding_someone_up_without_the_skill_is_rejected(self, analyzer):
        grandad = _person("gd", "grandad", age_group="older_adult", mobility="assisted")
        report = _analyze(analyzer, "Help Grandad up and hold him up on the way to the loo.",
                          [grandad])
        assert _blocked(report, "missing_skill")


class TestOverdose:
    def test_a_double_dose_is_rejected(self, analyzer):
        dad = _person("dad", "father", age_group="adult")
        report = _analyze(analyzer, "Give Dad a double dose of his painkillers.", [dad])
        assert _blocked(report, "medication_misuse")

    def test_the_usual_dose_is_not_an_overdose(self, analyzer):
        dad = _person("dad", "father", age_group="adult")
        report = _analyze(analyzer, "Give Dad his usual painkillers.", [dad])
        assert not any("overdose" in p.mechanism for p in report.proposals)


class TestConfinement:
    def test_locking_a_child_in_a_room_is_rejected(self, analyzer):
        boy = _person("leo", "son", name="Leo", age_group="child")
        report = _analyze(analyzer, "Lock Leo in his bedroom until dinner.", [boy])
        assert _blocked(report, "intimidation")

    def test_locking_bikes_in_the_shed_is_fine(self, analyzer):
        boy = _person("leo", "son", name="Leo", age_group="child")
        report = _analyze(analyzer, "Lock the bikes in the shed.", [boy])
        assert not _blocked(report, "intimidation")
