"""The Hazard Template Library over HTTP: browse and read templates with their versions."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter

from app.api.deps import ServicesDep
from app.domain.models import Category, TemplateStatus

router = APIRouter(tags=["templates"])


@router.get("/templates")
def list_templates(
    services: ServicesDep,
    category: Category | None = None,
    hazard_class: str | None = None,
    status: TemplateStatus | None = None,
) -> dict[str, Any]:
    """Templates at their current version, filtered by category, hazard class and status."""
    templates = services.repository.list_templates(
        category=category, hazard_class=hazard_class, status=status
    )
    return {
        "count": len(templates),
        "templates": [t.model_dump(mode="json") for t in templates],
    }


@router.get("/templates/{template_id}")
def get_template(template_id: str, services: ServicesDep) -> dict[str, Any]:
    """One template at its current version, with every version kept."""
    history = services.repository.get_template_history(template_id)
    body: dict[str, Any] = history.current.model_dump(mode="json")
    body["versions"] = [v.model_dump(mode="json") for v in history.versions]
    return body
