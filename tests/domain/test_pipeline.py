"""The pipeline fails closed: an analyzer crash or a broken template never authorizes."""

from __future__ import annotations

from app.domain.binding import TemplateIndex
from app.domain.gate import Decision, Rule
from app.domain.models import GateRequest, HazardReport
from app.domain.pipeline import run_gate


class CrashingAnalyzer:
    name = "crashing"

    def analyze(self, request: GateRequest, templates: object = ()) -> HazardReport:
        raise TimeoutError("the model did not answer")


class EmptyAnalyzer:
    name = "empty"

    def analyze(self, request: GateRequest, templates: object = ()) -> HazardReport:
        return HazardReport(analyzer=self.name)


class TestRunGate:
    def test_an_analyzer_crash_defers_with_a_critical_unknown(self) -> None:
        result = run_gate(
            GateRequest(command="bring me the coffee"),
            templates=TemplateIndex(()),
            analyzer=CrashingAnalyzer(),
        )
        assert result.decision.decision is Decision.DEFER
        assert result.decision.rule is Rule.R3
        assert result.report.unknowns[0].description == "hazard analysis unavailable"
        assert result.contract is None

    def test_no_hazards_authorizes_with_an_empty_contract(self) -> None:
        result = run_gate(
            GateRequest(command="wave hello"), templates=TemplateIndex(()), analyzer=EmptyAnalyzer()
        )
        assert result.decision.decision is Decision.AUTHORIZE
        assert result.contract is not None and len(result.contract) == 0
        assert set(result.timings_ms) >= {"analysis", "binding", "decision", "contract", "total"}
