"""The Hazard Template Library over HTTP: browse, validate, write and (de)activate templates.

Reads and `POST /templates/validate` (which stores nothing) follow `ReadAccess`; every write needs
a curator (or admin) key, whatever the auth mode. A write answers the stored template with the
validation's `warnings` (e.g. a hazard class already covered); an invalid document is a 422
problem+json whose `errors` point at each field and, in a formula, the line and column.
"""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter, Body, Path, Query, status
from pydantic import BaseModel, Field

from app.api.deps import CatalogDep, CurationDep, CuratorKey, ReadAccess
from app.api.openapi import problem_responses
from app.api.read_schemas import (
    CuratedTemplateResponse,
    TemplateHistoryResponse,
    TemplateResponse,
    TemplateValidationResponse,
)
from app.domain.models import Category, HazardTemplate, TemplateStatus
from app.services.curation import Curated
from app.services.template_listing import SortOrder, TemplateSortKey
from app.store.records import ApiKeyRecord

router = APIRouter(tags=["templates"])
# Versions count from 1; past a 64-bit integer the database cannot even compare one (a 500
# before this bound), so a 422 names the parameter instead.
MAX_VERSION = 2**31 - 1
MAX_PAGE = 500
MAX_OFFSET = 2**31 - 1  # like a version: bounded so a 422 names it, never a silent overflow

_DOCUMENT = Body(  # FastAPI's way to take the raw JSON body, so our validator reports on it
    ...,
    examples=[{
        "id": "thermal.iron_left_on_near_child", "name": "Hot iron near a child",
        "category": "physical", "hazard_class": "thermal_burn",
        "description": "A hot iron burns a child who touches it.", "severity": "high",
        "preventability": "preventable",
        "variables": [{"name": "obj", "type": "object"}],
        "guards": [{"id": "no_hot_handover", "action": "HandOver",
                    "formula": "@object != $obj or not hot($obj)",
                    "description": "Never hand over the iron while it is hot."}],
    }],
)


def _author(key: ApiKeyRecord) -> str:
    return key.name or f"key {key.id}"


def _curated(curated: Curated) -> CuratedTemplateResponse:
    return CuratedTemplateResponse.model_validate({
        **curated.template.model_dump(mode="json"),
        "warnings": [warning.as_dict() for warning in curated.warnings]})


def _template(template: HazardTemplate) -> TemplateResponse:
    return TemplateResponse.model_validate(template.model_dump(mode="json"))


class TemplateListResponse(BaseModel):
    """One page of the library (every match when no `limit` is given)."""

    count: int = Field(description="How many templates this answer holds.")
    total: int = Field(description="How many templates match, on every page together.")
    offset: int = Field(description="How many matches were skipped before this page.")
    limit: int | None = Field(description="The page size asked for; null when not paging.")
    templates: list[TemplateResponse] = Field(
        description="Templates at their current version, as `GET /templates/{template_id}` "
                    "answers them without `versions`.")


@router.get("/templates", summary="List, search, sort and page templates",
            response_model=TemplateListResponse, responses=problem_responses(503))
def list_templates(
    catalog: CatalogDep,
    _: ReadAccess,
    category: Category | None = None,
    hazard_class: str | None = None,
    status: TemplateStatus | None = None,
    q: Annotated[str | None, Query(
        description="Search words: a template matches when its id, name, hazard class or "
                    "description holds every word as a whole word (\"hot\" finds "
                    "`scald_hot_liquid`, not \"Photographing\"); case-insensitive.")] = None,
    sort: Annotated[TemplateSortKey, Query(
        description="The column to sort by (severity by how bad, not alphabetically); ties "
                    "keep id order.")] = TemplateSortKey.ID,
    order: Annotated[SortOrder, Query(description="Ascending or descending.")] = SortOrder.ASC,
    offset: Annotated[int, Query(ge=0, le=MAX_OFFSET,
                                 description="Matches to skip before the page.")] = 0,
    limit: Annotated[int | None, Query(
        ge=1, le=MAX_PAGE, description="Page size; without it, every match from `offset` "
                                       "on.")] = None,
) -> TemplateListResponse:
    """Templates at their current version, filtered by category, class, status and search words,
    sorted by one column, optionally one page at a time (`total` counts every match)."""
    found = catalog.page(category=category, hazard_class=hazard_class, status=status, text=q,
                         sort=sort, order=order, offset=offset, limit=limit)
    return TemplateListResponse(count=len(found.templates), total=found.total, offset=offset,
                                limit=limit, templates=[_template(t) for t in found.templates])


