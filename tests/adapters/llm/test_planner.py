"""The SMART-LLM-style planner: plans in the action model, under the contract's constraints."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from app.adapters.llm import LitellmClient, LlmOutputInvalid, LlmPlanner, LlmTimeout
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import planner_constraints
from app.domain.gate import Decision
from app.domain.pipeline import run_gate
from app.store import load_library
from tests.adapters.llm.answers import SAFE_REQUEST
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer

ClientFactory = Callable[..., LitellmClient]
TEMPLATES = Path(__file__).resolve().parents[3] / "templates_db"
GOOD_PLAN = {"steps": [
    {"action": "GoToObject", "object": "apple_1"},
    {"action": "PickupObject", "object": "apple_1"},
    {"action": "GoToObject", "object": "fridge_1"},
    {"action": "OpenObject", "object": "fridge_1"},
    {"action": "PutObject", "object": "apple_1", "target": "fridge_1", "relation": "in"},
    {"action": "CloseObject", "object": "fridge_1"},
]}


class TestLlmPlanner:
    def test_returns_the_plan_in_the_wire_shape(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(GOOD_PLAN)
        plan = LlmPlanner(make_client()).plan(SAFE_REQUEST)
        assert plan == GOOD_PLAN["steps"]

    def test_the_prompt_carries_the_contract_as_constraints(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        gated = run_gate(SAFE_REQUEST, templates=TemplateIndex(load_library(TEMPLATES)),
                         analyzer=SymbolicAnalyzer())
        assert gated.decision.decision is Decision.AUTHORIZE and gated.contract is not None
        constraints = planner_constraints(gated.contract)
        assert constraints
        llm_server.answer_json(GOOD_PLAN)
        LlmPlanner(make_client()).plan(SAFE_REQUEST, gated.contract)
        prompt = llm_server.requests[0]["messages"][-1]["content"]
        assert all(c in prompt for c in constraints)
        system = llm_server.requests[0]["messages"][0]["content"]
        assert "- PickupObject:" in system

    def test_a_step_naming_an_unknown_object_is_sent_back_for_repair(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        wrong = {"steps": [{"action": "PickupObject", "object": "banana_7"}]}
        llm_server.answer_json(wrong, GOOD_PLAN)
        assert LlmPlanner(make_client()).plan(SAFE_REQUEST) == GOOD_PLAN["steps"]
        assert "banana_7" in llm_server.requests[1]["messages"][-1]["content"]

    def test_no_valid_plan_after_the_repair_raises(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json({"steps": [{"action": "Teleport"}]}, {"steps": []})
        with pytest.raises(LlmOutputInvalid):
            LlmPlanner(make_client()).plan(SAFE_REQUEST)

    def test_a_timeout_raises(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.queue(Scripted(content="{}", delay=2.5))
        with pytest.raises(LlmTimeout):
            LlmPlanner(make_client(timeout=1.0)).plan(SAFE_REQUEST)
