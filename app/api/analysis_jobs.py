"""The worker-process half of the deciding routes: Stages 1-5 and their answers' JSON.

Each job is `job(deciders, *args)` with the worker's `Deciders` (see
`app/services/analysis_pool.py`); the routes run them with `pool.run(job, ...)`, so the
analysis, the audit write and the answer's encoding all happen off the event loop. A job returns
the answer's JSON text plus what the app's own metrics count (the worker's metrics are never
read), and raises SafeGate errors as the routes would (they pickle whole).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from app.api.schemas import gate_response
from app.api.verify_schemas import VerifyRequest, verify_response
from app.domain.gate import Decision, Rule
from app.domain.models import GateRequest
from app.metrics import Metrics
from app.services import Deciders, verification
from app.services.gate import Decided


@dataclass(frozen=True)
class GateAnswer:
    """A decision's answer (GateResponse JSON) and what the metrics count of it."""

    body: str
    decision: Decision
    rule: Rule
    timings_ms: dict[str, float]
    record_id: str = ""
    """The audit record's id (answered in `X-Gate-Request-ID` too)."""

    def count(self, metrics: Metrics) -> None:
        metrics.record_decision(self.decision, self.rule, self.timings_ms)


@dataclass(frozen=True)
class VerifyAnswer:
    """A verification's answer (VerifyResponse JSON) and its outcome for the metrics."""

    body: str
    outcome: str

    def count(self, metrics: Metrics) -> None:
        metrics.verifications.labels(self.outcome).inc()


def _answer(decided: Decided) -> GateAnswer:
    decision = decided.result.decision
    return GateAnswer(body=gate_response(decided).model_dump_json(),
                      decision=decision.decision, rule=decision.rule,
                      timings_ms=decided.result.timings_ms, record_id=decided.request_id)


def decide(deciders: Deciders, request: GateRequest, with_reference_plan: bool = False
           ) -> GateAnswer:
    """POST /gate: Stages 1-4 and the audit record (and, asked for, the reference plan)."""
    return _answer(deciders.gate.decide(request, with_reference_plan=with_reference_plan))


def answer(deciders: Deciders, request_id: str, answers: dict[str, Any]) -> GateAnswer:
    """POST /gate/{id}/answers: the answers folded in, decided again."""
    return _answer(deciders.gate.answer(request_id, answers))


def reevaluate_request(deciders: Deciders, request_id: str) -> GateAnswer:
    """POST /gate/{id}/reevaluate: a waiting request decided again with today's library."""
    return _answer(deciders.extensions.reevaluate_request(request_id))


def reevaluate_class(deciders: Deciders, hazard_class: str) -> tuple[str, list[GateAnswer]]:
    """POST /extensions/reevaluate: every request waiting on a class decided again.

    Returns:
        The response's JSON text, and each new decision for the metrics.
    """
    results = [(old, _answer(decided))
               for old, decided in deciders.extensions.reevaluate_class(hazard_class)]
    items = ",".join(
        f'{{"reevaluated_request_id":{json.dumps(old)},"decision":{answered.body}}}'
        for old, answered in results)
    body = (f'{{"hazard_class":{json.dumps(hazard_class)},"count":{len(results)},'
            f'"results":[{items}]}}')
    return body, [answered for _, answered in results]


def verify(deciders: Deciders, request: VerifyRequest) -> VerifyAnswer:
    """POST /verify: Stage 5, with the contract's attempt budget and audit trail."""
    verified = deciders.verification.verify(
        request.plan,
        contract_id=request.contract_id,
        contract=None if request.contract is None else request.contract.to_domain(),
        initial_state=request.initial_state,
    )
    return VerifyAnswer(body=verify_response(verified).model_dump_json(),
                        outcome=verification.outcome_of(verified.result))
