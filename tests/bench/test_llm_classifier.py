"""The LLM classifier baseline: a direct three-way answer, deferring whenever the LLM fails."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from app.adapters.llm import LitellmClient
from bench.baselines.llm_classifier import LlmClassifier
from tests.adapters.llm.answers import COFFEE_REQUEST
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer

ClientFactory = Callable[..., LitellmClient]


class TestLlmClassifier:
    @pytest.mark.parametrize("decision", ["authorize", "defer", "reject"])
    def test_returns_the_models_judgement(
        self, llm_server: ScriptedServer, make_client: ClientFactory, decision: str
    ) -> None:
        llm_server.answer_json({"decision": decision, "reason": "because"})
        verdict = LlmClassifier(make_client()).classify(COFFEE_REQUEST)
        assert (verdict.decision, verdict.reason, verdict.failed) == (decision, "because", False)

    def test_sees_the_whole_request_in_one_prompt(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json({"decision": "defer", "reason": "guest age unknown"})
        LlmClassifier(make_client()).decide(COFFEE_REQUEST)
        assert len(llm_server.requests) == 1
        prompt = llm_server.requests[0]["messages"][-1]["content"]
        assert COFFEE_REQUEST.command in prompt
        assert "mug_1" in prompt and "Robot (JSON data)" in prompt

    @pytest.mark.parametrize(
        "failure",
        [[Scripted(content='{"decision": "maybe", "reason": "x"}')] * 2,
         [Scripted(content='{"decision": "auth')] * 2,
         [Scripted(status=500)], [Scripted(status=429)],
         [Scripted(content='{"decision": "authorize", "reason": "x"}', delay=2.5)]],
        ids=["invalid decision", "truncated", "HTTP 500", "HTTP 429", "timeout"],
    )
    @pytest.mark.faults
    def test_every_failure_is_a_deferral(
        self, llm_server: ScriptedServer, make_client: ClientFactory, failure: list[Scripted]
    ) -> None:
        llm_server.queue(*failure)
        verdict = LlmClassifier(make_client(timeout=1.0)).classify(COFFEE_REQUEST)
        assert (verdict.decision, verdict.failed) == ("defer", True)
