"""Each condition of a template parses and type-checks against the vocabulary.

In: a `HazardTemplate`. Out: the parsed formula of every condition (keyed by kind and position)
and an issue for every condition that fails, carrying the line and column inside the formula the
parser or checker reported: a syntax error, a predicate not in the vocabulary, a wrong arity or
argument type, an undeclared `$variable`, `@object` outside a guard. Fails: never (every
`FormulaError` becomes an issue).
"""

from __future__ import annotations

from dataclasses import dataclass

from app.domain.errors import FormulaError
from app.domain.formula import Formula, check, parse
from app.domain.models import ConditionKind, HazardTemplate, TemplateCondition
from app.domain.template_validation.issues import TemplateIssue, condition_field


@dataclass(frozen=True, slots=True)
class ParsedCondition:
    """One condition with where it sits in the document and its checked formula."""

    kind: ConditionKind
    index: int
    condition: TemplateCondition
    formula: Formula

    @property
    def field(self) -> str:
        """The path of the condition's formula in the document."""
        return condition_field(self.kind.value, self.index)


def variable_types(template: HazardTemplate) -> dict[str, str]:
    """The template's variables, name to type name."""
    return {variable.name: variable.type.value for variable in template.variables}


def _issue(error: FormulaError, field: str, code: str) -> TemplateIssue:
    return TemplateIssue(field, error.detail, code, line=error.line, column=error.column)


def parse_conditions(
    template: HazardTemplate,
) -> tuple[list[ParsedCondition], list[TemplateIssue]]:
    """Parse and type-check every condition.

    Args:
        template: a template that passed the schema.

    Returns:
        The conditions that are well formed, and an issue per condition that is not.
    """
    variables = variable_types(template)
    parsed: list[ParsedCondition] = []
    issues: list[TemplateIssue] = []
    positions: dict[ConditionKind, int] = {}
    for kind, condition in template.conditions():
        index = positions.get(kind, 0)
        positions[kind] = index + 1
        field = condition_field(kind.value, index)
        try:
            formula = parse(condition.formula)
        except FormulaError as error:
            issues.append(_issue(error, field, "syntax"))
            continue
        try:
            check(formula, variables, allow_action_args=kind is ConditionKind.GUARD)
        except FormulaError as error:
            issues.append(_issue(error, field, "type"))
            continue
        parsed.append(ParsedCondition(kind, index, condition, formula))
    return parsed, issues
