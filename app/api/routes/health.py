"""Liveness and readiness."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.deps import ReadinessDep
from app.api.openapi import problem_responses

router = APIRouter(tags=["health"])


@router.get("/healthz", summary="Liveness: the process is up")
def healthz() -> dict[str, str]:
    """The process is up."""
    return {"status": "ok"}


@router.get("/readyz", summary="Readiness: database and library",
            responses=problem_responses(
                (503, "The database does not answer or the library is not loaded.")))
def readyz(readiness: ReadinessDep) -> dict[str, object]:
    """The database answers and the template library is loaded (503 otherwise)."""
    return {"status": "ready", "templates": readiness.check()}
