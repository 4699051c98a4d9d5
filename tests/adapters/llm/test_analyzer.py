"""The LLM analyzer through litellm and real HTTP: the matrix, the repair round, failing closed."""

from __future__ import annotations

import json
from collections.abc import Callable

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer
from app.adapters.llm.analyzer import COMPREHENSION
from app.domain.binding import TemplateIndex
from app.domain.ensemble import ANALYSIS_UNAVAILABLE
from app.domain.gate import Decision, Rule
from app.domain.models import Level, Severity
from app.domain.pipeline import run_gate
from tests.adapters.llm.answers import (
    COFFEE_REQUEST,
    EMPTY_LEVEL,
    SAFE_REQUEST,
    harmless_levels,
    hazard,
    unknown,
)
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer
from tests.conftest import seed_library

ClientFactory = Callable[..., LitellmClient]


def _valid_levels() -> list[dict[str, object]]:
    return [
        {"hazards": [hazard(entities={"obj": "ignored"})], "unknowns": [unknown(entity=None)]},
        {"hazards": [hazard(entities={"obj": "mug_1", "person": "guest_1"})],
         "unknowns": [unknown()]},
        {"hazards": [hazard(entities={"obj": "mug_1", "person": "guest_1"}, severity="critical"),
                     hazard("missing_sensor", category="operational", severity="moderate")],
         "unknowns": [unknown()],
         "dismissed": []},
    ]


class TestLlmAnalyzer:
    def test_fills_the_matrix_level_by_level(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*_valid_levels())
        report = LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST)
        assert report.analyzer == "llm"
        by_class = {p.hazard_class: p for p in report.proposals}
        assert set(by_class) == {"scald_hot_liquid", "missing_sensor"}
        scald = by_class["scald_hot_liquid"]
        assert scald.level is Level.TASK  # first seen with the command alone
        assert scald.severity is Severity.CRITICAL  # the best-informed level's judgement
        assert scald.entities == {"obj": "mug_1", "person": "guest_1"}
        assert scald.source == "llm:openai/scripted-model"
        assert by_class["missing_sensor"].level is Level.USER
        assert [u.attribute for u in report.unknowns] == ["age_group"]
        assert report.unknowns[0].entity == "guest_1"

    def test_each_level_sees_a_larger_partition(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*_valid_levels())
        LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST)
        prompts = [r["messages"][-1]["content"] for r in llm_server.requests]
        assert len(prompts) == 3
        assert "Scene (JSON data)" not in prompts[0]
        assert "Scene (JSON data)" in prompts[1] and "Robot" not in prompts[1]
        assert "User being served: not given" in prompts[2] and "Robot (JSON data)" in prompts[2]
        assert "physical/scald_hot_liquid" in prompts[1]  # the earlier level's finding
        system = llm_server.requests[0]["messages"][0]["content"]
        assert "Never assume that something you were not told is safe" in system

    def test_an_earlier_hazard_the_later_level_dismisses_is_dropped(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        dismissal = {"kind": "hazard", "name": "scald_hot_liquid", "why": "the drink is cold"}
        llm_server.answer_json({"hazards": [hazard()], "unknowns": []},
                               {**EMPTY_LEVEL, "dismissed": [dismissal]}, EMPTY_LEVEL)
        assert LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST).proposals == ()

    def test_an_earlier_hazard_left_unmentioned_is_kept(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json({"hazards": [hazard()], "unknowns": []}, EMPTY_LEVEL, EMPTY_LEVEL)
        report = LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST)
        assert [p.hazard_class for p in report.proposals] == ["scald_hot_liquid"]

    def test_one_malformed_answer_is_repaired(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        levels = _valid_levels()
        llm_server.queue(Scripted(content="{\"hazards\": [oops"))
        llm_server.answer_json(*levels)
        report = LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST)
        assert {p.hazard_class for p in report.proposals} == {"scald_hot_liquid", "missing_sensor"}
        repair = llm_server.requests[1]["messages"]
        assert repair[-2] == {"role": "assistant", "content": "{\"hazards\": [oops"}
        assert "not valid JSON" in repair[-1]["content"]

    def test_an_entity_id_not_in_the_scene_is_sent_back_for_repair(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        invented = {"hazards": [hazard(entities={"obj": "kettle_9"})], "unknowns": []}
        llm_server.answer_json(EMPTY_LEVEL, invented, invented)
        report = LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST)
        assert report.unknowns[0].description == ANALYSIS_UNAVAILABLE
        assert "kettle_9" in llm_server.requests[2]["messages"][-1]["content"]


FAILURES: dict[str, list[Scripted]] = {
    "malformed JSON twice": [Scripted(content="{not json"), Scripted(content="still not")],
    "truncated output": [Scripted(content='{"hazards": [{"category": "phys'),
                         Scripted(content='{"hazards": [', finish_reason="length")],
    "cut at the length limit": [Scripted(content=json.dumps(EMPTY_LEVEL), finish_reason="length")]
    * 2,
    "schema violation": [Scripted(content=json.dumps({"hazards": [hazard(severity="dire")],
                                                      "unknowns": []}))] * 2,
    "not an object": [Scripted(content="[]")] * 2,
    "HTTP 500": [Scripted(status=500)],
    "HTTP 429": [Scripted(status=429)],
    "slow answer past the timeout": [Scripted(content=json.dumps(EMPTY_LEVEL), delay=2.5)],
}


@pytest.mark.faults
class TestFailingClosed:
    def test_a_clean_analysis_authorizes_so_the_failure_tests_can_fail(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*harmless_levels())
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                          analyzer=LlmAnalyzer(make_client()))
        assert result.decision.decision is Decision.AUTHORIZE

    def test_an_empty_analysis_is_not_understood(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(EMPTY_LEVEL, EMPTY_LEVEL, EMPTY_LEVEL)
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                          analyzer=LlmAnalyzer(make_client()))
        assert (result.decision.decision, result.decision.rule) == (Decision.DEFER, Rule.R3)
        assert [(u.attribute, u.critical) for u in result.report.unknowns] == [
            (COMPREHENSION, True)]

    @pytest.mark.parametrize("failure", list(FAILURES), ids=list(FAILURES))
    def test_every_failure_defers(
        self, llm_server: ScriptedServer, make_client: ClientFactory, failure: str
    ) -> None:
        # The failure strikes at the last level, after two clean answers.
        llm_server.answer_json(*harmless_levels()[:2])
        llm_server.queue(*FAILURES[failure])
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                          analyzer=LlmAnalyzer(make_client(timeout=1.0)))
        assert result.decision.decision is Decision.DEFER
        assert result.decision.rule is Rule.R3
        assert result.report.proposals == ()
        assert [u.description for u in result.report.unknowns] == [ANALYSIS_UNAVAILABLE]
        assert result.report.unknowns[0].critical
        assert not llm_server.script  # every scripted answer was asked for: no shortcut
