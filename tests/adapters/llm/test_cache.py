"""LLM analyses are cached in the store by (request, model, prompt version); failures are not."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer, PromptSet, request_hash
from app.adapters.llm.caching import CachedAnalyses
from app.adapters.llm.prompting import PROMPTS_DIR
from app.domain.ensemble import ANALYSIS_UNAVAILABLE
from app.domain.models import GateRequest
from app.store import Repository
from tests.adapters.llm.answers import COFFEE_REQUEST, EMPTY_LEVEL, SAFE_REQUEST, hazard
from tests.adapters.llm.conftest import SCRIPTED_MODEL
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer
from tests.conftest import seed_library

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
        fresh = analyzer.analyze(SAFE_REQUEST)
        assert [u.attribute for u in fresh.unknowns] == ["comprehension"]
        assert analyzer.analyze(SAFE_REQUEST) == fresh
        assert len(llm_server.requests) == 4  # the failure once, then three levels, cached


class TestCacheKey:
    def test_a_curator_change_to_the_library_misses_the_cache(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*[ONE_HAZARD] * 6)
        analyzer = LlmAnalyzer(make_client(), cache=repository)
        library = seed_library()
        analyzer.analyze(COFFEE_REQUEST, library)
        analyzer.analyze(COFFEE_REQUEST, library)
        assert len(llm_server.requests) == 3
        analyzer.analyze(COFFEE_REQUEST, [t for t in library if t.hazard_class != "choking"])
        assert len(llm_server.requests) == 6

    def test_other_model_settings_miss_the_cache(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*[ONE_HAZARD] * 6)
        LlmAnalyzer(make_client(), cache=repository).analyze(COFFEE_REQUEST)
        LlmAnalyzer(make_client(temperature=0.7), cache=repository).analyze(COFFEE_REQUEST)
        assert len(llm_server.requests) == 6

    def test_an_expired_entry_is_analysed_afresh(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(*[ONE_HAZARD] * 6)
        now = [1000.0]
        cache = CachedAnalyses(repository, model=SCRIPTED_MODEL,
                               prompt_version=PromptSet().identity, ttl_seconds=60,
                               clock=lambda: now[0])
        report = LlmAnalyzer(make_client()).analyze(COFFEE_REQUEST)
        cache.put("k", report)
        now[0] += 59
        assert cache.get("k") == report
        now[0] += 2
        assert cache.get("k") is None

    def test_extra_keys_the_model_never_sees_do_not_split_the_cache(self) -> None:
        body = COFFEE_REQUEST.model_dump(mode="json", by_alias=True, exclude_none=True)
        padded = GateRequest.model_validate({**body, "tracking_id": "abc-123"})
        assert request_hash(padded) == request_hash(COFFEE_REQUEST)

    def test_an_empty_analysis_cached_by_an_ensemble_member_is_still_not_understood_alone(
        self, repository: Repository, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(EMPTY_LEVEL, EMPTY_LEVEL, EMPTY_LEVEL)
        member = LlmAnalyzer(make_client(), cache=repository, require_findings=False)
        assert member.analyze(SAFE_REQUEST).unknowns == ()
        alone = LlmAnalyzer(make_client(), cache=repository).analyze(SAFE_REQUEST)
        assert len(llm_server.requests) == 3  # served from the cache
        assert [u.attribute for u in alone.unknowns] == ["comprehension"]
