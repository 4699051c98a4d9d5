"""What template validation reports: issues (errors or warnings) that point at a field.

In: built by the validation steps. Out: `TemplateIssue` values, each naming the offending field as
a dotted path (`body.invariants.0.formula`), what is wrong, a stable `code`, and for conditions
the 1-based line and column inside the formula; `TemplateValidation` gathers them with the parsed
template. Fails: never.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from app.domain.models import HazardTemplate

BODY = "body"


@dataclass(frozen=True, slots=True)
class TemplateIssue:
    """One problem found in a template document.

    Attributes:
        field: dotted path of the offending field, e.g. `body.guards.1.formula`.
        message: what is wrong, in words a curator can act on.
        code: a stable machine-readable kind (`schema`, `syntax`, `type`, `contradiction`...).
        line: line inside the condition's formula (1-based), when the issue is in a formula.
        column: column inside that line (1-based), when the issue is in a formula.
    """

    field: str
    message: str
    code: str
    line: int | None = None
    column: int | None = None

    def as_dict(self) -> dict[str, Any]:
        """The issue as JSON (the position keys only when known)."""
        body: dict[str, Any] = {"field": self.field, "message": self.message, "code": self.code}
        if self.line is not None:
            body["line"] = self.line
            body["column"] = self.column
        return body


@dataclass(frozen=True, slots=True)
class TemplateValidation:
    """The verdict on one template document.

    Attributes:
        template: the parsed template when the schema held (even if later checks failed).
        errors: problems that forbid storing the template.
        warnings: problems worth a look that do not forbid it (duplicates, unused variables).
    """

    template: HazardTemplate | None
    errors: tuple[TemplateIssue, ...] = ()
    warnings: tuple[TemplateIssue, ...] = ()

    @property
    def ok(self) -> bool:
        """True when the template may be stored."""
        return self.template is not None and not self.errors

    def as_dict(self) -> dict[str, Any]:
        """The verdict as JSON: `valid`, `errors`, `warnings`."""
        return {
            "valid": self.ok,
            "errors": [issue.as_dict() for issue in self.errors],
            "warnings": [issue.as_dict() for issue in self.warnings],
        }


def condition_field(kind: str, index: int, part: str = "formula") -> str:
    """The path of one condition's part, e.g. `body.aborts.0.formula` for kind `abort`."""
    return f"{BODY}.{kind}s.{index}.{part}"
