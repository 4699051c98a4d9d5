"""Validate a hazard template before anything is stored: schema, language, meaning, duplicates.

In: a template document as a curator sends it (decoded JSON), the library it would join, and a
solver budget. Out: `TemplateValidation` with the parsed template, errors (which forbid storing
it) and warnings (which do not). Each issue names the field (`body.guards.0.formula`) and, for a
condition, the line and column inside its formula. The steps stop at the first layer that fails,
because later ones need earlier ones: schema and conventions, then every condition parses and
type-checks against the vocabulary (known predicates, arity, argument types, declared
variables), then Z3 (invariants jointly satisfiable, guards satisfiable, no abort always true).
Fails: never; every problem is an issue. A solver `unknown` is an error (fail closed).
"""

from __future__ import annotations

from collections.abc import Sequence

from app.domain.models import HazardTemplate
from app.domain.template_validation.conditions import ParsedCondition, parse_conditions
from app.domain.template_validation.duplicates import duplicate_warnings
from app.domain.template_validation.issues import TemplateIssue, TemplateValidation
from app.domain.template_validation.meaning import class_conflict, meaning_issues
from app.domain.template_validation.skeleton import suggest_template
from app.domain.template_validation.structure import (
    SERVER_FIELDS,
    parse_document,
    structure_errors,
    structure_warnings,
)

DEFAULT_TIMEOUT_MS = 2000


def validate_template(
    document: object,
    *,
    library: Sequence[HazardTemplate] = (),
    timeout_ms: int = DEFAULT_TIMEOUT_MS,
) -> TemplateValidation:
    """Validate one template document.

    Args:
        document: the decoded JSON template (server-managed fields such as `version` and
            `status` are ignored, so a document fetched with GET can be sent back).
        library: the stored templates (any status), for duplicate warnings.
        timeout_ms: the solver's budget per check.

    Returns:
        The verdict; `ok` is True only when there is no error.
    """
    template, schema_issues = parse_document(document)
    if template is None:
        return TemplateValidation(None, tuple(schema_issues))
    errors = structure_errors(template)
    warnings = structure_warnings(template)
    parsed, condition_errors = parse_conditions(template)
    errors += condition_errors
    if not errors:
        found, noted = meaning_issues(template, parsed, timeout_ms)
        errors += found
        warnings += noted
    warnings += duplicate_warnings(template, parsed, library)
    return TemplateValidation(template, tuple(errors), tuple(warnings))


__all__ = [
    "DEFAULT_TIMEOUT_MS",
    "SERVER_FIELDS",
    "ParsedCondition",
    "TemplateIssue",
    "TemplateValidation",
    "class_conflict",
    "suggest_template",
    "validate_template",
]
