"""The gate pipeline: Stages 1 to 4 in the paper's order, for one request.

In: a gate request, the active template index, an analyzer and the gate policy.
Out: `GateResult`: the hazard report, the binding, the decision and, on authorize, the contract,
with the time each stage took.
Fails closed: an analyzer that raises becomes a report with one critical unknown ("hazard
analysis unavailable"), so the gate defers; a template that does not compile turns an authorize
into a defer (extend_library) naming the broken template. Nothing here can produce `authorize`
except the gate's R4 with a compiled contract.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from typing import Protocol

from pydantic import BaseModel, ConfigDict

from app.domain.binding import BindingResult, TemplateIndex, bind
from app.domain.contracts import Contract, compile_contract
from app.domain.errors import FormulaError
from app.domain.gate import (
    DEFAULT_POLICY,
    Decision,
    DeferKind,
    GateDecision,
    GatePolicy,
    Rule,
    decide,
)
from app.domain.models import GateRequest, HazardReport, HazardTemplate, UnknownFact


class Analyzer(Protocol):
    """Stage 1: anything that fills the Hazard Analysis Matrix for a request."""

    name: str

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport: ...


class GateResult(BaseModel):
    model_config = ConfigDict(frozen=True)

    report: HazardReport
    binding: BindingResult
    decision: GateDecision
    contract: Contract | None
    timings_ms: dict[str, float]


def run_gate(
    request: GateRequest,
    *,
    templates: TemplateIndex,
    analyzer: Analyzer,
    policy: GatePolicy = DEFAULT_POLICY,
    clock: Callable[[], float] = time.perf_counter,
) -> GateResult:
    """Decide one request: analyze, bind, decide, and compile the contract on authorize.

    Args:
        request: the task context and robot capabilities.
        templates: the active Hazard Template Library.
        analyzer: Stage 1.
        policy: the gate's parameters.
        clock: a monotonic clock in seconds (injectable for tests).

    Returns:
        The full result of Stages 1 to 4.
    """
    timings: dict[str, float] = {}
    started = clock()
    report = _analyze_or_fail_closed(analyzer, request, templates)
    timings["analysis"] = (clock() - started) * 1000

    started = clock()
    binding = bind(report, templates)
    timings["binding"] = (clock() - started) * 1000

    started = clock()
    decision = decide(
        [h.proposal for h in binding.bound],
        [h.proposal for h in binding.unbound],
        report.unknowns,
        policy,
    )
    timings["decision"] = (clock() - started) * 1000

    contract: Contract | None = None
    if decision.decision is Decision.AUTHORIZE:
        started = clock()
        try:
            contract = compile_contract(binding.bound, templates.always)
        except FormulaError as error:
            decision = GateDecision(
                decision=Decision.DEFER,
                rule=Rule.R2,
                defer_kind=DeferKind.EXTEND_LIBRARY,
                trigger_hazards=tuple(h.proposal for h in binding.bound),
                reason=f"a matched template does not compile, so no contract: {error.detail}",
            )
        timings["contract"] = (clock() - started) * 1000
    timings["total"] = sum(timings.values())
    return GateResult(
        report=report, binding=binding, decision=decision, contract=contract, timings_ms=timings
    )


def _analyze_or_fail_closed(analyzer: Analyzer, request: GateRequest,
                            templates: TemplateIndex) -> HazardReport:
    try:
        return analyzer.analyze(request, templates.templates)
    except Exception as error:
        return HazardReport(
            unknowns=(
                UnknownFact(
                    attribute="hazard_analysis",
                    description="hazard analysis unavailable",
                    critical=True,
                    why=f"the {analyzer.name} analyzer failed ({type(error).__name__}); "
                    "without an analysis nothing can be authorized",
                    question="The hazard analysis could not be completed. "
                    "Please try again or describe the task differently.",
                ),
            ),
            analyzer=analyzer.name,
        )
