"""POST /gate and the audit trail: a command in, a decision with its reasons out."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter

from app.api.deps import ServicesDep
from app.api.schemas import GateResponse, gate_response
from app.domain.models import GateRequest

router = APIRouter(tags=["gate"])


@router.post("/gate", response_model=GateResponse)
def post_gate(request: GateRequest, services: ServicesDep) -> GateResponse:
    """Decide a command: authorize (with a contract), defer (with a question) or reject."""
    return gate_response(services.decide(request))


@router.get("/gate/{request_id}")
def get_gate(request_id: str, services: ServicesDep) -> dict[str, Any]:
    """The audit record of one decided request."""
    return services.gate_record(request_id)
