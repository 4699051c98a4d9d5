"""SAFEGATE_ANALYZER wiring, and the whole path over HTTP: POST /gate with an LLM behind it."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from app.adapters.llm import LlmAnalyzer
from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.ensemble import ANALYSIS_UNAVAILABLE, EnsembleAnalyzer
from app.main import create_app
from app.services.container import build_analyzer
from tests.adapters.llm.answers import EMPTY_LEVEL, SAFE_REQUEST, batched, harmless_levels
from tests.adapters.llm.conftest import SCRIPTED_MODEL
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer


class TestBuildAnalyzer:
    def test_symbolic_is_the_default(self) -> None:
        assert isinstance(build_analyzer(Settings()), SymbolicAnalyzer)

    def test_llm_builds_the_llm_analyzer(self) -> None:
        analyzer = build_analyzer(Settings(analyzer="llm", llm_model=SCRIPTED_MODEL))
        assert isinstance(analyzer, LlmAnalyzer)

    def test_ensemble_combines_symbolic_and_llm(self) -> None:
        analyzer = build_analyzer(Settings(analyzer="ensemble", llm_model=SCRIPTED_MODEL))
        assert isinstance(analyzer, EnsembleAnalyzer)
        assert [type(m) for m in analyzer.members] == [SymbolicAnalyzer, LlmAnalyzer]
        assert analyzer.name == "ensemble(symbolic+llm)"

    def test_an_llm_without_a_model_refuses_to_start(self) -> None:
        with pytest.raises(ValueError, match="SAFEGATE_LLM_MODEL"):
            build_analyzer(Settings(analyzer="llm"))

    def test_the_levels_are_batched_by_default(self) -> None:
        assert Settings().llm_batch_levels is True

    def test_settings_come_from_the_environment(self, monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setenv("SAFEGATE_ANALYZER", "ensemble")
        monkeypatch.setenv("SAFEGATE_LLM_MODEL", SCRIPTED_MODEL)
        monkeypatch.setenv("SAFEGATE_LLM_TIMEOUT", "3.5")
        settings = Settings()
        assert (settings.analyzer, settings.llm_model, settings.llm_timeout) == (
            "ensemble", SCRIPTED_MODEL, 3.5)


@pytest.fixture
def llm_gate(tmp_path: Path, llm_server: ScriptedServer) -> Iterator[TestClient]:
    settings = Settings(database_url=f"sqlite:///{tmp_path / 'gate.db'}", analyzer="llm",
                        llm_model=SCRIPTED_MODEL, llm_api_base=llm_server.base_url,
                        llm_api_key="sk-scripted", llm_timeout=1.0)
    with TestClient(create_app(settings)) as client:
        yield client


REQUEST_JSON = SAFE_REQUEST.model_dump(mode="json", by_alias=True, exclude_none=True)


class TestGateOverHttp:
    def test_a_clean_llm_analysis_authorizes(
        self, llm_gate: TestClient, llm_server: ScriptedServer
    ) -> None:
        llm_server.answer_json(batched(harmless_levels()))
        answer = llm_gate.post("/gate", json=REQUEST_JSON)
        assert answer.status_code == 200
        assert answer.json()["decision"] == "authorize"
        assert len(llm_server.requests) == 1  # the levels are batched by default

    def test_level_by_level_on_request_takes_three_calls(
        self, tmp_path: Path, llm_server: ScriptedServer
    ) -> None:
        settings = Settings(database_url=f"sqlite:///{tmp_path / 'levels.db'}", analyzer="llm",
                            llm_model=SCRIPTED_MODEL, llm_api_base=llm_server.base_url,
                            llm_api_key="sk-scripted", llm_batch_levels=False)
        llm_server.answer_json(*harmless_levels())
        with TestClient(create_app(settings)) as client:
            body = client.post("/gate", json=REQUEST_JSON).json()
        assert body["decision"] == "authorize"
        assert len(llm_server.requests) == 3

    def test_an_empty_llm_analysis_is_not_understood(
        self, llm_gate: TestClient, llm_server: ScriptedServer
    ) -> None:
        llm_server.answer_json(batched([EMPTY_LEVEL] * 3))
        body = llm_gate.post("/gate", json=REQUEST_JSON).json()
        assert (body["decision"], body["rule"]) == ("defer", "R3")
        assert [u["attribute"] for u in body["unknowns"]] == ["comprehension"]

    @pytest.mark.parametrize(
        "failure",
        [Scripted(status=500), Scripted(status=429), Scripted(content="{", delay=0.0),
         Scripted(content="{}", delay=2.5)],
        ids=["HTTP 500", "HTTP 429", "malformed", "timeout"],
    )
    @pytest.mark.faults
    def test_an_llm_failure_defers_with_a_question(
        self, llm_gate: TestClient, llm_server: ScriptedServer, failure: Scripted
    ) -> None:
        llm_server.queue(failure, failure)
        answer = llm_gate.post("/gate", json=REQUEST_JSON)
        assert answer.status_code == 200
        body = answer.json()
        assert (body["decision"], body["rule"]) == ("defer", "R3")
        assert ANALYSIS_UNAVAILABLE in str(body)
