"""POST /verify: Stage 5, a plan checked against its Task Safety Contract before anything moves."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.deps import ServicesDep
from app.api.limits import check_initial_state, check_plan
from app.api.verify_schemas import VerifyRequest, VerifyResponse, verify_response
from app.services import verification

router = APIRouter(tags=["verify"])


@router.post("/verify", response_model=VerifyResponse)
def post_verify(request: VerifyRequest, services: ServicesDep) -> VerifyResponse:
    """Verify a plan for every value of the unknown facts; 200 whether or not it passes.

    A failed verification spends one of the contract's attempts; the last one downgrades the
    gate decision to reject, and later calls are refused (409 AttemptsExhausted).
    """
    check_plan(request.plan, services.settings)
    check_initial_state(request.initial_state, services.settings)
    verified = verification.verify(
        services,
        request.plan,
        contract_id=request.contract_id,
        contract=None if request.contract is None else request.contract.to_domain(),
        initial_state=request.initial_state,
    )
    return verify_response(verified)
