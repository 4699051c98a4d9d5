"""Liveness and readiness."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.deps import ReadinessDep
from app.api.openapi import problem_responses
from app.api.read_schemas import HealthResponse, ReadinessResponse

router = APIRouter(tags=["health"])


@router.get("/healthz", response_model=HealthResponse, summary="Liveness: the process is up",
            responses=problem_responses(
                (500, "The process answers but failed unexpectedly (never expected here).")))
def healthz() -> HealthResponse:
    """The process is up."""
    return HealthResponse(status="ok")


@router.get("/readyz", response_model=ReadinessResponse,
            summary="Readiness: database and library",
            responses=problem_responses(
                (503, "The database does not answer or the library is not loaded.")))
def readyz(readiness: ReadinessDep) -> ReadinessResponse:
    """The database answers and the template library is loaded (503 otherwise)."""
    return ReadinessResponse(status="ready", templates=readiness.check())
