"""Move the Hazard Template Library in and out as YAML (`safegate templates export|import`).

In: a repository, and for an import the text of a YAML file shaped like `templates_db/*.yaml` (a
mapping with a `templates:` list), each entry optionally with a `status`. Out: the YAML of every
template at its current version with its status (`export_yaml`), or an `ImportReport` of what an
import created, revised, re-statused and left alone (`import_yaml`).
An import validates every entry the way `POST /templates` does (schema, vocabulary, Z3, against
the stored library), refuses a status a template cannot take (back to draft) and, like
`POST /templates/{id}/activate`, any active template whose invariants contradict the other active
templates of its class. Only when the whole file passes is it written, in one transaction.
Fails: `TemplateInvalid` listing every problem (`errors`: where, field, message); nothing is
stored then. `Unavailable` and `Conflict` from the database, also with nothing stored.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import yaml

from app.domain.errors import TemplateInvalid
from app.domain.models import HazardTemplate, TemplateStatus
from app.domain.template_validation import class_conflict, validate_template
from app.store.records import TemplateChange
from app.store.repository import template_content_hash
from app.store.repository.template_imports import TemplateImportQueries

# What an export leaves out: bookkeeping the database assigns (an import makes its own).
_BOOKKEEPING = frozenset({"version", "source", "author", "created_at"})


@dataclass(frozen=True)
class ImportIssue:
    """One problem with an entry of an import file."""

    where: str
    field: str
    message: str

    def as_dict(self) -> dict[str, str]:
        return {"where": self.where, "field": self.field, "message": self.message}


@dataclass(frozen=True)
class ImportReport:
    """What an import did (or, for a dry run, would do), by template id."""

    created: tuple[str, ...] = ()
    revised: tuple[str, ...] = ()
    status_changed: tuple[str, ...] = ()
    unchanged: tuple[str, ...] = ()
    warnings: tuple[ImportIssue, ...] = ()
    changes: tuple[TemplateChange, ...] = field(default=(), repr=False)


@dataclass(frozen=True)
class Export:
    """An exported library: the YAML text and how many templates it holds."""

    text: str
    count: int


def export_yaml(repository: TemplateImportQueries, *,
                status: TemplateStatus | None = None) -> Export:
    """The library (or the templates with one status) as YAML, in id order.

    Args:
        repository: where the templates are stored.
        status: keep only this status.

    Returns:
        The YAML (the shape `templates_db/README.md` describes, each entry with its `status`)
        and the number of templates in it.
    """
    documents = [
        template.model_dump(mode="json", exclude=set(_BOOKKEEPING))
        for template in repository.list_templates(status=status)
    ]
    text = yaml.safe_dump(
        {"templates": documents}, sort_keys=False, allow_unicode=True, width=100
    )
    return Export(text, len(documents))


def _entries(text: str) -> list[Any]:
    try:
        document = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise TemplateInvalid(f"not valid YAML: {error}", field="templates") from error
    if not isinstance(document, dict) or not isinstance(document.get("templates"), list):
        raise TemplateInvalid("expected a mapping with a 'templates:' list", field="templates")
    entries: list[Any] = document["templates"]
    return entries


def _where(index: int, entry: object) -> str:
    label = entry.get("id") if isinstance(entry, dict) else None
    return f"templates[{index}]" + (f" ({label})" if isinstance(label, str) else "")


def _status_of(entry: dict[str, Any], current: HazardTemplate | None) -> TemplateStatus:
    raw = entry.get("status")
    if raw is None:
        return current.status if current is not None else TemplateStatus.DRAFT
    return TemplateStatus(raw)


@dataclass
class _Planner:
    """Validates the entries one by one and collects the changes and problems."""

    stored: dict[str, HazardTemplate]
    timeout_ms: int
    errors: list[ImportIssue] = field(default_factory=list)
    warnings: list[ImportIssue] = field(default_factory=list)
    final: dict[str, tuple[HazardTemplate, TemplateStatus, bool]] = field(default_factory=dict)

    def add(self, index: int, entry: object) -> None:
        where = _where(index, entry)
        validation = validate_template(
            entry, library=list(self.stored.values()), timeout_ms=self.timeout_ms
        )
        self.warnings += [ImportIssue(where, w.field, w.message) for w in validation.warnings]
        if validation.template is None or validation.errors or not isinstance(entry, dict):
            self.errors += [ImportIssue(where, e.field, e.message) for e in validation.errors]
            return
        template = validation.template
        if template.id in self.final:
            self.errors.append(ImportIssue(where, "body.id", f"id {template.id!r} repeats an "
                                                             "earlier entry of the file"))
            return
        current = self.stored.get(template.id)
        try:
            status = _status_of(entry, current)
        except ValueError:
            self.errors.append(ImportIssue(where, "body.status", f"unknown status "
                                           f"{entry.get('status')!r}"))
            return
        if (status is TemplateStatus.DRAFT and current is not None
                and current.status is not TemplateStatus.DRAFT):
            self.errors.append(ImportIssue(where, "body.status", f"template {template.id!r} is "
                                           f"{current.status}; it cannot become draft"))
            return
        changed = current is None or (
            template_content_hash(template) != template_content_hash(current))
        self.final[template.id] = (template, status, changed)

    def check_active_classes(self) -> None:
        """Every template the import activates or changes while active must agree with the
        other templates of its class that are active once the import is done."""
        active = {tid: t for tid, t in self.stored.items() if t.status is TemplateStatus.ACTIVE}
        for tid, (template, status, _) in self.final.items():
            active.pop(tid, None)
            if status is TemplateStatus.ACTIVE:
                active[tid] = template
        for tid, (template, status, changed) in self.final.items():
            current = self.stored.get(tid)
            becomes_active = current is None or current.status is not TemplateStatus.ACTIVE
            if status is not TemplateStatus.ACTIVE or not (changed or becomes_active):
                continue
            others = [t for t in active.values()
                      if t.hazard_class == template.hazard_class and t.id != tid]
            conflict = class_conflict(template, others, self.timeout_ms)
            if conflict is not None:
                self.errors.append(ImportIssue(tid, conflict.field, conflict.message))


def _report(planner: _Planner) -> ImportReport:
    created: list[str] = []
    revised: list[str] = []
    status_changed: list[str] = []
    unchanged: list[str] = []
    changes: list[TemplateChange] = []
    for tid, (template, status, changed) in planner.final.items():
        current = planner.stored.get(tid)
        if current is None:
            created.append(tid)
        elif changed:
            revised.append(tid)
        elif status is not current.status:
            status_changed.append(tid)
        else:
            unchanged.append(tid)
            continue
        changes.append(TemplateChange(template=template, status=status, new_version=changed,
                                      base_version=None if current is None else current.version))
    return ImportReport(tuple(created), tuple(revised), tuple(status_changed), tuple(unchanged),
                        tuple(planner.warnings), tuple(changes))


def plan_import(repository: TemplateImportQueries, text: str, *, timeout_ms: int) -> ImportReport:
    """Validate an import file against the stored library and work out what it would change.

    Args:
        repository: the library it would be imported into.
        text: the YAML file's content.
        timeout_ms: the solver's budget per check.

    Returns:
        The report; nothing is written.

    Raises:
        TemplateInvalid: the file or any entry is invalid; `errors` lists every problem.
    """
    entries = _entries(text)
    planner = _Planner({t.id: t for t in repository.list_templates()}, timeout_ms)
    for index, entry in enumerate(entries):
        planner.add(index, entry)
    if not planner.errors:
        planner.check_active_classes()
    if planner.errors:
        _refuse(planner.errors)
    return _report(planner)


def _refuse(errors: Sequence[ImportIssue]) -> None:
    first = errors[0]
    count = f"{len(errors)} problems" if len(errors) > 1 else "a problem"
    raise TemplateInvalid(
        f"the file has {count}; nothing was imported. First: {first.where}, {first.field}: "
        f"{first.message}",
        field=first.field,
        errors=[issue.as_dict() for issue in errors],
    )


def import_yaml(
    repository: TemplateImportQueries, text: str, *, author: str, timeout_ms: int,
    dry_run: bool = False,
) -> ImportReport:
    """Validate an import file and, when every entry passes, write it in one transaction.

    Args:
        repository: the library to import into.
        text: the YAML file's content.
        author: who the new versions are credited to.
        timeout_ms: the solver's budget per check.
        dry_run: validate and report only.

    Returns:
        What was (or would be) created, revised, re-statused and left unchanged.

    Raises:
        TemplateInvalid: the file or an entry is invalid (nothing is stored).
        Conflict: the library changed under the import (nothing is stored).
        Unavailable: database error (nothing is stored).
    """
    report = plan_import(repository, text, timeout_ms=timeout_ms)
    if not dry_run and report.changes:
        repository.apply_template_changes(report.changes, author)
    return report