@router.post("/templates/validate", response_model=TemplateValidationResponse,
             response_model_exclude_unset=True,
             summary="Validate a template without storing it", responses=problem_responses(503))
def validate_template(
    curation: CurationDep, _: ReadAccess, document: Any = _DOCUMENT
) -> TemplateValidationResponse:
    """Validate a template without storing it: `valid`, `errors` and `warnings`."""
    return TemplateValidationResponse.model_validate(curation.validate(document).as_dict())


@router.post("/templates", status_code=status.HTTP_201_CREATED,
             response_model=CuratedTemplateResponse, response_model_exclude_unset=True,
             summary="Create a template (a draft)",
             responses=problem_responses(403, (409, "A template with this id exists."), 503))
def create_template(
    curation: CurationDep, key: CuratorKey, document: Any = _DOCUMENT
) -> CuratedTemplateResponse:
    """Validate a new template and store it as a draft (activate it to put it to use)."""
    return _curated(curation.create(document, _author(key)))


@router.get("/templates/{template_id}", response_model=TemplateHistoryResponse,
            summary="Read a template with its versions", responses=problem_responses(404, 503))
def get_template(template_id: str, catalog: CatalogDep,
                 _: ReadAccess) -> TemplateHistoryResponse:
    """One template at its current version, with every version kept."""
    history = catalog.history(template_id)
    return TemplateHistoryResponse.model_validate({
        **history.current.model_dump(mode="json"),
        "versions": [v.model_dump(mode="json") for v in history.versions]})


@router.get("/templates/{template_id}/versions/{version}", response_model=TemplateResponse,
            summary="Read one version of a template", responses=problem_responses(404, 503))
def get_template_version(
    template_id: str, version: Annotated[int, Path(ge=1, le=MAX_VERSION)], catalog: CatalogDep,
    _: ReadAccess,
) -> TemplateResponse:
    """One template as it was at one version (contracts name the versions they used)."""
    return _template(catalog.version(template_id, version))


@router.put("/templates/{template_id}", response_model=CuratedTemplateResponse,
            response_model_exclude_unset=True, summary="Revise a template (a new version)",
            responses=problem_responses(
                403, 404, (409, "Revised concurrently, or its id does not match."), 503))
def revise_template(
    template_id: str, curation: CurationDep, key: CuratorKey, document: Any = _DOCUMENT
) -> CuratedTemplateResponse:
    """Store a revision as the next version; earlier versions stay readable."""
    return _curated(curation.revise(template_id, document, _author(key)))


@router.post("/templates/{template_id}/activate", response_model=TemplateResponse,
             summary="Activate a template",
             responses=problem_responses(
                 403, 404, (409, "Its status or validity does not allow it."), 503))
def activate_template(template_id: str, curation: CurationDep,
                      _: CuratorKey) -> TemplateResponse:
    """Put a template to use: the gate binds it from the next request on."""
    return _template(curation.activate(template_id))


@router.post("/templates/{template_id}/deprecate", response_model=TemplateResponse,
             summary="Deprecate a template",
             responses=problem_responses(
                 403, 404, (409, "Its status does not allow it."), 503))
def deprecate_template(
    template_id: str, curation: CurationDep, _: CuratorKey
) -> TemplateResponse:
    """Retire a template: the gate stops binding it; its versions stay readable."""
    return _template(curation.deprecate(template_id))
