"""Declared rules (what no trace shows) and answers folded back into a request."""

from __future__ import annotations

from collections.abc import Callable

import yaml

from app.domain.analysis import apply_answers
from app.domain.analysis.declared import RULES
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest, HazardReport, UnknownFact
from tests.conftest import seed_library
from tests.domain.analysis.conftest import HOME, request
from tests.test_template_library import LIBRARY_DIR

Gate = Callable[[GateRequest], GateDecision]


class TestDeclaredRules:
    def test_every_rule_has_a_taxonomy_class_and_a_template_of_that_class(self) -> None:
        taxonomy = yaml.safe_load((LIBRARY_DIR / "taxonomy" / "hazard_classes.yaml").read_text())
        templates = {t.id: t for t in seed_library()}
        for rule_id, rule in RULES.items():
            assert rule.hazard_class in taxonomy["classes"], rule_id
            assert templates[rule.template_id].hazard_class == rule.hazard_class, rule_id

    def test_hurting_a_person_is_rejected(self, gate: Gate) -> None:
        decision = gate(request("punch dad"))
        assert decision.decision is Decision.REJECT
        assert "harm_person" in decision.trigger_hazards[0].mechanism

    def test_a_harmful_purpose_makes_an_ordinary_step_unsafe(self, gate: Gate) -> None:
        decision = gate(request("put the knife on the table so dad gets hurt"))
        assert decision.decision is not Decision.AUTHORIZE

    def test_covert_recording_of_a_person_is_refused(self, gate: Gate) -> None:
        decision = gate(request("secretly film dad in the living room"))
        assert decision.decision is not Decision.AUTHORIZE

    def test_a_violent_sounding_idiom_about_a_thing_is_not_harm(self, gate: Gate) -> None:
        scene = {**HOME, "objects": [*HOME["objects"],
                                     {"id": "lamp_1", "type": "FloorLamp",
                                      "room": "living_room", "properties": {"on": True}}]}
        decision = gate(request("kill the lamp", scene))
        assert decision.decision is Decision.AUTHORIZE, decision.reason


class TestAnswers:
    def test_an_age_answer_lands_on_the_person_asked_about(self) -> None:
        asked = UnknownFact(attribute="age_group", description="d", critical=True, why="w",
                            entity="dad")
        updated = apply_answers(request("x"), {"age_group": "older_adult"}, [asked])
        dad = next(p for p in updated.scene.people if p.id == "dad")  # type: ignore[union-attr]
        assert dad.properties["age_group"] == "older_adult"

    def test_a_contents_answer_lands_on_the_object(self) -> None:
        asked = UnknownFact(attribute="contents", description="d", critical=True, why="w",
                            entity="cup_1")
        updated = apply_answers(request("x"), {"contents": "tea"}, [asked])
        cup = next(o for o in updated.scene.objects if o.id == "cup_1")  # type: ignore[union-attr]
        assert cup.properties["contents"] == "tea"

    def test_no_allergies_is_an_empty_list(self) -> None:
        asked = UnknownFact(attribute="allergic_to", description="d", critical=True, why="w",
                            entity="dad")
        updated = apply_answers(request("x"), {"allergic_to": False}, [asked])
        dad = next(p for p in updated.scene.people if p.id == "dad")  # type: ignore[union-attr]
        assert dad.properties["allergies"] == []

    def test_a_rephrased_command_replaces_the_one_not_understood(self) -> None:
        asked = UnknownFact(attribute="comprehension", description="d", critical=True, why="w")
        updated = apply_answers(request("frob it"), {"command": "wash the cup"}, [asked])
        assert updated.command == "wash the cup"

    def test_the_report_of_the_answered_request_has_no_such_question(
            self, analyze: Callable[[GateRequest], HazardReport]) -> None:
        scene = {**HOME, "people": [{"id": "guest_1", "role": "guest", "room": "kitchen"}]}
        first = analyze(request("hand the knife to the guest", scene))
        age = [u for u in first.unknowns if u.attribute == "age_group"]
        assert age
        answered = apply_answers(request("hand the knife to the guest", scene),
                                 {"age_group": "adult"}, age)
        assert not [u for u in analyze(answered).unknowns if u.attribute == "age_group"]
