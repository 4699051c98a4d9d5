"""LLM analyses are cached in the store by (request, model, prompt version); failures are not."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer, PromptSet, request_hash
from app.adapters.llm.prompting import PROMPTS_DIR
from app.domain.ensemble import ANALYSIS_UNAVAILABLE
from app.store import Repository
from tests.adapters.llm.answers import COFFEE_REQUEST, EMPTY_LEVEL, SAFE_REQUEST, hazard
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer

ClientFactory = Callable[..., LitellmClient]
ONE_HAZARD = {"hazards": [hazard(entities={"obj": "mug_1"})], "unknowns": []}


class TestAnalysisCache:
    def test_the_same_request_is_answered_from_the_store(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(EMPTY_LEVEL, ONE_HAZARD, EMPTY_LEVEL)
        first = LlmAnalyzer(make_client(), cache=repository).analyze(COFFEE_REQUEST)
        second = LlmAnalyzer(make_client(), cache=repository).analyze(COFFEE_REQUEST)
        assert second == first
        assert [p.hazard_class for p in second.proposals] == ["scald_hot_liquid"]
        assert len(llm_server.requests) == 3

    def test_a_different_request_is_analysed_afresh(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*[EMPTY_LEVEL] * 6)
        analyzer = LlmAnalyzer(make_client(), cache=repository)
        analyzer.analyze(COFFEE_REQUEST)
        analyzer.analyze(SAFE_REQUEST)
        assert len(llm_server.requests) == 6
        assert request_hash(COFFEE_REQUEST) != request_hash(SAFE_REQUEST)

    def test_another_prompt_version_misses_the_cache(
        self, tmp_path: Path, repository: Repository, llm_server: ScriptedServer,
        make_client: ClientFactory
    ) -> None:
        edited = tmp_path / "v1"
        edited.mkdir()
        for prompt in (PROMPTS_DIR / "v1").glob("*.md"):
            (edited / prompt.name).write_text(prompt.read_text() + "\n(edited)\n")
        llm_server.answer_json(*[EMPTY_LEVEL] * 6)
        LlmAnalyzer(make_client(), cache=repository).analyze(COFFEE_REQUEST)
        LlmAnalyzer(make_client(), cache=repository,
                    prompts=PromptSet(root=tmp_path)).analyze(COFFEE_REQUEST)
        assert len(llm_server.requests) == 6

    @pytest.mark.faults
    def test_a_failed_analysis_is_not_cached(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.queue(Scripted(status=500))
        llm_server.answer_json(EMPTY_LEVEL, EMPTY_LEVEL, EMPTY_LEVEL)
        analyzer = LlmAnalyzer(make_client(), cache=repository)
        failed = analyzer.analyze(SAFE_REQUEST)
        assert failed.unknowns[0].description == ANALYSIS_UNAVAILABLE
        assert analyzer.analyze(SAFE_REQUEST).unknowns == ()
        assert repository.get_cached_analysis(
            request_hash(SAFE_REQUEST), "openai/scripted-model", analyzer.prompt_version
        ) == {"proposals": [], "unknowns": [], "analyzer": "llm"}
