"""Grounding phrases on the request's world state: objects, people, rooms, new entities."""

from __future__ import annotations

import copy
from typing import Any

from app.domain.analysis.grounding import Grounder
from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.phrases import NounPhrase, parse_phrase
from app.domain.models import GateRequest
from app.domain.world import state_from_request
from tests.domain.analysis.conftest import HOME


def grounder(scene: dict[str, Any] | None = None) -> Grounder:
    request = GateRequest.model_validate({"command": "x", "scene": copy.deepcopy(scene or HOME)})
    return Grounder(state_from_request(request), request, load_lexicon())


def phrase(text: str) -> NounPhrase:
    found = parse_phrase(text.split(), load_lexicon())
    assert found is not None
    return found


class TestObjects:
    def test_a_type_word_names_the_scene_object(self) -> None:
        assert grounder().any(phrase("the microwave")).ids == ("microwave_1",)

    def test_a_substance_names_the_container_that_holds_it(self) -> None:
        assert grounder().any(phrase("the water")).ids == ("bowl_1",)

    def test_alike_objects_are_one_choice_and_differing_ones_a_question(self) -> None:
        assert len(grounder().any(phrase("the cabinet")).ids) == 1
        scene = {**HOME, "objects": [{"id": "b1", "type": "Bottle", "room": "kitchen",
                                      "properties": {"contents": "water"}},
                                     {"id": "b2", "type": "Bottle", "room": "kitchen",
                                      "properties": {"contents": "bleach"}}]}
        found = grounder(scene).any(phrase("the bottle"))
        assert not found.ids and set(found.candidates) == {"b1", "b2"}

    def test_a_known_noun_the_scene_lacks_becomes_a_new_object(self) -> None:
        g = grounder()
        found = g.any(phrase("a wallet"))
        assert found.new and g.scene().value("valuable", found.ids) is True

    def test_a_liquid_the_scene_lacks_comes_in_a_cup(self) -> None:
        g = grounder()
        found = g.any(phrase("some milk"))
        assert g.scene().objects[found.ids[0]].type == "Cup"

    def test_a_word_that_is_no_english_noun_is_a_gap(self) -> None:
        g = grounder()
        assert g.any(phrase("the zorblat")).kind == "none"
        assert g.gaps and g.gaps[0].words == "the zorblat"

    def test_words_about_height_are_noted(self) -> None:
        scene = {**HOME, "objects": [{"id": "shelf_1", "type": "Shelf", "room": "kitchen"}]}
        g = grounder(scene)
        g.any(phrase("the top shelf"), place=True)
        assert g.scene().value("elevated", ("shelf_1",)) is True


class TestPeopleAndPronouns:
    def test_a_role_word_names_the_scene_person(self) -> None:
        assert grounder().person(phrase("dad")).ids == ("dad",)

    def test_a_role_the_scene_lacks_becomes_a_person_of_that_age(self) -> None:
        g = grounder()
        found = g.any(phrase("the toddler"))
        assert found.kind == "person" and g.scene().value("toddler", found.ids) is True

    def test_it_points_to_the_last_object_but_not_to_a_place(self) -> None:
        g = grounder()
        g.any(phrase("the potato"))
        g.any(phrase("the microwave"), place=True)
        assert g.any(phrase("it")).ids == ("potato_1",)

    def test_me_is_the_speaker_an_adult_unless_the_profile_says_otherwise(self) -> None:
        g = grounder()
        me = g.any(phrase("me"))
        assert g.scene().value("age_group", me.ids) == "adult"
