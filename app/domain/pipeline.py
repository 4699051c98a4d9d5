"""The gate pipeline: Stages 1 to 4 in the paper's order, for one request.

In: a gate request, the active template index, an analyzer, the gate policy and a reader (Stage
1's reading of the command into the action model; the analyzer itself when it can read).
Out: `GateResult`: the hazard report, the binding, the decision and, on authorize, the contract
with the task's scope, with the time each stage took.
Fails closed: an analyzer that raises becomes a report with one critical unknown ("hazard
analysis unavailable"), so the gate defers; a template that does not compile turns an authorize
into a defer (extend_library) naming the broken template; a reader that fails turns an
authorize into a defer (clarify), since a contract without the task's scope would let a plan
do anything the conditions do not mention. A caller that passes no reader, with an analyzer
that cannot read, gets a contract without a scope (checked as one stored before scopes).
Nothing here can produce `authorize` except the gate's R4 with a compiled contract.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Protocol, runtime_checkable

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
from app.domain.scope import TaskScope, task_scope

if TYPE_CHECKING:
    from app.domain.analysis import Understanding


class Analyzer(Protocol):
    """Stage 1: anything that fills the Hazard Analysis Matrix for a request."""

    name: str

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport: ...


@runtime_checkable
class Reader(Protocol):
    """Stage 1's reading alone: the command as steps of the action model (the task's scope)."""

    def understand(self, request: GateRequest) -> Understanding: ...


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
    reader: Reader | None = None,
) -> GateResult:
    """Decide one request: analyze, bind, decide, and compile the contract on authorize.

    Args:
        request: the task context and robot capabilities.
        templates: the active Hazard Template Library.
        analyzer: Stage 1.
        policy: the gate's parameters.
        clock: a monotonic clock in seconds (injectable for tests).
        reader: reads the command into the task's scope on authorize; default the analyzer
            when it can read (the symbolic one). With no reader at all the contract has no
            scope (as one stored before scopes); a reader that fails defers the request.

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
        entities_missing=[h.proposal for h in binding.unbound if h.entities_missing],
    )
    timings["decision"] = (clock() - started) * 1000

    contract: Contract | None = None
    if decision.decision is Decision.AUTHORIZE:
        started = clock()
        if reader is None and isinstance(analyzer, Reader):
            reader = analyzer
        scope = None if reader is None else _scope_or_none(reader, request)
        try:
            if reader is not None and scope is None:
                decision = _unscoped(decision)
            else:
                contract = compile_contract(binding.bound, templates.always, scope)
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


def _scope_or_none(reader: Reader, request: GateRequest) -> TaskScope | None:
    """The task's scope, or None when the reader fails (never raises)."""
    try:
        return task_scope(reader.understand(request), request)
    except Exception:
        return None


def _unscoped(decision: GateDecision) -> GateDecision:
    """An authorize that cannot be bounded by the task's scope defers instead."""
    return GateDecision(
        decision=Decision.DEFER,
        rule=Rule.R3,
        defer_kind=DeferKind.CLARIFY,
        trigger_hazards=decision.trigger_hazards,
        question="I could not work out which steps this task needs. "
        "Please describe the task step by step.",
        reason="the command could not be read into the task's scope, so no contract",
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
