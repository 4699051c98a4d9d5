"""Queries on the Hazard Template Library: seeding, curation and the gate's active set.

In: `HazardTemplate` values. Out: `HazardTemplate` values at their current (or a named) version,
rebuilt from the stored JSON document with the row's status and source. A template's content is
never edited in place: every change is a new version row.
Fails: `NotFound` for an unknown id or version, `Conflict` for an id that already exists or a
status change that is not allowed, `TemplateInvalid` for a document whose id disagrees with the
template it is filed under, `Unavailable` for database errors.
"""

from __future__ import annotations

from collections.abc import Sequence

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session

from app.domain.errors import Conflict, NotFound, TemplateInvalid, Unavailable
from app.domain.models import Category, HazardTemplate, TemplateSource, TemplateStatus
from app.store.records import SeedReport, TemplateHistory, TemplateVersionRecord
from app.store.repository._base import RepositoryBase
from app.store.repository.template_documents import (
    rebuild_template,
    template_content_hash,
    version_row,
)
from app.store.tables import HazardTemplateRow, TemplateVersionRow, utc_now

SEED_RETRIES = 3


class TemplateQueries(RepositoryBase):
    """Hazard templates and their versions."""

    def upsert_seed_templates(self, templates: Sequence[HazardTemplate]) -> SeedReport:
        """Load seed templates idempotently.

        A new id is added at version 1 with the template's own status. A seed template whose
        content changed gets a new version (its status, possibly set by a curator, is kept). A
        template whose source is `user` is never touched.

        Args:
            templates: the library as loaded from YAML; ids must be unique.

        Returns:
            Which ids were added, got a new version, were unchanged or were skipped.

        Raises:
            TemplateInvalid: two templates share an id.
            Unavailable: database error (also after concurrent loaders kept colliding).
        """
        seen: set[str] = set()
        for template in templates:
            if template.id in seen:
                raise TemplateInvalid(f"duplicate template id {template.id!r}", field="id")
            seen.add(template.id)
        for _ in range(SEED_RETRIES):
            try:
                with self._transaction("seeding templates") as session:
                    return self._seed_in(session, templates)
            except Unavailable as error:
                # Another replica seeding at the same moment inserts the same ids; retrying
                # sees its rows and finds them unchanged.
                if not isinstance(error.__cause__, IntegrityError):
                    raise
        raise Unavailable("seeding templates kept colliding with a concurrent loader")

    def _seed_in(self, session: Session, templates: Sequence[HazardTemplate]) -> SeedReport:
        added: list[str] = []
        new_versions: list[str] = []
        unchanged: list[str] = []
        skipped: list[str] = []
        for template in templates:
            row = session.get(HazardTemplateRow, template.id, with_for_update=True)
            if row is None:
                now = utc_now()
                session.add(
                    HazardTemplateRow(
                        id=template.id,
                        hazard_class=template.hazard_class,
                        category=template.category.value,
                        status=template.status.value,
                        source=TemplateSource.SEED.value,
                        current_version=1,
                        created_at=now,
                        updated_at=now,
                    )
                )
                session.add(version_row(template, 1, template.author, template.status.value))
                added.append(template.id)
            elif row.source == TemplateSource.USER.value:
                skipped.append(template.id)
            elif self._current_version(session, row).content_hash == template_content_hash(
                template
            ):
                unchanged.append(template.id)
            else:
                self._append_version(session, row, template, template.author)
                new_versions.append(template.id)
            session.flush()
        return SeedReport(
            added=tuple(added),
            new_versions=tuple(new_versions),
            unchanged=tuple(unchanged),
            skipped_user=tuple(skipped),
        )

    def create_user_template(self, template: HazardTemplate, author: str) -> HazardTemplate:
        """Store a curator's new template as a draft at version 1.

        Args:
            template: the template; its status and source are replaced by draft and user.
            author: who wrote it.

        Returns:
            The stored template.

        Raises:
            Conflict: a template with this id already exists.
        """
        with self._transaction("creating a template") as session:
            if session.get(HazardTemplateRow, template.id) is not None:
                raise Conflict(f"template {template.id!r} already exists", field="id")
            now = utc_now()
            row = HazardTemplateRow(
                id=template.id,
                hazard_class=template.hazard_class,
                category=template.category.value,
                status=TemplateStatus.DRAFT.value,
                source=TemplateSource.USER.value,
                current_version=1,
                created_at=now,
                updated_at=now,
            )
            version = version_row(template, 1, author, TemplateStatus.DRAFT.value)
            session.add_all([row, version])
            try:
                session.flush()
            except IntegrityError as error:
                raise Conflict(f"template {template.id!r} already exists", field="id") from error
            return rebuild_template(row, version, row.status)

    def add_template_version(
        self, template_id: str, template: HazardTemplate, author: str
    ) -> HazardTemplate:
        """Add a new version of an existing template; its status stays as it was.

        The template becomes a `user` template, so later seed loads leave the curator's edit alone.

        Args:
            template_id: the template to revise.
            template: the new content; its id must equal `template_id`.
            author: who wrote the revision.

        Returns:
            The template at its new version.

        Raises:
            TemplateInvalid: the document's id differs from `template_id`.
            NotFound: no such template.
        """
        if template.id != template_id:
            raise TemplateInvalid(
                f"template id {template.id!r} does not match {template_id!r}", field="id"
            )
        with self._transaction("adding a template version") as session:
            row = self._row(session, template_id, lock=True)
            row.source = TemplateSource.USER.value
            version = self._append_version(session, row, template, author)
            try:
                session.flush()
            except IntegrityError as error:
                raise Conflict(f"template {template_id!r} was revised concurrently") from error
            return rebuild_template(row, version, row.status)

    def set_template_status(self, template_id: str, status: TemplateStatus) -> HazardTemplate:
        """Activate or deprecate a template (a template never goes back to draft).

        Args:
            template_id: the template.
            status: `active` or `deprecated` (or `draft` for a template still in draft).

        Returns:
            The template at its current version with the new status.

        Raises:
            NotFound: no such template.
            Conflict: moving a non-draft template back to draft.
        """
        with self._transaction("changing a template's status") as session:
            row = self._row(session, template_id, lock=True)
            if status is TemplateStatus.DRAFT and row.status != TemplateStatus.DRAFT.value:
                raise Conflict(f"template {template_id!r} is {row.status}; it cannot become draft")
            row.status = status.value
            row.updated_at = utc_now()
            version = self._current_version(session, row)
            version.status = status.value
            return rebuild_template(row, version, row.status)

    def get_template(self, template_id: str, version: int | None = None) -> HazardTemplate:
        """One template at its current version, or at `version`.

        Raises:
            NotFound: no such template or version.
        """
        with self._transaction("reading a template") as session:
            row = self._row(session, template_id)
            if version is None:
                return rebuild_template(row, self._current_version(session, row), row.status)
            stored = session.get(TemplateVersionRow, (template_id, version))
            if stored is None:
                raise NotFound(f"template {template_id!r} has no version {version}")
            return rebuild_template(row, stored, stored.status)

    def get_template_history(self, template_id: str) -> TemplateHistory:
        """A template at its current version with all its versions, oldest first.

        Raises:
            NotFound: no such template.
        """
        with self._transaction("reading a template's history") as session:
            row = self._row(session, template_id)
            versions = session.scalars(
                select(TemplateVersionRow)
                .where(TemplateVersionRow.template_id == template_id)
                .order_by(TemplateVersionRow.version)
            ).all()
            current = next(v for v in versions if v.version == row.current_version)
            return TemplateHistory(
                current=rebuild_template(row, current, row.status),
                versions=tuple(
                    TemplateVersionRecord(
                        template_id=template_id,
                        version=v.version,
                        template=rebuild_template(row, v, v.status),
                        author=v.author,
                        status=TemplateStatus(v.status),
                        created_at=v.created_at,
                    )
                    for v in versions
                ),
            )

    def list_templates(
        self,
        *,
        category: Category | None = None,
        hazard_class: str | None = None,
        status: TemplateStatus | None = None,
    ) -> list[HazardTemplate]:
        """Templates at their current versions, ordered by id, optionally filtered.

        Args:
            category: keep only this category.
            hazard_class: keep only this hazard class.
            status: keep only this status.
        """
        query = select(HazardTemplateRow, TemplateVersionRow).join(
            TemplateVersionRow,
            (TemplateVersionRow.template_id == HazardTemplateRow.id)
            & (TemplateVersionRow.version == HazardTemplateRow.current_version),
        )
        if category is not None:
            query = query.where(HazardTemplateRow.category == category.value)
        if hazard_class is not None:
            query = query.where(HazardTemplateRow.hazard_class == hazard_class)
        if status is not None:
            query = query.where(HazardTemplateRow.status == status.value)
        with self._transaction("listing templates") as session:
            rows = session.execute(query.order_by(HazardTemplateRow.id)).all()
            return [rebuild_template(row, version, row.status) for row, version in rows]

    def list_active_templates(self) -> list[HazardTemplate]:
        """Every active template at its current version: what the gate binds against."""
        return self.list_templates(status=TemplateStatus.ACTIVE)

    @staticmethod
    def _row(session: Session, template_id: str, *, lock: bool = False) -> HazardTemplateRow:
        row = session.get(HazardTemplateRow, template_id, with_for_update=lock)
        if row is None:
            raise NotFound(f"no template {template_id!r}")
        return row

    @staticmethod
    def _current_version(session: Session, row: HazardTemplateRow) -> TemplateVersionRow:
        version = session.get(TemplateVersionRow, (row.id, row.current_version))
        if version is None:
            raise Unavailable(f"template {row.id!r} lost its current version")
        return version

    @staticmethod
    def _append_version(
        session: Session, row: HazardTemplateRow, template: HazardTemplate, author: str
    ) -> TemplateVersionRow:
        version = version_row(template, row.current_version + 1, author, row.status)
        session.add(version)
        row.current_version = version.version
        row.hazard_class = template.hazard_class
        row.category = template.category.value
        row.updated_at = utc_now()
        return version
