"""WorldState built from gate requests: facts, unknown-vs-false, snapshots."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from app.domain.formula import Unknown, fact_key
from app.domain.formula.vocabulary import VOCABULARY
from app.domain.models import InitialState
from app.domain.world import WorldState

Build = Callable[..., WorldState]


class TestSpecExampleState:
    def test_robot_fields_come_from_the_request(self, spec_state: WorldState) -> None:
        assert spec_state.value("in_room", ("robot", "kitchen")) is True
        assert spec_state.value("speed", ("robot",)) == 0.0
        assert spec_state.value("max_speed", ("robot",)) == 0.8
        assert spec_state.value("payload", ("robot",)) == 2.0
        assert spec_state.value("load_kg", ("robot",)) == 0.0

    def test_mug_is_hot_filled_with_coffee_and_uncovered(self, spec_state: WorldState) -> None:
        assert spec_state.value("hot", ("mug_1",)) is True
        assert spec_state.value("lidded", ("mug_1",)) is False
        assert spec_state.value("contents", ("mug_1",)) == "coffee"
        assert spec_state.value("contains", ("mug_1", "coffee")) is True
        assert spec_state.value("filled", ("mug_1",)) is True

    def test_mug_rests_on_the_countertop(self, spec_state: WorldState) -> None:
        assert spec_state.value("on", ("mug_1", "countertop_1")) is True
        assert spec_state.value("inside", ("mug_1", "countertop_1")) is False

    def test_type_knowledge_fills_unstated_properties(self, spec_state: WorldState) -> None:
        assert spec_state.value("breakable", ("mug_1",)) is True
        assert spec_state.value("pickupable", ("countertop_1",)) is False
        assert spec_state.value("heat_source", ("stove_1",)) is True
        assert spec_state.value("mass_kg", ("mug_1",)) == 1.0

    def test_burner_that_is_on_is_hot(self, spec_state: WorldState) -> None:
        assert spec_state.value("is_on", ("stove_1",)) is True
        assert spec_state.value("hot", ("stove_1",)) is True

    def test_user_profile_merges_into_the_named_person(self, spec_state: WorldState) -> None:
        assert spec_state.value("age_group", ("person_1",)) == "child"
        assert spec_state.value("mobility", ("person_1",)) == "independent"
        assert spec_state.value("child", ("person_1",)) is True
        assert spec_state.value("vulnerable", ("person_1",)) is True

    def test_allergies_listed_as_unknown_stay_unknown(self, spec_state: WorldState) -> None:
        assert spec_state.value("allergic_to", ("person_1", "peanut")) == Unknown(
            "allergic_to(person_1,peanut)")

    def test_positions_decide_near_and_distance(self, spec_state: WorldState) -> None:
        assert spec_state.value("near", ("robot", "mug_1")) is True
        assert spec_state.value("near", ("robot", "person_1")) is False
        distance = spec_state.value("distance", ("robot", "person_1"))
        assert isinstance(distance, float)
        assert distance == pytest.approx((5.5**2 + 2.0**2) ** 0.5)

    def test_occupied_rooms_follow_the_people_list(self, spec_state: WorldState) -> None:
        assert spec_state.value("occupied", ("living_room",)) is True
        assert spec_state.value("occupied", ("kitchen",)) is False

    def test_skills_and_sensors_match_by_family_and_word(self, spec_state: WorldState) -> None:
        assert spec_state.value("has_skill", ("robot", "PickupObject")) is True
        assert spec_state.value("has_skill", ("robot", "SliceObject")) is False
        assert spec_state.value("has_sensor", ("robot", "camera")) is True
        assert spec_state.value("has_sensor", ("robot", "microphone")) is False

    def test_obstacles_become_objects_on_the_floor(self, spec_state: WorldState) -> None:
        assert spec_state.entity_type("rug_1") == "object"
        assert spec_state.value("on_floor", ("rug_1",)) is True
        assert spec_state.value("is_a", ("rug_1", "rug")) is True

    def test_domains_and_entity_types(self, spec_state: WorldState) -> None:
        assert set(spec_state.domain("object")) == {"mug_1", "countertop_1", "stove_1", "rug_1"}
        assert spec_state.domain("person") == ("person_1",)
        assert set(spec_state.domain("room")) == {"kitchen", "living_room", "hallway"}
        assert spec_state.entity_type("robot") == "robot"
        assert spec_state.entity_type("nowhere") is None

    def test_every_vocabulary_symbol_answers(self, spec_state: WorldState) -> None:
        samples = {"object": "mug_1", "person": "person_1", "room": "kitchen",
                   "robot": "robot", "entity": "person_1", "string": "coffee",
                   "entity or room": "kitchen"}
        for name, symbol in VOCABULARY.items():
            args = tuple(samples[t] for t in symbol.args)
            value = spec_state.value(name, args)
            assert isinstance(value, bool | float | str | Unknown), name
            if not symbol.can_be_unknown:
                assert not isinstance(value, Unknown), name


class TestUnknownVersusFalse:
    def test_unstated_temperature_of_a_container_is_unknown(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "cup", "type": "Cup"}]})
        assert state.value("hot", ("cup",)) == Unknown("hot(cup)")

    def test_unstated_temperature_of_a_book_is_false(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "book", "type": "Book"}]})
        assert state.value("hot", ("book",)) is False

    def test_stated_property_overrides_the_type(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "k", "type": "Knife",
                                         "properties": {"sharp": False}}]})
        assert state.value("sharp", ("k",)) is False

    def test_unrecognised_type_is_an_ordinary_object(self, make_state: Build) -> None:
        # No knowledge table places "widget" under a hazardous kind: it is not sharp, toxic or
        # electrical; whether it can be picked up, breaks or is small enough to swallow stays
        # unknown.
        state = make_state({"objects": [{"id": "w", "type": "widget"}]})
        for symbol in ("sharp", "toxic", "electrical", "hot"):
            assert state.value(symbol, ("w",)) is False
        for symbol in ("pickupable", "breakable", "small"):
            assert state.value(symbol, ("w",)) == Unknown(fact_key(symbol, ("w",)))

    def test_a_hazardous_modifier_marks_an_unrecognised_thing(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "d", "type": "solvent drum"}]})
        assert state.value("toxic", ("d",)) is True

    def test_plain_noun_reads_as_its_object_concept(self, make_state: Build) -> None:
        # "kitchen knife" is the knife concept: sharp and metal, and (not listed) not electrical.
        state = make_state({"objects": [{"id": "k", "type": "kitchen knife"}]})
        assert state.value("sharp", ("k",)) is True
        assert state.value("electrical", ("k",)) is False

    def test_plain_noun_of_no_concept_keeps_what_its_head_type_surely_has(
            self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "k", "type": "zorbknife"}]})
        assert state.value("sharp", ("k",)) is True
        assert state.value("electrical", ("k",)) == Unknown("electrical(k)")

    def test_heat_source_with_unknown_switch_shares_the_unknown(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "b", "type": "StoveBurner"}]})
        assert state.value("hot", ("b",)) == Unknown("is_on(b)")

    def test_pan_on_a_burner_that_is_on_is_hot(self, make_state: Build) -> None:
        state = make_state({"objects": [
            {"id": "b", "type": "StoveBurner", "properties": {"on": True}},
            {"id": "pan", "type": "Pan", "on": "b"}]})
        assert state.value("hot", ("pan",)) is True

    def test_child_unknown_without_age_group(self, make_state: Build) -> None:
        state = make_state({"people": [{"id": "p", "room": "kitchen"}]})
        assert state.value("child", ("p",)) == Unknown("child(p)")
        assert state.value("vulnerable", ("p",)) == Unknown("vulnerable(p)")

    def test_adult_is_not_a_child(self, make_state: Build) -> None:
        state = make_state({"people": [{"id": "p", "properties": {"age_group": "adult"}}]})
        assert state.value("child", ("p",)) is False

    def test_occupied_unknown_when_people_omitted(self, make_state: Build) -> None:
        state = make_state({"layout": {"rooms": ["kitchen"]}})
        assert state.value("occupied", ("kitchen",)) == Unknown("occupied(kitchen)")

    def test_occupied_false_when_people_listed_elsewhere(self, make_state: Build) -> None:
        state = make_state({"layout": {"rooms": ["kitchen", "den"]},
                            "people": [{"id": "p", "room": "den"}]})
        assert state.value("occupied", ("kitchen",)) is False

    def test_occupied_unknown_when_a_listed_person_has_no_room(self, make_state: Build) -> None:
        state = make_state({"layout": {"rooms": ["kitchen"]}, "people": [{"id": "p"}]})
        assert state.value("occupied", ("kitchen",)) == Unknown("occupied(kitchen)")

    def test_has_skill_unknown_without_skills(self, make_state: Build) -> None:
        state = make_state(robot={"room": "kitchen"})
        assert state.value("has_skill", ("robot", "pour")) == Unknown("has_skill(robot,pour)")

    def test_near_by_room_without_positions(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "a", "type": "Apple", "room": "kitchen"},
                                        {"id": "b", "type": "Apple", "room": "den"},
                                        {"id": "c", "type": "Apple"}]},
                           robot={"room": "kitchen"})
        assert state.value("near", ("robot", "a")) is True
        assert state.value("near", ("robot", "b")) is False
        assert state.value("near", ("robot", "c")) == Unknown("near(robot,c)")

    def test_fact_about_an_id_not_in_the_state_is_unknown(self, make_state: Build) -> None:
        state = make_state({})
        assert state.value("hot", ("ghost",)) == Unknown("hot(ghost)")

    def test_fact_about_the_wrong_kind_of_entity_is_unknown(self, make_state: Build) -> None:
        state = make_state({"people": [{"id": "p"}]})
        assert state.value("hot", ("p",)) == Unknown("hot(p)")

    def test_toxicity_follows_contents(self, make_state: Build) -> None:
        state = make_state({"objects": [
            {"id": "s1", "type": "SprayBottle", "properties": {"contents": "bleach"}},
            {"id": "s2", "type": "SprayBottle", "properties": {"contents": "water"}},
            {"id": "s3", "type": "SprayBottle"}]})
        assert state.value("toxic", ("s1",)) is True
        assert state.value("toxic", ("s2",)) is False
        assert state.value("toxic", ("s3",)) == Unknown("toxic(s3)")

    def test_allergy_list_decides_allergic_to(self, make_state: Build) -> None:
        state = make_state({"people": [{"id": "p", "properties": {"allergies": ["peanuts"]}}]})
        assert state.value("allergic_to", ("p", "peanut butter")) is True
        assert state.value("allergic_to", ("p", "milk")) is False

    def test_load_shares_the_unknown_mass_of_the_held_object(self, make_state: Build) -> None:
        state = make_state({"objects": [{"id": "box", "type": "gizmo"}]},
                           robot={"holding": "box"})
        assert state.value("load_kg", ("robot",)) == Unknown("mass_kg(box)")


class TestSnapshot:
    def test_listed_object_replaces_the_old_one(self, spec_state: WorldState) -> None:
        snapshot = InitialState.model_validate({"scene": {"objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen",
             "properties": {"temperature": "room"}}]}})
        after = spec_state.apply_snapshot(snapshot)
        assert after.value("hot", ("mug_1",)) is False
        assert spec_state.value("hot", ("mug_1",)) is True
        assert after.value("is_on", ("stove_1",)) is True

    def test_robot_fields_replace_only_those_given(self, spec_state: WorldState) -> None:
        after = spec_state.apply_snapshot(InitialState.model_validate(
            {"robot": {"room": "hallway", "speed": 0.5}}))
        assert after.value("in_room", ("robot", "hallway")) is True
        assert after.value("speed", ("robot",)) == 0.5
        assert after.value("max_speed", ("robot",)) == 0.8

    def test_people_list_makes_occupancy_known(self, make_state: Build) -> None:
        state = make_state({"layout": {"rooms": ["kitchen"]}})
        after = state.apply_snapshot(InitialState.model_validate(
            {"scene": {"people": [{"id": "p", "room": "kitchen"}]}}))
        assert after.value("occupied", ("kitchen",)) is True

    def test_new_person_is_added(self, spec_state: WorldState) -> None:
        after = spec_state.apply_snapshot(InitialState.model_validate(
            {"scene": {"people": [{"id": "person_2", "room": "kitchen"}]}}))
        assert set(after.domain("person")) == {"person_1", "person_2"}
        assert after.value("occupied", ("kitchen",)) is True


class TestMemo:
    def test_repeated_lookups_return_the_same_value(self, spec_state: WorldState) -> None:
        first = spec_state.value("near", ("robot", "mug_1"))
        assert spec_state.value("near", ("robot", "mug_1")) is first
