"""GET /contracts/{id}: the Task Safety Contract of an authorized request."""

from __future__ import annotations

from typing import Literal

from fastapi import APIRouter
from fastapi.responses import PlainTextResponse, Response

from app.api.deps import ServicesDep
from app.api.schemas import ContractResponse, contract_response
from app.domain.contracts import planner_constraints
from app.services import gate

router = APIRouter(tags=["contracts"])


@router.get("/contracts/{contract_id}", response_model=ContractResponse)
def get_contract(
    contract_id: str, services: ServicesDep, format: Literal["json", "planner"] = "json"
) -> ContractResponse | Response:
    """The contract as JSON, or (`format=planner`) as plain planning constraints."""
    contract, stored = gate.contract_of(services, contract_id)
    if format == "planner":
        lines = planner_constraints(contract)
        header = "Safety constraints your plan must satisfy:\n"
        return PlainTextResponse(header + "\n".join(f"- {line}" for line in lines) + "\n")
    return contract_response(contract, stored)
