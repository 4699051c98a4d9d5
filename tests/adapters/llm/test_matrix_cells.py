"""The twelve cells (3 levels x 4 categories) answered explicitly: an open cell is repaired, a
cell still open after the repair round is "not understood" and defers, never authorizes."""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer
from app.adapters.llm.analyzer import COMPREHENSION
from app.adapters.llm.cells import cell_problems, only_cells_missing, reason_words
from app.adapters.llm.schemas import LevelAnswer
from app.domain.binding import TemplateIndex
from app.domain.gate import Decision, Rule
from app.domain.pipeline import GateResult, run_gate
from tests.adapters.llm.answers import SAFE_REQUEST, harmless_levels, with_cells
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer
from tests.conftest import seed_library

ClientFactory = Callable[..., LitellmClient]


def _open_cell(level: dict[str, Any], category: str = "psychological") -> dict[str, Any]:
    """The level answered, but for one category it says nothing about."""
    answered = with_cells(level)
    return {**answered, "none_because": {k: v for k, v in answered["none_because"].items()
                                         if k != category}}


def _send(server: ScriptedServer, *answers: dict[str, Any]) -> None:
    # Queued as written: the fixture's completion of open cells must not hide them.
    server.queue(*(Scripted(content=json.dumps(a)) for a in answers))


def _gate(client: LitellmClient, **options: Any) -> GateResult:
    return run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                    analyzer=LlmAnalyzer(client, **options))


class TestCellProblems:
    @pytest.mark.parametrize("reason", ["none", "None.", "n/a", "no hazard", "none, because",
                                        "none: safe"])
    def test_a_none_without_a_reason_leaves_the_cell_open(self, reason: str) -> None:
        answer = LevelAnswer.model_validate(with_cells({"hazards": [], "unknowns": []}))
        answer = answer.model_copy(update={"none_because": {**answer.none_because,
                                                            "operational": reason}})
        problems = cell_problems(answer, "task")
        assert len(problems) == 1 and "task/operational" in problems[0]
        assert only_cells_missing(problems)

    @pytest.mark.parametrize("reason", ["none, because nobody is in the room",
                                        "No hazard: the robot can carry a book",
                                        "nothing is left switched on"])
    def test_a_none_with_its_reason_answers_the_cell(self, reason: str) -> None:
        assert reason_words(reason) >= 2

    def test_a_hazard_of_the_category_answers_its_cell(self) -> None:
        answer = LevelAnswer.model_validate(
            {**harmless_levels()[0], "none_because": {
                "psychological": "none, because nobody is near",
                "operational": "none, because the robot can do it",
                "consequential": "none, because nothing is left behind"}})
        assert cell_problems(answer, "task") == []

    def test_other_problems_are_not_only_cells(self) -> None:
        assert not only_cells_missing([])
        assert not only_cells_missing(["matrix cell task/physical ...", "hazards[0].hazard_class"])


class TestOpenCellsOverHttp:
    def test_a_missing_cell_is_sent_back_and_repaired(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        task, deployment, user = harmless_levels()
        _send(llm_server, _open_cell(task), with_cells(task), with_cells(deployment),
              with_cells(user))
        result = _gate(make_client())
        repair = llm_server.requests[1]["messages"][-1]["content"]
        assert "matrix cell task/psychological has no hazard and no none_because" in repair
        assert len(llm_server.requests) == 4
        assert result.decision.decision is Decision.AUTHORIZE

    def test_a_cell_still_missing_after_the_repair_defers_as_not_understood(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        task, deployment, _ = harmless_levels()
        _send(llm_server, with_cells(task), _open_cell(deployment, "consequential"),
              _open_cell(deployment, "consequential"))
        result = _gate(make_client())
        assert (result.decision.decision, result.decision.rule) == (Decision.DEFER, Rule.R3)
        assert result.report.proposals == ()
        assert [(u.attribute, u.critical) for u in result.report.unknowns] == [
            (COMPREHENSION, True)]
        assert "unanswered" in result.report.unknowns[0].description
        assert not llm_server.script and len(llm_server.requests) == 3  # no third level asked

    def test_a_bare_none_is_not_an_answer(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        task = with_cells(harmless_levels()[0])
        bare = {**task, "none_because": {k: "none" for k in task["none_because"]}}
        _send(llm_server, bare, bare)
        result = _gate(make_client())
        assert result.decision.decision is Decision.DEFER
        assert result.report.unknowns[0].attribute == COMPREHENSION

    def test_a_batched_answer_is_held_to_all_twelve_cells(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        task, deployment, user = harmless_levels()
        open_user = {"task": with_cells(task), "deployment": with_cells(deployment),
                     "user": _open_cell(user, "operational")}
        complete = {"task": with_cells(task), "deployment": with_cells(deployment),
                    "user": with_cells(user)}
        _send(llm_server, open_user, complete)
        assert _gate(make_client(), batch_levels=True).decision.decision is Decision.AUTHORIZE
        assert "matrix cell user/operational" in llm_server.requests[1]["messages"][-1]["content"]

        _send(llm_server, open_user, open_user)
        result = _gate(make_client(), batch_levels=True)
        assert result.decision.decision is Decision.DEFER
        assert result.report.unknowns[0].attribute == COMPREHENSION
