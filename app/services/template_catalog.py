"""Reading the template library: one page of it, one template's history, one version.

In: the template repository; the listing's filters, search words, sort and page. Out: a
`TemplatePage` (`app.services.template_listing`), a `TemplateHistory` or a `HazardTemplate`.
Fails: `NotFound` (404) for an unknown template or version, `Unavailable` (503).
"""

from __future__ import annotations

from app.domain.models import Category, HazardTemplate, TemplateStatus
from app.services import template_listing
from app.services.template_listing import SortOrder, TemplatePage, TemplateSortKey
from app.store.records import TemplateHistory
from app.store.repository import TemplateRepository


class TemplateCatalog:
    """Read access to the library for the API."""

    def __init__(self, templates: TemplateRepository) -> None:
        self._templates = templates

    def page(
        self, *, category: Category | None, hazard_class: str | None,
        status: TemplateStatus | None, text: str | None, sort: TemplateSortKey,
        order: SortOrder, offset: int, limit: int | None,
    ) -> TemplatePage:
        """Templates at their current version, filtered, searched, sorted and paged."""
        templates = self._templates.list_templates(
            category=category, hazard_class=hazard_class, status=status)
        return template_listing.page(templates, text=text, sort=sort, order=order,
                                     offset=offset, limit=limit)

    def history(self, template_id: str) -> TemplateHistory:
        """One template at its current version, with every version kept."""
        return self._templates.get_template_history(template_id)

    def version(self, template_id: str, version: int) -> HazardTemplate:
        """One template as it was at one version."""
        return self._templates.get_template(template_id, version)
