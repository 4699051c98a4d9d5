"""Calibration (theta in the severity anchors, unknown attributes /answers applies) and cost
(one system prompt for every call of a request; the three levels batched into one call)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer
from app.adapters.llm.library import LibraryView
from app.domain.analysis.answers import ANSWERABLE_ATTRIBUTES, apply_answers
from app.domain.binding import TemplateIndex
from app.domain.ensemble import ANALYSIS_UNAVAILABLE
from app.domain.gate import Decision, Rule
from app.domain.models import Severity, UnknownFact
from app.domain.pipeline import run_gate
from tests.adapters.llm.answers import (
    SAFE_REQUEST,
    TWO_PEOPLE_REQUEST,
    harmless_levels,
    hazard,
    unknown,
)
from tests.adapters.llm.scripted_server import ScriptedServer
from tests.conftest import seed_library

ClientFactory = Callable[..., LitellmClient]
SCALD = hazard("scald_hot_liquid")
SCALD_MUG = hazard("scald_hot_liquid", entities={"obj": "mug_1"})

# A value each attribute's question could be answered with, as a caller would send it.
ANSWER_VALUES: dict[str, Any] = {
    "age": 7, "age_group": "adult", "allergic_to": False, "allergies": ["peanut"],
    "asleep": True, "cognitive_state": "impaired", "consents": True,
    "hearing_impairment": True, "impaired": True, "location": "kitchen",
    "mobility": "wheelchair", "needs_walking_aid": True, "pregnant": True,
    "visual_impairment": "low vision", "contents": "tea", "owner": "grandpa", "is_on": True,
    "hot": False, "mass_kg": 0.4, "lidded": True, "sealed": True, "sharp": True,
    "fragile": True, "toxic": True, "flammable": True, "open": True, "broken": True,
    "electrical": True, "wet": True, "temperature": "cold", "command": "put the mug away",
}
SUBJECT_ENTITY = {"person": "kid_1", "object": "mug_1", "task": None}


class TestCalibration:
    def test_the_severity_anchors_name_the_gates_theta(
        self, make_client: ClientFactory
    ) -> None:
        view = LibraryView.of(seed_library())
        for theta in (Severity.HIGH, Severity.CRITICAL):
            system = LlmAnalyzer(make_client(), theta=theta).system_prompt(view)
            assert f"severity {theta.value} or above" in system

    def test_the_prompt_offers_exactly_the_attributes_answers_apply(
        self, make_client: ClientFactory
    ) -> None:
        system = LlmAnalyzer(make_client()).system_prompt(LibraryView.of(seed_library()))
        offered = {name.strip() for line in system.splitlines() if line.startswith("- about ")
                   for name in line.split(":", 1)[1].split(",")}
        assert offered == set(ANSWERABLE_ATTRIBUTES)

    @pytest.mark.parametrize("attribute", sorted(ANSWERABLE_ATTRIBUTES))
    def test_every_offered_attribute_is_applied_by_answers(self, attribute: str) -> None:
        asked = UnknownFact(attribute=attribute, description="d", critical=True, why="w",
                            entity=SUBJECT_ENTITY[ANSWERABLE_ATTRIBUTES[attribute]])
        updated = apply_answers(TWO_PEOPLE_REQUEST, {attribute: ANSWER_VALUES[attribute]},
                                [asked])
        assert updated != TWO_PEOPLE_REQUEST

    def test_an_attribute_outside_the_list_is_sent_back(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        free_form = {"hazards": [SCALD_MUG], "unknowns": [unknown("kid_age", entity="kid_1")]}
        listed = {"hazards": [SCALD_MUG], "unknowns": [unknown("age_group", entity="kid_1")]}
        llm_server.answer_json({"hazards": [SCALD], "unknowns": []}, free_form, listed, listed)
        report = LlmAnalyzer(make_client()).analyze(TWO_PEOPLE_REQUEST, seed_library())
        repair = llm_server.requests[2]["messages"][-1]["content"]
        assert "'kid_age' is not one of the listed attributes" in repair
        assert [(u.attribute, u.entity) for u in report.unknowns] == [("age_group", "kid_1")]

    def test_an_objects_unknown_must_name_the_object(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        vague = {"hazards": [SCALD_MUG], "unknowns": [unknown("contents", entity=None)]}
        llm_server.answer_json({"hazards": [SCALD], "unknowns": []}, vague, vague)
        report = LlmAnalyzer(make_client()).analyze(TWO_PEOPLE_REQUEST, seed_library())
        assert [u.description for u in report.unknowns] == [ANALYSIS_UNAVAILABLE]
        assert "name the object id" in llm_server.requests[2]["messages"][-1]["content"]


class TestOneSystemPrompt:
    def test_every_call_of_a_request_shares_one_system_prompt(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*harmless_levels())
        LlmAnalyzer(make_client()).analyze(SAFE_REQUEST, seed_library())
        systems = {r["messages"][0]["content"] for r in llm_server.requests}
        assert len(llm_server.requests) == 3 and len(systems) == 1


def _batched(task: Any, deployment: Any, user: Any) -> dict[str, Any]:
    return {"task": task, "deployment": deployment, "user": user}


class TestBatchedLevels:
    def test_one_call_fills_the_three_levels(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(_batched(*harmless_levels()))
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                          analyzer=LlmAnalyzer(make_client(), batch_levels=True))
        assert len(llm_server.requests) == 1
        prompt = llm_server.requests[0]["messages"][-1]["content"]
        assert "Scene (JSON data)" in prompt and "Robot (JSON data)" in prompt
        assert [p.entities for p in result.report.proposals] == [{"obj": "apple_1"}]
        assert result.decision.decision is Decision.AUTHORIZE

    def test_levels_merge_as_if_asked_one_by_one(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(_batched(
            {"hazards": [SCALD], "unknowns": []},
            {"hazards": [SCALD_MUG], "unknowns": [unknown(entity="kid_1", critical=True)]},
            {"hazards": [SCALD_MUG], "unknowns": [unknown(entity="guest_1", critical=False)]},
        ))
        result = run_gate(TWO_PEOPLE_REQUEST, templates=TemplateIndex(seed_library()),
                          analyzer=LlmAnalyzer(make_client(), batch_levels=True))
        assert (result.decision.decision, result.decision.rule) == (Decision.DEFER, Rule.R3)

    def test_a_bad_level_in_the_batch_is_repaired_or_fails_closed(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        bad = _batched(*harmless_levels()[:2], {"hazards": [hazard("scald_hot_liquids")],
                                                "unknowns": []})
        llm_server.answer_json(bad, bad)
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                          analyzer=LlmAnalyzer(make_client(), batch_levels=True))
        assert "user.hazards[0].hazard_class" in llm_server.requests[1]["messages"][-1]["content"]
        assert result.decision.decision is Decision.DEFER
        assert [u.description for u in result.report.unknowns] == [ANALYSIS_UNAVAILABLE]
