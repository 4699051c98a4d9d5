"""GET /contracts/{id}: the Task Safety Contract of an authorized request."""

from __future__ import annotations

from typing import Literal

from fastapi import APIRouter
from fastapi.responses import PlainTextResponse, Response

from app.api.deps import AuditTrailDep
from app.api.openapi import problem_responses
from app.api.schemas import ContractResponse, contract_response
from app.domain.contracts import planner_constraints

router = APIRouter(tags=["contracts"])


@router.get(
    "/contracts/{contract_id}", response_model=ContractResponse,
    summary="Read a Task Safety Contract",
    responses={200: {"content": {"text/plain": {"schema": {"type": "string"}, "example": (
        "Safety constraints your plan must satisfy:\n- Never throw anything at a person.\n")}},
        "description": "The contract: JSON, or plain text with `format=planner`."},
        **problem_responses(404, 503)})
def get_contract(
    contract_id: str, audit_trail: AuditTrailDep, format: Literal["json", "planner"] = "json"
) -> ContractResponse | Response:
    """The contract as JSON, or (`format=planner`) as plain planning constraints."""
    contract, stored = audit_trail.contract(contract_id)
    if format == "planner":
        lines = planner_constraints(contract)
        header = "Safety constraints your plan must satisfy:\n"
        return PlainTextResponse(header + "\n".join(f"- {line}" for line in lines) + "\n")
    return contract_response(contract, stored)
