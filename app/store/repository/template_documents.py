"""How a hazard template is stored: a content document, its hash, and the way back.

In: `HazardTemplate` values and stored rows. Out: version rows (the content as JSON without the
bookkeeping that lives in columns: version, status, source, author, creation time), content
hashes that tell a changed seed template from an unchanged one, and templates rebuilt from rows.
Fails: pydantic `ValidationError` if a stored document no longer fits `HazardTemplate`.
"""

from __future__ import annotations

import hashlib
import json
from typing import Any

from app.domain.models import HazardTemplate
from app.store.tables import HazardTemplateRow, TemplateVersionRow, utc_now

_NOT_CONTENT = frozenset({"version", "status", "source", "author", "created_at"})


def template_content_hash(template: HazardTemplate) -> str:
    """A hash of what a template says, ignoring its bookkeeping (version, status, author...).

    Args:
        template: the template to fingerprint.

    Returns:
        A 64-character hex SHA-256 of the canonical JSON of its content.
    """
    content = template.model_dump(mode="json", exclude=set(_NOT_CONTENT))
    canonical = json.dumps(content, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode()).hexdigest()


def _document(template: HazardTemplate) -> dict[str, Any]:
    return template.model_dump(mode="json", exclude=set(_NOT_CONTENT))


def rebuild_template(
    row: HazardTemplateRow, version: TemplateVersionRow, status: str
) -> HazardTemplate:
    """The domain template a stored version describes, with the given status."""
    return HazardTemplate.model_validate(
        {
            **version.document,
            "version": version.version,
            "status": status,
            "source": row.source,
            "author": version.author,
            "created_at": version.created_at,
        }
    )


def version_row(
    template: HazardTemplate, version: int, author: str, status: str
) -> TemplateVersionRow:
    """A new version row holding the template's content document and its hash."""
    return TemplateVersionRow(
        template_id=template.id,
        version=version,
        document=_document(template),
        content_hash=template_content_hash(template),
        author=author,
        status=status,
        created_at=utc_now(),
    )
