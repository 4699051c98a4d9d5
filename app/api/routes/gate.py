"""POST /gate and the audit trail: a command in, a decision with its reasons out."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Body

from app.api.deps import ServicesDep
from app.api.schemas import GateResponse, gate_response
from app.domain.models import GateRequest
from app.services import gate

router = APIRouter(tags=["gate"])


@router.post("/gate", response_model=GateResponse)
def post_gate(request: GateRequest, services: ServicesDep) -> GateResponse:
    """Decide a command: authorize (with a contract), defer (with a question) or reject."""
    return gate_response(gate.decide(services, request))


@router.get("/gate/{request_id}")
def get_gate(request_id: str, services: ServicesDep) -> dict[str, Any]:
    """The audit record of one decided request, with the decisions that followed it."""
    return gate.audit_record(services, request_id)


@router.post("/gate/{request_id}/answers", response_model=GateResponse)
def post_answers(
    request_id: str,
    services: ServicesDep,
    answers: dict[str, Any] = Body(  # noqa: B008 - FastAPI's way to declare a body
        ..., examples=[{"age_group": "adult"}, {"contents": "water"}]
    ),
) -> GateResponse:
    """Answer the clarifying question; the pipeline runs again and links to the original."""
    return gate_response(gate.answer(services, request_id, answers))
