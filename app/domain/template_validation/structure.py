"""The shape of a template document: schema, unknown keys and the library's conventions.

In: a JSON-like document (as a curator POSTs it). Out: the parsed `HazardTemplate` (or None when
the schema does not hold) and the issues found: schema errors with the pydantic location as a
dotted field path, unknown keys (a typo such as `invariant` must not silently drop conditions),
an id without a family prefix, no condition at all, repeated condition or variable ids, a guard
that names no canonical action, value variables that binding could never fill, and, as warnings,
entity variable names the analyzer never fills and variables no condition uses. Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from pydantic import ValidationError

from app.domain.models import HazardTemplate, TemplateCondition, TemplateVariable, VariableType
from app.domain.template_validation.issues import BODY, TemplateIssue, condition_field
from app.domain.world import canonical_action

# Fields the server manages; a document fetched with GET may carry them back unchanged.
SERVER_FIELDS = frozenset({"version", "status", "source", "author", "created_at", "versions"})
_TEMPLATE_KEYS = frozenset(HazardTemplate.model_fields) - SERVER_FIELDS
_VARIABLE_KEYS = frozenset(TemplateVariable.model_fields)
_CONDITION_KEYS = frozenset(TemplateCondition.model_fields)
_CONDITION_LISTS = ("invariants", "guards", "aborts")

ENTITY_TYPES = frozenset(
    {VariableType.OBJECT, VariableType.PERSON, VariableType.ROOM, VariableType.ENTITY}
)
# The analyzer fills entity variables by these names only (templates_db/README.md).
ANALYZER_ENTITY_NAMES = ("obj", "other", "person", "room", "aid")
_FAMILY_ID = re.compile(r"^[a-z][a-z0-9_]*\.[a-z0-9_.\-]+$")
_DEFAULT_TYPES: dict[VariableType, tuple[type, ...]] = {
    VariableType.NUMBER: (int, float),
    VariableType.STRING: (str,),
    VariableType.BOOL: (bool,),
}


def _unknown_keys(document: Mapping[str, Any]) -> list[TemplateIssue]:
    issues = [
        TemplateIssue(f"{BODY}.{key}", f"unknown field {key!r}", "unknown_field")
        for key in document
        if key not in _TEMPLATE_KEYS and key not in SERVER_FIELDS
    ]
    nested: list[tuple[str, frozenset[str]]] = [("variables", _VARIABLE_KEYS)] + [
        (name, _CONDITION_KEYS) for name in _CONDITION_LISTS
    ]
    for list_name, allowed in nested:
        entries = document.get(list_name)
        if not isinstance(entries, list):
            continue
        for index, entry in enumerate(entries):
            if isinstance(entry, Mapping):
                issues.extend(
                    TemplateIssue(
                        f"{BODY}.{list_name}.{index}.{key}", f"unknown field {key!r}",
                        "unknown_field",
                    )
                    for key in entry
                    if key not in allowed
                )
    return issues


def parse_document(document: object) -> tuple[HazardTemplate | None, list[TemplateIssue]]:
    """Validate a document against the template schema.

    Args:
        document: the decoded JSON body.

    Returns:
        The template (None when the schema fails) and the schema issues.
    """
    if not isinstance(document, Mapping):
        return None, [TemplateIssue(BODY, "a template must be a JSON object", "schema")]
    issues = _unknown_keys(document)
    content = {k: v for k, v in document.items() if k in _TEMPLATE_KEYS}
    try:
        template = HazardTemplate.model_validate(content)
    except ValidationError as error:
        for item in error.errors():
            path = ".".join(str(part) for part in (BODY, *item["loc"]))
            issues.append(TemplateIssue(path, item["msg"], "schema"))
        return None, issues
    return (None if issues else template), issues


def _duplicates(names: list[str]) -> list[int]:
    seen: set[str] = set()
    repeated: list[int] = []
    for index, name in enumerate(names):
        if name in seen:
            repeated.append(index)
        seen.add(name)
    return repeated


def _variable_issues(template: HazardTemplate) -> list[TemplateIssue]:
    issues = [
        TemplateIssue(f"{BODY}.variables.{i}.name",
                      f"variable ${template.variables[i].name} is declared twice", "duplicate_id")
        for i in _duplicates([v.name for v in template.variables])
    ]
    for index, variable in enumerate(template.variables):
        expected = _DEFAULT_TYPES.get(variable.type)
        if expected is None:
            continue
        where = f"{BODY}.variables.{index}.default"
        if variable.default is None:
            issues.append(TemplateIssue(
                where, f"${variable.name} ({variable.type.value}) needs a default: binding only "
                "fills entity variables, so without one the template can never be used",
                "missing_default"))
        elif not isinstance(variable.default, expected) or (
            variable.type is VariableType.NUMBER and isinstance(variable.default, bool)
        ):
            issues.append(TemplateIssue(
                where, f"the default of ${variable.name} must be a {variable.type.value}",
                "default_type"))
    return issues


def _condition_issues(template: HazardTemplate) -> list[TemplateIssue]:
    issues: list[TemplateIssue] = []
    conditions = template.conditions()
    if not conditions:
        issues.append(TemplateIssue(
            f"{BODY}.invariants", "a template needs at least one invariant, guard or abort",
            "no_condition"))
    indexed = {kind: 0 for kind, _ in conditions}
    ids: list[str] = []
    places: list[str] = []
    for kind, condition in conditions:
        index = indexed[kind]
        indexed[kind] += 1
        ids.append(condition.id)
        places.append(condition_field(kind.value, index, "id"))
        if kind.value == "guard":
            canonical = canonical_action(condition.action or "")
            if canonical != condition.action:
                hint = f"; use {canonical!r}" if canonical else ""
                issues.append(TemplateIssue(
                    condition_field("guard", index, "action"),
                    f"{condition.action!r} is not a canonical action name{hint}", "action"))
        elif condition.action is not None:
            issues.append(TemplateIssue(
                condition_field(kind.value, index, "action"),
                f"only guards name an action; a {kind.value} holds in every state", "action"))
    issues.extend(
        TemplateIssue(places[i], f"condition id {ids[i]!r} is used twice", "duplicate_id")
        for i in _duplicates(ids)
    )
    return issues


def structure_errors(template: HazardTemplate) -> list[TemplateIssue]:
    """Conventions a stored template must follow (beyond the schema).

    Args:
        template: a template that passed the schema.

    Returns:
        Errors: family prefix, conditions, ids, guard actions, value-variable defaults.
    """
    issues: list[TemplateIssue] = []
    if not _FAMILY_ID.match(template.id):
        issues.append(TemplateIssue(
            f"{BODY}.id", f"{template.id!r} needs a dotted family prefix, e.g. "
            f"'{template.category.value}.{template.id}'", "id"))
    return issues + _variable_issues(template) + _condition_issues(template)


def structure_warnings(template: HazardTemplate) -> list[TemplateIssue]:
    """Conventions worth a warning: unfillable entity names and unused variables."""
    issues: list[TemplateIssue] = []
    text = " ".join(condition.formula for _, condition in template.conditions())
    for index, variable in enumerate(template.variables):
        where = f"{BODY}.variables.{index}.name"
        if variable.type in ENTITY_TYPES and variable.name not in ANALYZER_ENTITY_NAMES:
            issues.append(TemplateIssue(
                where, f"the analyzer never fills ${variable.name}; entity variables it fills "
                f"are {', '.join('$' + n for n in ANALYZER_ENTITY_NAMES)}, so this template "
                "would stay unbound", "unfillable_variable"))
        if not re.search(rf"\${re.escape(variable.name)}\b", text):
            issues.append(TemplateIssue(
                where, f"${variable.name} is declared but no condition uses it",
                "unused_variable"))
    return issues
