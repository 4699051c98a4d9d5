"""Template curation: validate, create, revise, activate and deprecate library templates.

In: a template document (decoded JSON) from a curator, with the curator's name as author. Out:
the stored template with the validation's warnings (`Curated`), or the validation verdict alone.
Validation runs before anything is stored, so bad input changes nothing. The gate's template
cache is refreshed after every status change and every new version of an active template.
Fails: `TemplateInvalid` (422, `errors` lists each problem with its field and position),
`NotFound` (404), `Conflict` (409: the id exists, or activating would contradict the class's
other active templates), `Unavailable` (503).
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import Any

from app.domain.errors import Conflict, TemplateInvalid
from app.domain.models import HazardTemplate, TemplateStatus
from app.domain.template_validation import (
    TemplateIssue,
    TemplateValidation,
    class_conflict,
    validate_template,
)
from app.services.template_cache import TemplateCache
from app.store.repository import TemplateRepository


@dataclass(frozen=True)
class Curated:
    """A stored template and what validation warned about."""

    template: HazardTemplate
    warnings: tuple[TemplateIssue, ...] = ()


def _refuse(errors: list[dict[str, Any]], warnings: tuple[TemplateIssue, ...] = ()) -> None:
    first = errors[0]
    where = first["field"]
    if first.get("line") is not None:
        where += f" (line {first['line']}, column {first['column']})"
    count = f"{len(errors)} problems" if len(errors) > 1 else "a problem"
    raise TemplateInvalid(
        f"the template has {count}; first at {where}: {first['message']}",
        errors=errors,
        warnings=[w.as_dict() for w in warnings],
    )


def _valid_template(validation: TemplateValidation) -> HazardTemplate:
    if validation.template is None or validation.errors:
        _refuse([issue.as_dict() for issue in validation.errors], validation.warnings)
    assert validation.template is not None
    return validation.template


class CurationService:
    """Template writes, validated first, with the gate's template cache kept current."""

    def __init__(self, *, templates: TemplateRepository, cache: TemplateCache,
                 solver_lock: threading.Lock, solver_timeout_ms: int) -> None:
        """Args:
            templates: the library.
            cache: the gate's active templates, refreshed after a change that affects them.
            solver_lock: held around every Z3 use in this process: Z3's shared context is not
                thread-safe, and concurrent template writes in the threadpool failed with 500.
            solver_timeout_ms: Z3's budget per check.
        """
        self._templates = templates
        self._cache = cache
        self._solver_lock = solver_lock
        self._timeout_ms = solver_timeout_ms

    def validate(self, document: object) -> TemplateValidation:
        """Validate a document against the schema, the vocabulary, Z3 and the stored library."""
        library = self._templates.list_templates()
        with self._solver_lock:
            return validate_template(document, library=library,
                                     timeout_ms=self._timeout_ms)


    def create(self, document: object, author: str) -> Curated:
        """Validate a new template and store it as a draft at version 1.

        Raises:
            TemplateInvalid: the document fails validation (nothing is stored).
            Conflict: a template with this id exists.
        """
        validation = self.validate(document)
        template = _valid_template(validation)
        stored = self._templates.create_user_template(template, author)
        return Curated(stored, validation.warnings)


    def revise(self, template_id: str, document: object, author: str) -> Curated:
        """Validate a revision and store it as the template's next version (older ones are kept).

        Raises:
            NotFound: no such template.
            TemplateInvalid: the document fails validation or names another id.
        """
        self._templates.get_template(template_id)
        validation = self.validate(document)
        template = _valid_template(validation)
        if template.id != template_id:
            _refuse([{"field": "body.id", "code": "id",
                      "message": f"the document's id {template.id!r} is not {template_id!r}"}])
        stored = self._templates.add_template_version(template_id, template, author)
        if stored.status is TemplateStatus.ACTIVE:
            self._cache.refresh()
        return Curated(stored, validation.warnings)


    def activate(self, template_id: str) -> HazardTemplate:
        """Make a template active, so that the gate binds it from now on.

        Raises:
            NotFound: no such template.
            Conflict: its invariants contradict those of the class's other active templates.
        """
        template = self._templates.get_template(template_id)
        others = [
            other
            for other in self._cache.index().for_class(template.hazard_class)
            if other.id != template_id
        ]
        with self._solver_lock:
            conflict = class_conflict(template, others, self._timeout_ms)
        if conflict is not None:
            raise Conflict(conflict.message, field=conflict.field, code=conflict.code)
        stored = self._templates.set_template_status(template_id, TemplateStatus.ACTIVE)
        self._cache.refresh()
        return stored


    def deprecate(self, template_id: str) -> HazardTemplate:
        """Retire a template: the gate stops binding it; its versions stay readable.

        Raises:
            NotFound: no such template.
        """
        stored = self._templates.set_template_status(template_id, TemplateStatus.DEPRECATED)
        self._cache.refresh()
        return stored
