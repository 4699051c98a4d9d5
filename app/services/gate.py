"""The gate use case: decide a request, answer its question, re-evaluate it; keep the audit trail.

In: a validated `GateRequest` (or answers to an earlier one). Out: `Decided`: the stored audit
record plus the in-memory pipeline result the response is built from.
The analyzer reads the command canonicalized (`text_hygiene.for_analysis`: look-alike and
invisible characters read as a person reads them); the audit trail keeps it as sent.
Every decision is written (with its contract, if any) before it is returned; a failed write raises
`Unavailable` and the caller gets 503, never an unrecorded decision.
Asked for one, an authorized decision also gets a reference plan (`app.domain.planning`): a plan
for the command that Stage 5 proves keeps the contract, or None with the reason.
"""

from __future__ import annotations

import uuid
from dataclasses import dataclass
from typing import Any

from pydantic import ValidationError

from app.domain.analysis import apply_answers
from app.domain.contracts import Contract
from app.domain.errors import InvalidInput, SafeGateError
from app.domain.gate import Decision
from app.domain.models import GateRequest
from app.domain.pipeline import GateResult, run_gate
from app.domain.planning import ReferencePlan, reference_plan
from app.services.container import Services
from app.services.text_hygiene import for_analysis
from app.store.records import ContractRecord, GateRecord


@dataclass(frozen=True)
class Decided:
    record: GateRecord
    result: GateResult
    reference: ReferencePlan | None = None
    """Only when asked for: the proved plan, or None with the reason."""


def decide(
    services: Services, request: GateRequest, *, parent_request_id: str | None = None,
    with_reference_plan: bool = False,
) -> Decided:
    """Run Stages 1-4 on a request and record it (and its contract) in the audit trail; with
    `with_reference_plan`, plan an authorized task and prove the plan (Stage 5)."""
    readable = for_analysis(request)
    result = run_gate(
        readable,
        templates=services.templates.index(),
        analyzer=services.analyzer,
        policy=services.policy,
        reader=services.reader,
    )
    decision = result.decision
    request_id = uuid.uuid4().hex
    contract = None
    if result.contract is not None and decision.decision is Decision.AUTHORIZE:
        contract = ContractRecord(
            id=uuid.uuid4().hex,
            request_id=request_id,
            contract=result.contract.model_dump(mode="json"),
            template_versions=result.contract.template_versions,
            max_attempts=services.settings.max_verify_attempts,
        )
    record, _ = services.repository.save_gate_decision(
        GateRecord(
            id=request_id,
            request=request,
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
            parent_request_id=parent_request_id,
        ),
        contract,
    )
    services.metrics.record_decision(record.decision, record.rule, result.timings_ms)
    reference = _reference(services, readable, result) if with_reference_plan else None
    return Decided(record=record, result=result, reference=reference)


def _reference(services: Services, request: GateRequest, result: GateResult) -> ReferencePlan:
    if result.contract is None or result.decision.decision is not Decision.AUTHORIZE:
        return ReferencePlan(None, "no reference plan: the task was not authorized")
    try:
        return reference_plan(request, result.contract,
                              timeout_ms=services.settings.solver_timeout_ms,
                              reader=services.reader)
    except SafeGateError as error:  # fail closed: no plan rather than an unproved one
        return ReferencePlan(None, f"no reference plan: {error.detail}")
    except Exception as error:  # the reader may fail like any Stage 1 reading: the decision stands
        return ReferencePlan(None, f"no reference plan: planning failed ({type(error).__name__})")


def answer(services: Services, request_id: str, answers: dict[str, Any]) -> Decided:
    """Fold answers to a clarifying question into the request and decide it again."""
    if not answers:
        raise InvalidInput("give at least one answer", field="body")
    original = services.repository.get_gate_record(request_id)
    unknowns = original.hazard_report.unknowns if original.hazard_report else ()
    try:
        updated = apply_answers(original.request, answers, unknowns)
    except ValidationError as error:
        raise _invalid_answer(error, answers) from error
    return decide(services, updated, parent_request_id=request_id)


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


def reevaluate(services: Services, request_id: str) -> Decided:
    """Decide a stored request again against the current library (after a curator's change)."""
    original = services.repository.get_gate_record(request_id)
    return decide(services, original.request, parent_request_id=request_id)


def audit_record(services: Services, request_id: str) -> dict[str, Any]:
    """A stored decision with the decisions that followed it (answers, re-evaluations)."""
    record = services.repository.get_gate_record(request_id)
    children = services.repository.list_child_records(request_id)
    body = record.model_dump(mode="json", by_alias=True)
    body["request_id"] = record.id
    body["followed_by"] = [child.id for child in children]
    return body


def contract_of(services: Services, contract_id: str) -> tuple[Contract, ContractRecord]:
    """A stored contract, parsed back into the domain model."""
    stored = services.repository.get_contract(contract_id)
    return Contract.model_validate(stored.contract), stored
