"""Listing the template library for a table: whole-word search, sorting and paging.

In: the templates at their current versions (as the repository lists them, ordered by id) and
the listing's query (search text, sort column and order, offset and optional limit). Out: a
`TemplatePage`, the page's templates with the number of matches before paging. Pure and total:
an offset past the end is an empty page, no limit is every match (what callers that do not page
got before paging existed).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from enum import StrEnum

from app.domain.models import HazardTemplate

# A word is a run of letters and digits: ids and hazard classes split at '.', '_' and '-', so
# "hot" finds `scald_hot_liquid` and "Hot liquid", never "Photographing".
_WORD = re.compile(r"[^\W_]+")


class TemplateSortKey(StrEnum):
    """The columns the library can be sorted by."""

    ID = "id"
    NAME = "name"
    CATEGORY = "category"
    HAZARD_CLASS = "hazard_class"
    SEVERITY = "severity"
    STATUS = "status"
    VERSION = "version"


class SortOrder(StrEnum):
    ASC = "asc"
    DESC = "desc"


@dataclass(frozen=True)
class TemplatePage:
    """One page of a listing: its templates, and how many matched in all."""

    templates: list[HazardTemplate]
    total: int


def _words(text: str) -> set[str]:
    return {word.casefold() for word in _WORD.findall(text)}


def search(templates: list[HazardTemplate], text: str | None) -> list[HazardTemplate]:
    """The templates whose id, name, hazard class or description hold every word of `text`.

    Words match whole words only, case-insensitively; an empty or wordless text keeps all.
    """
    wanted = _words(text or "")
    if not wanted:
        return templates

    def matches(template: HazardTemplate) -> bool:
        found = _words(" ".join(
            (template.id, template.name, template.hazard_class, template.description)))
        return wanted <= found

    return [template for template in templates if matches(template)]


_SORT_VALUES: dict[TemplateSortKey, Callable[[HazardTemplate], str | int]] = {
    TemplateSortKey.ID: lambda t: t.id,
    TemplateSortKey.NAME: lambda t: t.name.casefold(),
    TemplateSortKey.CATEGORY: lambda t: t.category.value,
    TemplateSortKey.HAZARD_CLASS: lambda t: t.hazard_class,
    # Severity sorts by how bad it is (negligible first), not alphabetically.
    TemplateSortKey.SEVERITY: lambda t: t.severity.rank,
    TemplateSortKey.STATUS: lambda t: t.status.value,
    TemplateSortKey.VERSION: lambda t: t.version,
}


def sort_templates(
    templates: list[HazardTemplate], key: TemplateSortKey, order: SortOrder
) -> list[HazardTemplate]:
    """The templates sorted by one column; ties keep id order, whichever the direction."""
    by_id = sorted(templates, key=lambda t: t.id)
    value = _SORT_VALUES[key]
    # Python's sort is stable, so sorting the id-ordered list by the column keeps ids in order
    # among equal values; a descending sort reverses only the column's order.
    if order is SortOrder.ASC:
        return sorted(by_id, key=value)
    groups: dict[str | int, list[HazardTemplate]] = {}
    for template in by_id:
        groups.setdefault(value(template), []).append(template)
    return [t for column_value in sorted(groups, reverse=True) for t in groups[column_value]]


def page(
    templates: list[HazardTemplate],
    *,
    text: str | None = None,
    sort: TemplateSortKey = TemplateSortKey.ID,
    order: SortOrder = SortOrder.ASC,
    offset: int = 0,
    limit: int | None = None,
) -> TemplatePage:
    """Search, sort, then cut one page.

    Args:
        templates: the templates to list.
        text: search words (whole words, all required); None or blank keeps all.
        sort: the column to sort by.
        order: ascending or descending.
        offset: how many sorted matches to skip.
        limit: the page's size; None for every match from `offset` on.
    """
    found = sort_templates(search(templates, text), sort, order)
    end = None if limit is None else offset + limit
    return TemplatePage(templates=found[offset:end], total=len(found))
