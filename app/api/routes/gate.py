"""POST /gate and the audit trail: a command in, a decision with its reasons out.

The deciding routes hand their work (Stages 1-4, the audit write, the answer's JSON) to the
analysis pool (`app/services/analysis_pool.py`): worker processes, so the event loop keeps
answering websockets, probes and reads while requests are analysed, however long an analysis
(or an LLM) takes. When the workers and their queue are full, the gate answers 503 with
Retry-After. The answer is the `GateResponse` JSON the worker encoded, so FastAPI does not
validate and serialize it a second time.
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Query, Response

from app.api import analysis_jobs
from app.api.deps import AuditTrailDep, MetricsDep, PoolDep
from app.api.examples import ANSWERS_EXAMPLES, GATE_EXAMPLES
from app.api.observability import GATE_REQUEST_ID_HEADER
from app.api.openapi import problem_responses
from app.api.read_schemas import GateRecordResponse
from app.api.schemas import GateResponse
from app.domain.models import GateRequest

router = APIRouter(tags=["gate"])


def _json(answer: analysis_jobs.GateAnswer, metrics: MetricsDep) -> Response:
    answer.count(metrics)
    # The audit record's id also in a header, so the access log line links the HTTP request id
    # to the decision it produced (app/api/observability.py).
    return Response(answer.body, media_type="application/json",
                    headers={GATE_REQUEST_ID_HEADER: answer.record_id})


@router.post("/gate", response_model=GateResponse, summary="Decide a command",
             responses=problem_responses(403, 503))
async def post_gate(
    request: Annotated[GateRequest, Body(openapi_examples=GATE_EXAMPLES)],
    metrics: MetricsDep,
    pool: PoolDep,
    reference_plan: bool = Query(
        default=False,
        description="On an authorize, also answer a plan for the command that Stage 5 "
        "proves keeps the contract (`reference_plan`), or why there is none "
        "(`reference_plan_reason`).",
    ),
) -> Response:
    """Decide a command: authorize (with a contract), defer (with a question) or reject.

    503 with Retry-After when the analysis workers and their queue are full.
    """
    return _json(await pool.run(analysis_jobs.decide, request, reference_plan), metrics)


@router.get("/gate/{request_id}", response_model=GateRecordResponse,
            summary="Read a decision's audit record", responses=problem_responses(404, 503))
def get_gate(request_id: str, audit_trail: AuditTrailDep) -> GateRecordResponse:
    """The audit record of one decided request, with the decisions that followed it."""
    entry = audit_trail.entry(request_id)
    record = entry.record
    return GateRecordResponse.model_validate({
        **dict(record), "request_id": record.id, "followed_by": list(entry.followed_by)})


@router.post("/gate/{request_id}/answers", response_model=GateResponse,
             summary="Answer the clarifying question",
             responses=problem_responses(403, 404, 503))
async def post_answers(
    request_id: str,
    metrics: MetricsDep,
    pool: PoolDep,
    answers: dict[str, Any] = Body(  # noqa: B008 - FastAPI's way to declare a body
        ..., openapi_examples=ANSWERS_EXAMPLES,
        description="The missing facts, each under the attribute the question names "
                    "(`age_group`, `contents`, `mass_kg`...); at least one.",
        json_schema_extra={"minProperties": 1},
    ),
) -> Response:
    """Answer the clarifying question; the pipeline runs again and links to the original."""
    return _json(await pool.run(analysis_jobs.answer, request_id, answers), metrics)
