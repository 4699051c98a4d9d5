"""Flag a template that repeats what the library already has (warnings, never refusals).

In: a template, its parsed conditions and the library (every template, any status). Out:
warnings: its hazard class already covered by active templates (binding will apply them
together), a class no template has had yet (the symbolic analyzer only proposes the taxonomy's
classes), a category that differs from the class's other templates, and conditions identical
(after canonical rendering) to a condition of another template. Fails: never.
"""

from __future__ import annotations

from collections.abc import Sequence

from app.domain.errors import FormulaError
from app.domain.formula import parse, render
from app.domain.models import HazardTemplate, TemplateStatus
from app.domain.template_validation.conditions import ParsedCondition
from app.domain.template_validation.issues import BODY, TemplateIssue


def _canonical(text: str) -> str | None:
    try:
        return render(parse(text))
    except FormulaError:
        return None


def _class_warnings(
    template: HazardTemplate, library: Sequence[HazardTemplate]
) -> list[TemplateIssue]:
    field = f"{BODY}.hazard_class"
    if library and all(t.hazard_class != template.hazard_class for t in library):
        return [TemplateIssue(
            field, f"no template has hazard class {template.hazard_class!r} yet; the symbolic "
            "analyzer only proposes the taxonomy's classes (templates_db/README.md)", "new_class")]
    same_class = [
        t for t in library if t.hazard_class == template.hazard_class and t.id != template.id
    ]
    warnings: list[TemplateIssue] = []
    active = [t.id for t in same_class if t.status is TemplateStatus.ACTIVE]
    if active:
        warnings.append(TemplateIssue(
            field, f"hazard class {template.hazard_class!r} is already covered by active "
            f"templates {', '.join(active)}; binding applies this one together with them",
            "duplicate_class"))
    categories = sorted({t.category.value for t in same_class})
    if categories and template.category.value not in categories:
        warnings.append(TemplateIssue(
            f"{BODY}.category", f"other templates of {template.hazard_class!r} are "
            f"{', '.join(categories)}, not {template.category.value}", "category"))
    return warnings


def duplicate_warnings(
    template: HazardTemplate,
    parsed: Sequence[ParsedCondition],
    library: Sequence[HazardTemplate],
) -> list[TemplateIssue]:
    """Warnings for a template that duplicates the library.

    Args:
        template: the candidate.
        parsed: its well-formed conditions.
        library: the stored templates; a template with the candidate's own id is ignored (a
            revision does not duplicate itself).

    Returns:
        The warnings, class-level first.
    """
    others = [t for t in library if t.id != template.id]
    warnings = _class_warnings(template, library)
    seen: dict[str, str] = {}
    for other in others:
        for _, condition in other.conditions():
            canonical = _canonical(condition.formula)
            if canonical is not None:
                seen.setdefault(canonical, f"{other.id}:{condition.id}")
    for item in parsed:
        match = seen.get(render(item.formula))
        if match is not None:
            warnings.append(TemplateIssue(
                item.field, f"{item.kind.value} {item.condition.id!r} repeats {match}",
                "duplicate_condition"))
    return warnings
