"""The knowledge data: every file loads, AI2-THOR types map to concepts, WordNet generalises."""

from __future__ import annotations

import pytest

from app.domain.analysis.knowledge_base import Knowledge, load_knowledge, singular
from app.domain.models import Severity


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


class TestConcepts:
    def test_every_ai2thor_type_but_the_marker_has_a_concept(self, knowledge: Knowledge
                                                             ) -> None:
        missing = [t for t in knowledge.ai2thor_types if knowledge.concept_of_type(t) is None]
        assert missing == ["TargetCircle"]

    @pytest.mark.parametrize(("word", "concept"), [
        ("cleaver", "knife"), ("scalpel", "knife"), ("machete", "knife"),
        ("thermos", "mug"), ("tylenol", "medication"), ("espresso maker", "coffee_machine"),
        ("knives", "knife"), ("StoveBurner", "stove"),
    ])
    def test_words_generalise_to_concepts(self, knowledge: Knowledge, word: str, concept: str
                                          ) -> None:
        found = knowledge.noun_concept(word) or knowledge.concept_of_type(word)
        assert found == concept

    def test_concept_properties(self, knowledge: Knowledge) -> None:
        assert "sharp" in knowledge.concepts["knife"].props
        assert "walking_aid" in knowledge.concepts["walking_aid"].props
        assert "heat_source" in knowledge.concepts["stove"].props

    def test_type_mass_comes_from_ai2thor(self, knowledge: Knowledge) -> None:
        assert knowledge.type_mass("Dumbbell") == pytest.approx(4.54)


class TestSubstances:
    def test_bleach_and_ammonia_react(self, knowledge: Knowledge) -> None:
        bleach = knowledge.substances[knowledge.substance_of("bleach") or ""]
        ammonia = knowledge.substances[knowledge.substance_of("window cleaner") or ""]
        reactions = [r for r in knowledge.reactions
                     if set(r.classes) == {*bleach.classes, *ammonia.classes}]
        assert reactions and Severity(reactions[0].severity) == Severity.CRITICAL

    def test_allergen_groups(self, knowledge: Knowledge) -> None:
        assert knowledge.substances[knowledge.substance_of("peanut butter") or ""].allergen \
            == "peanut"


class TestPeople:
    def test_role_words_imply_age_only_when_they_do(self, knowledge: Knowledge) -> None:
        assert knowledge.role_words["toddler"].age_group == "child"
        assert knowledge.role_words["toddler"].young
        assert knowledge.role_words["grandpa"].age_group == "older_adult"
        assert knowledge.role_words["daughter"].age_group is None


class TestMorphology:
    @pytest.mark.parametrize(("plural", "single"), [
        ("boxes", "box"), ("knives", "knife"), ("batteries", "battery"), ("glass", "glass"),
        ("kitchen knives", "kitchen knife")])
    def test_singular(self, plural: str, single: str) -> None:
        assert singular(plural) == single
