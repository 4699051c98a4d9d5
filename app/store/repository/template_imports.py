"""Writing a whole batch of template changes at once (the library import).

In: `TemplateChange` values, already validated by the caller (`app.services.template_transfer`).
Out: the changes applied in one transaction: a new id is stored at version 1 with its status, a
changed template gets a new version, a status change updates the template and its current
version. Every written template becomes a `user` template, so seed loads leave it alone.
Fails: `Conflict` when a template is not at the version the batch was planned against (another
writer got there first), `Unavailable` for database errors; either way the transaction rolls
back and nothing of the batch is stored.
"""

from __future__ import annotations

from collections.abc import Sequence

from sqlalchemy.exc import IntegrityError

from app.domain.errors import Conflict
from app.domain.models import TemplateSource
from app.store.records import TemplateChange
from app.store.repository.template_documents import version_row
from app.store.repository.templates import TemplateQueries
from app.store.tables import HazardTemplateRow, utc_now


class TemplateImportQueries(TemplateQueries):
    """Template queries plus the all-or-nothing batch write."""

    def apply_template_changes(self, changes: Sequence[TemplateChange], author: str) -> None:
        """Apply every change in one transaction.

        Args:
            changes: what to write, one entry per template id.
            author: who the new versions are credited to.

        Raises:
            Conflict: a template is no longer at the change's `base_version` (nothing is stored).
            Unavailable: database error (nothing is stored).
        """
        with self._transaction("importing templates") as session:
            for change in changes:
                template = change.template
                row = session.get(HazardTemplateRow, template.id, with_for_update=True)
                found = None if row is None else row.current_version
                if found != change.base_version:
                    raise Conflict(f"template {template.id!r} changed while importing (version "
                                   f"{found}, expected {change.base_version}); nothing was stored")
                if row is None:
                    now = utc_now()
                    row = HazardTemplateRow(
                        id=template.id, hazard_class=template.hazard_class,
                        category=template.category.value, status=change.status.value,
                        source=TemplateSource.USER.value, current_version=1,
                        created_at=now, updated_at=now,
                    )
                    session.add_all([row, version_row(template, 1, author, row.status)])
                    continue
                row.status = change.status.value
                row.updated_at = utc_now()
                if change.new_version:
                    row.source = TemplateSource.USER.value
                    self._append_version(session, row, template, author)
                else:
                    self._current_version(session, row).status = row.status
            try:
                session.flush()
            except IntegrityError as error:
                raise Conflict("the library changed while importing; nothing was stored") \
                    from error
