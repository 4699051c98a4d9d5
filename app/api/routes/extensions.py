"""The library-extension loop over HTTP: what waits for a template, and deciding it again.

`GET /extensions/pending` lists requests whose latest decision defers with `extend_library`,
grouped by the hazard class they wait for. Once an active template covers a class, a curator
re-decides them one by one (`POST /gate/{id}/reevaluate`) or all at once
(`POST /extensions/reevaluate {"hazard_class": ...}`); re-evaluation runs the normal pipeline
(in the analysis pool, off the event loop) and each new decision is linked to the one it follows.
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Response
from pydantic import BaseModel, ConfigDict, Field

from app.api import analysis_jobs
from app.api.deps import CuratorKey, ExtensionsDep, MetricsDep, PoolDep, ReadAccess
from app.api.observability import GATE_REQUEST_ID_HEADER
from app.api.openapi import problem_responses
from app.api.read_schemas import PendingExtensionsResponse
from app.api.schemas import GateResponse
from app.services.extensions import PendingClass, WaitingRequest

router = APIRouter(tags=["extensions"])


class ReevaluateClassRequest(BaseModel):
    """The hazard class whose waiting requests to decide again."""

    model_config = ConfigDict(json_schema_extra={"examples": [{"hazard_class": "thermal_burn"}]})

    hazard_class: str = Field(min_length=1, max_length=120, examples=["sharp_laceration"])


class ReevaluatedRequest(BaseModel):
    reevaluated_request_id: str
    decision: GateResponse


class ReevaluateClassResponse(BaseModel):
    hazard_class: str
    count: int
    results: list[ReevaluatedRequest]


def _waiting(waiting: WaitingRequest, hazard_class: str) -> dict[str, Any]:
    record = waiting.record
    return {
        "request_id": record.id,
        "command": record.request.command,
        "created_at": record.created_at.isoformat() if record.created_at else None,
        "parent_request_id": record.parent_request_id,
        "hazards": [
            {"hazard_class": h.hazard_class, "mechanism": h.mechanism,
             "severity": h.severity.value, "entities": dict(h.entities)}
            for h in waiting.unbound
            if h.hazard_class == hazard_class
        ],
        "also_waiting_for": sorted(waiting.hazard_classes - {hazard_class}),
    }


def _group(group: PendingClass) -> dict[str, Any]:
    return {
        "hazard_class": group.hazard_class,
        "count": len(group.requests),
        "covered": bool(group.covered_by),
        "covered_by": list(group.covered_by),
        "requests": [_waiting(w, group.hazard_class) for w in group.requests],
        "suggested_template": group.suggested_template,
    }


@router.get("/extensions/pending", response_model=PendingExtensionsResponse,
            summary="List requests waiting for the library", responses=problem_responses(503))
def pending_extensions(extensions: ExtensionsDep, _: ReadAccess) -> PendingExtensionsResponse:
    """Requests waiting for a library extension, grouped by hazard class."""
    groups = extensions.pending_by_class()
    request_ids = {w.record.id for g in groups for w in g.requests}
    return PendingExtensionsResponse.model_validate(
        {"count": len(request_ids), "classes": [_group(g) for g in groups]})


@router.post("/extensions/reevaluate", response_model=ReevaluateClassResponse,
             summary="Decide a hazard class's waiting requests again",
             responses=problem_responses(
                 403, (409, "No active template covers the class yet."), 503))
async def reevaluate_class(
    body: ReevaluateClassRequest, metrics: MetricsDep, pool: PoolDep, _: CuratorKey
) -> Response:
    """Decide again every request waiting on a class that an active template now covers."""
    text, answers = await pool.run(analysis_jobs.reevaluate_class, body.hazard_class)
    for answer in answers:
        answer.count(metrics)
    return Response(text, media_type="application/json")


@router.post("/gate/{request_id}/reevaluate", response_model=GateResponse,
             summary="Decide a waiting request again", tags=["gate"],
             responses=problem_responses(
                 403, 404, (409, "The request is not waiting for a library extension."), 503))
async def reevaluate_request(
    request_id: str, metrics: MetricsDep, pool: PoolDep, _: CuratorKey
) -> Response:
    """Decide a waiting request again with today's library (its chain's latest decision)."""
    answer = await pool.run(analysis_jobs.reevaluate_request, request_id)
    answer.count(metrics)
    return Response(answer.body, media_type="application/json",
                    headers={GATE_REQUEST_ID_HEADER: answer.record_id})
