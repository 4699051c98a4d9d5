"""POST /verify: Stage 5, a plan checked against its Task Safety Contract before anything moves.

The solver runs in the analysis pool (`app/services/analysis_pool.py`), off the event loop, like
the gate's Stages 1-4; a full pool answers 503 with Retry-After.
"""

from __future__ import annotations

from fastapi import APIRouter, Response

from app.api import analysis_jobs
from app.api.deps import MetricsDep, PoolDep
from app.api.openapi import problem_responses
from app.api.verify_schemas import VerifyRequest, VerifyResponse

router = APIRouter(tags=["verify"])


@router.post("/verify", response_model=VerifyResponse, summary="Verify a plan against a contract",
             responses=problem_responses(
                 403, 404, (409, "The contract's verification attempts are used up "
                                 "(AttemptsExhausted): its task is rejected."), 503))
async def post_verify(request: VerifyRequest, metrics: MetricsDep,
                      pool: PoolDep) -> Response:
    """Verify a plan for every value of the unknown facts; 200 whether or not it passes.

    A failed verification spends one of the contract's attempts; the last one downgrades the
    gate decision to reject, and later calls are refused (409 AttemptsExhausted).
    """
    answer = await pool.run(analysis_jobs.verify, request)
    answer.count(metrics)
    return Response(answer.body, media_type="application/json")
