"""The gate use case: decide a request, answer its question, re-evaluate it; keep the audit trail.

In: a validated `GateRequest` (or answers to an earlier one). Out: `Decided`, the one value both
the audit record and the answer are made from: the pipeline's result with the ids the service
gave the record and its contract (so the answer never mixes a stored record with a result).
The analyzer reads the command canonicalized (`text_hygiene.for_analysis`: look-alike and
invisible characters read as a person reads them); the audit trail keeps it as sent.
Every decision is written (with its contract, if any) before it is returned; a failed write raises
`Unavailable` and the caller gets 503, never an unrecorded decision.
Asked for one, an authorized decision also gets a reference plan (`app.domain.planning`): a plan
for the command that Stage 5 proves keeps the contract, or None with the reason. It is planned
before the write, so the audit record keeps what was handed out (`reference_plan`: the plan,
its goal and the reason, or no plan and why), in the same write as the decision.
"""

from __future__ import annotations

import time
import uuid
from dataclasses import dataclass, replace
from typing import Any

from pydantic import ValidationError

from app.adapters.tracing import stages
from app.domain.analysis import apply_answers
from app.domain.errors import InvalidInput, SafeGateError
from app.domain.gate import Decision, GatePolicy
from app.domain.models import GateRequest
from app.domain.pipeline import Analyzer, GateResult, Reader, run_gate
from app.domain.planning import ReferencePlan, reference_plan
from app.metrics import Metrics
from app.services.input_limits import MODEL_CAPS, InputLimits
from app.services.template_cache import TemplateCache
from app.services.text_hygiene import for_analysis
from app.store.records import ContractRecord, GateRecord
from app.store.repository import AuditRepository


@dataclass(frozen=True)
class Decided:
    """A decision: the pipeline's result and the ids of its audit record and contract."""

    request: GateRequest
    """As sent (the audit trail keeps it so); the analyzer read it canonicalized."""
    result: GateResult
    request_id: str
    contract_id: str | None
    """Set exactly when the decision authorizes with a contract."""
    parent_request_id: str | None = None
    reference: ReferencePlan | None = None
    """Only when asked for: the proved plan, or None with the reason."""

    def audit_record(self) -> GateRecord:
        """The audit trail's record of this decision."""
        result, decision = self.result, self.result.decision
        return GateRecord(
            id=self.request_id,
            request=self.request,
            hazard_report=result.report,
            decision=decision.decision,
            rule=decision.rule,
            defer_kind=decision.defer_kind,
            question=decision.question,
            triggers=[h.model_dump(mode="json") for h in decision.trigger_hazards]
            + [u.model_dump(mode="json") for u in decision.trigger_unknowns],
            timings=result.timings_ms,
            analyzer=result.report.analyzer,
            template_versions=result.contract.template_versions if result.contract else {},
            contract_id=self.contract_id,
            parent_request_id=self.parent_request_id,
            reference_plan=None if self.reference is None else reference_record(self.reference),
        )

    def contract_record(self, max_attempts: int) -> ContractRecord | None:
        """The contract to store with the decision (None unless it authorizes)."""
        contract = self.result.contract
        if contract is None or self.contract_id is None:
            return None
        return ContractRecord(
            id=self.contract_id, request_id=self.request_id,
            contract=contract.model_dump(mode="json"),
            template_versions=contract.template_versions, max_attempts=max_attempts)


def reference_record(reference: ReferencePlan) -> dict[str, Any]:
    """What the audit trail keeps of a reference plan: the plan handed out (the wire shape),
    the goal it reaches and the reason; or `plan` null and why there was none."""
    return {"plan": None if reference.plan is None else [dict(s) for s in reference.plan],
            "goal": reference.goal, "reason": reference.reason}


