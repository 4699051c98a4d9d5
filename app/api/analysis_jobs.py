"""The worker-process half of the deciding routes: Stages 1-5 and their answers' JSON.

Each job is `job(services, *args)` with the worker's `Services` (see
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
from app.services import Services, extensions, gate, verification
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
    return GateAnswer(body=gate_response(decided).model_dump_json(),
                      decision=decided.record.decision, rule=decided.record.rule,
                      timings_ms=decided.result.timings_ms, record_id=str(decided.record.id))


def decide(services: Services, request: GateRequest, with_reference_plan: bool = False
           ) -> GateAnswer:
    """POST /gate: Stages 1-4 and the audit record (and, asked for, the reference plan)."""
    return _answer(gate.decide(services, request, with_reference_plan=with_reference_plan))


def answer(services: Services, request_id: str, answers: dict[str, Any]) -> GateAnswer:
    """POST /gate/{id}/answers: the answers folded in, decided again."""
    return _answer(gate.answer(services, request_id, answers))


def reevaluate_request(services: Services, request_id: str) -> GateAnswer:
    """POST /gate/{id}/reevaluate: a waiting request decided again with today's library."""
    return _answer(extensions.reevaluate_request(services, request_id))


def reevaluate_class(services: Services, hazard_class: str) -> tuple[str, list[GateAnswer]]:
    """POST /extensions/reevaluate: every request waiting on a class decided again.

    Returns:
        The response's JSON text, and each new decision for the metrics.
    """
    results = [(old, _answer(decided))
               for old, decided in extensions.reevaluate_class(services, hazard_class)]
    items = ",".join(
        f'{{"reevaluated_request_id":{json.dumps(old)},"decision":{answered.body}}}'
        for old, answered in results)
    body = (f'{{"hazard_class":{json.dumps(hazard_class)},"count":{len(results)},'
            f'"results":[{items}]}}')
    return body, [answered for _, answered in results]


def verify(services: Services, request: VerifyRequest) -> VerifyAnswer:
    """POST /verify: Stage 5, with the contract's attempt budget and audit trail."""
    verified = verification.verify(
        services,
        request.plan,
        contract_id=request.contract_id,
        contract=None if request.contract is None else request.contract.to_domain(),
        initial_state=request.initial_state,
    )
    return VerifyAnswer(body=verify_response(verified).model_dump_json(),
                        outcome=verification.outcome_of(verified.result))
