"""The ensemble binds the union of two analyzers and fails closed when either fails."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.ensemble import ANALYSIS_UNAVAILABLE, EnsembleAnalyzer
from app.domain.gate import Decision, Rule
from app.domain.models import (
    Category,
    Confidence,
    GateRequest,
    HazardProposal,
    HazardReport,
    Level,
    Preventability,
    Severity,
    UnknownFact,
)
from app.domain.pipeline import run_gate
from tests.adapters.llm.answers import EMPTY_LEVEL, SAFE_REQUEST, hazard
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer
from tests.conftest import seed_library


def _proposal(hazard_class: str, source: str) -> HazardProposal:
    return HazardProposal(level=Level.TASK, category=Category.PHYSICAL, hazard_class=hazard_class,
                          mechanism="m", severity=Severity.HIGH,
                          preventability=Preventability.PREVENTABLE,
                          confidence=Confidence.CERTAIN, source=source)


class FixedAnalyzer:
    def __init__(self, name: str, report: HazardReport) -> None:
        self.name = name
        self._report = report

    def analyze(self, request: GateRequest, templates: object = ()) -> HazardReport:
        return self._report


class BrokenAnalyzer:
    name = "broken"

    def analyze(self, request: GateRequest, templates: object = ()) -> HazardReport:
        raise ConnectionError("down")


SHARED = _proposal("thermal_burn", "a")
LOOSE_END = UnknownFact(attribute="contents", description="contents of mug_1", critical=True,
                        why="w")


class TestEnsembleAnalyzer:
    def test_reports_the_union_without_duplicates(self) -> None:
        first = FixedAnalyzer("a", HazardReport(proposals=(SHARED, _proposal("choking", "a"))))
        second = FixedAnalyzer("b", HazardReport(proposals=(SHARED,), unknowns=(LOOSE_END,)))
        report = EnsembleAnalyzer([first, second]).analyze(GateRequest(command="x"))
        assert [p.hazard_class for p in report.proposals] == ["thermal_burn", "choking"]
        assert report.unknowns == (LOOSE_END,)
        assert report.analyzer == "ensemble(a+b)"

    def test_an_unbound_llm_hazard_keeps_the_symbolic_question(self) -> None:
        asked = LOOSE_END.model_copy(update={"question": "What is in mug_1?"})
        symbolic = FixedAnalyzer("symbolic", HazardReport(unknowns=(asked,)))
        llm = FixedAnalyzer("llm", HazardReport(proposals=(_proposal("laser_glare", "llm"),)))
        result = run_gate(GateRequest(command="x"), templates=TemplateIndex(seed_library()),
                          analyzer=EnsembleAnalyzer([symbolic, llm]))
        assert (result.decision.rule, result.decision.question) == (Rule.R2, "What is in mug_1?")

    @pytest.mark.faults
    def test_a_failing_member_adds_the_critical_unknown(self) -> None:
        first = FixedAnalyzer("a", HazardReport(proposals=(SHARED,)))
        report = EnsembleAnalyzer([first, BrokenAnalyzer()]).analyze(GateRequest(command="x"))
        assert report.proposals == (SHARED,)
        assert [u.description for u in report.unknowns] == [ANALYSIS_UNAVAILABLE]
        assert report.unknowns[0].critical
        assert "broken" in report.unknowns[0].why


class TestSymbolicPlusLlm:
    def test_an_llm_that_sees_nothing_keeps_the_symbolic_hazards(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        request = GateRequest.model_validate({
            **SAFE_REQUEST.model_dump(by_alias=True, exclude_none=True),
            "command": "hand the knife to the child",
            "scene": {"objects": [{"id": "knife_1", "type": "Knife", "room": "kitchen"}],
                      "people": [{"id": "c1", "room": "kitchen",
                                  "properties": {"age_group": "child"}}]},
        })
        symbolic = SymbolicAnalyzer().analyze(request, seed_library())
        assert symbolic.proposals  # the test means something only if symbolic finds hazards
        llm_server.answer_json(EMPTY_LEVEL, EMPTY_LEVEL, EMPTY_LEVEL)
        ensemble = EnsembleAnalyzer([SymbolicAnalyzer(), LlmAnalyzer(make_client())])
        report = ensemble.analyze(request, seed_library())
        assert all(p in report.proposals for p in symbolic.proposals)
        assert all(u in report.unknowns for u in symbolic.unknowns)

    def test_llm_hazards_are_added_to_the_symbolic_ones(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        extra = {"hazards": [hazard("startling", category="psychological",
                                    entities={"person": "p1"})], "unknowns": []}
        llm_server.answer_json(EMPTY_LEVEL, extra, EMPTY_LEVEL)
        ensemble = EnsembleAnalyzer([SymbolicAnalyzer(), LlmAnalyzer(make_client())])
        report = ensemble.analyze(SAFE_REQUEST, seed_library())
        assert "startling" in {p.hazard_class for p in report.proposals}

    @pytest.mark.faults
    def test_an_llm_failure_defers_what_symbolic_alone_authorizes(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        alone = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()),
                         analyzer=SymbolicAnalyzer())
        assert alone.decision.decision is Decision.AUTHORIZE
        llm_server.queue(Scripted(status=503))
        ensemble = EnsembleAnalyzer([SymbolicAnalyzer(), LlmAnalyzer(make_client())])
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(seed_library()), analyzer=ensemble)
        assert result.decision.decision is Decision.DEFER
        assert ANALYSIS_UNAVAILABLE in [u.description for u in result.report.unknowns]