class GateService:
    """Stages 1-4 (and on request Stage 5's reference plan) with the audit trail."""

    def __init__(self, *, audit: AuditRepository, templates: TemplateCache, analyzer: Analyzer,
                 reader: Reader | None, policy: GatePolicy, metrics: Metrics,
                 max_verify_attempts: int, solver_timeout_ms: int,
                 limits: InputLimits = MODEL_CAPS) -> None:
        """Args:
            audit: where decisions (and their contracts) are recorded.
            templates: the active templates.
            analyzer: Stage 1.
            reader: reads an authorized command into the task's scope.
            policy: the Decision Gate's parameters.
            metrics: where decisions are counted.
            max_verify_attempts: each new contract's verification budget.
            solver_timeout_ms: Z3's budget per check of a reference plan.
            limits: the sizes a request may have, however it reaches the gate.
        """
        self._limits = limits
        self._audit = audit
        self._templates = templates
        self._analyzer = analyzer
        self._reader = reader
        self._policy = policy
        self._metrics = metrics
        self._max_attempts = max_verify_attempts
        self._timeout_ms = solver_timeout_ms

    def decide(self, request: GateRequest, *, parent_request_id: str | None = None,
               with_reference_plan: bool = False) -> Decided:
        """Run Stages 1-4 on a request and record it (and its contract) in the audit trail;
        with `with_reference_plan`, plan an authorized task and prove the plan (Stage 5)."""
        self._limits.check_gate_request(request)
        readable = for_analysis(request)
        started_ns = time.time_ns()
        result = run_gate(readable, templates=self._templates.index(), analyzer=self._analyzer,
                          policy=self._policy, reader=self._reader)
        authorized = result.contract is not None and (
            result.decision.decision is Decision.AUTHORIZE)
        decided = Decided(request=request, result=result, request_id=uuid.uuid4().hex,
                          contract_id=uuid.uuid4().hex if authorized else None,
                          parent_request_id=parent_request_id)
        if with_reference_plan:  # before the write: the audit record keeps what is handed out
            with stages.stage("safegate.stage5.reference_plan",
                              **{"safegate.gate_request_id": decided.request_id}) as found:
                reference = self._reference(readable, result)
                found["safegate.planned"] = reference.plan is not None
            decided = replace(decided, reference=reference)
        self._audit.save_gate_decision(decided.audit_record(),
                                       decided.contract_record(self._max_attempts))
        self._metrics.record_decision(result.decision.decision, result.decision.rule,
                                      result.timings_ms)
        stages.record_gate(result, started_ns, decided.request_id)
        return decided

    def _reference(self, request: GateRequest, result: GateResult) -> ReferencePlan:
        if result.contract is None or result.decision.decision is not Decision.AUTHORIZE:
            return ReferencePlan(None, "no reference plan: the task was not authorized")
        try:
            return reference_plan(request, result.contract, timeout_ms=self._timeout_ms,
                                  reader=self._reader)
        except SafeGateError as error:  # fail closed: no plan rather than an unproved one
            return ReferencePlan(None, f"no reference plan: {error.detail}")
        except Exception as error:  # the reader may fail like any Stage 1 reading
            return ReferencePlan(
                None, f"no reference plan: planning failed ({type(error).__name__})")

    def answer(self, request_id: str, answers: dict[str, Any]) -> Decided:
        """Fold answers to a clarifying question into the request and decide it again."""
        if not answers:
            raise InvalidInput("give at least one answer", field="body")
        original = self._audit.get_gate_record(request_id)
        unknowns = original.hazard_report.unknowns if original.hazard_report else ()
        try:
            updated = apply_answers(original.request, answers, unknowns)
        except ValidationError as error:
            raise _invalid_answer(error, answers) from error
        return self.decide(updated, parent_request_id=request_id)

    def reevaluate(self, request_id: str) -> Decided:
        """Decide a stored request again against the current library (after a curator's
        change)."""
        original = self._audit.get_gate_record(request_id)
        return self.decide(original.request, parent_request_id=request_id)


def _invalid_answer(error: ValidationError, answers: dict[str, Any]) -> InvalidInput:
    """An answer that makes the request invalid (`{"mass_kg": -1}`, `{"age_group": "elf"}`),
    named by its key in the answers body."""
    first = error.errors()[0]
    where = [str(part) for part in first.get("loc", ())]
    written_as = {"on": "is_on", "temperature": "hot"}
    key = next((k for part in reversed(where)
                for k in (part, written_as.get(part)) if k in answers), None)
    return InvalidInput(f"the answer does not fit: {first.get('msg', 'invalid')}",
                        field=f"body.{key}" if key is not None else "body")
