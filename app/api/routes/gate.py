"""POST /gate and the audit trail: a command in, a decision with its reasons out.

The decide routes run their work (the pipeline, the audit write, the response's JSON) right in the
event loop. It is CPU-bound Python, so a worker thread only adds a GIL hand-over: measured with
`bench/perf/gate_http.py`, handing even just the audit write to a thread cost a third of the
throughput. They answer with the JSON `GateResponse` already encoded, so FastAPI does not
validate and serialize it a second time.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Body, Response

from app.api.deps import ServicesDep
from app.api.limits import check_gate_request
from app.api.observability import GATE_REQUEST_ID_HEADER
from app.api.schemas import GateResponse, gate_response
from app.domain.models import GateRequest
from app.services import Services, gate
from app.services.gate import Decided

router = APIRouter(tags=["gate"])


def _json(decided: Decided) -> Response:
    # The audit record's id also in a header, so the access log line links the HTTP request id
    # to the decision it produced (app/api/observability.py).
    return Response(gate_response(decided).model_dump_json(), media_type="application/json",
                    headers={GATE_REQUEST_ID_HEADER: str(decided.record.id)})


def _decide(services: Services, request: GateRequest) -> Response:
    check_gate_request(request, services.settings)
    return _json(gate.decide(services, request))


def _answer(services: Services, request_id: str, answers: dict[str, Any]) -> Response:
    return _json(gate.answer(services, request_id, answers))


@router.post("/gate", response_model=GateResponse)
async def post_gate(request: GateRequest, services: ServicesDep) -> Response:
    """Decide a command: authorize (with a contract), defer (with a question) or reject."""
    return _decide(services, request)


@router.get("/gate/{request_id}")
def get_gate(request_id: str, services: ServicesDep) -> dict[str, Any]:
    """The audit record of one decided request, with the decisions that followed it."""
    return gate.audit_record(services, request_id)


@router.post("/gate/{request_id}/answers", response_model=GateResponse)
async def post_answers(
    request_id: str,
    services: ServicesDep,
    answers: dict[str, Any] = Body(  # noqa: B008 - FastAPI's way to declare a body
        ..., examples=[{"age_group": "adult"}, {"contents": "water"}]
    ),
) -> Response:
    """Answer the clarifying question; the pipeline runs again and links to the original."""
    return _answer(services, request_id, answers)
