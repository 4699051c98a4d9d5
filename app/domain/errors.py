"""One exception tree for SafeGate. Verdicts are data; an exception means "could not decide".

SafeGateError
├── InvalidInput            the caller sent something we cannot use (API: 422)
│   ├── FormulaError        a condition does not parse or type-check (carries line/column)
│   ├── PlanError           a plan step names an unknown action or object (carries the step)
│   └── TemplateInvalid     a template fails validation (carries the field path)
├── NotFound                a request, template, contract or session id that does not exist (404)
├── Conflict                the operation is refused in the current state (409)
│   └── AttemptsExhausted   a contract has used up its verification attempts
├── Unauthorized            no valid API key where one is required (401)
├── Forbidden               the caller's key lacks the role (403)
└── Unavailable             a dependency failed: database, solver, LLM (503); never an authorize
    └── Busy                the analysis workers and their queue are full (503 + Retry-After)

No HTTP status codes here: `app/api/problems.py` maps each class to one. Every error pickles
whole (detail, field, extras), so one raised in an analysis worker process reaches the caller as
it was raised.
"""

from __future__ import annotations


class SafeGateError(Exception):
    """Root of every error SafeGate raises on purpose."""

    title = "SafeGate error"

    def __init__(self, detail: str, *, field: str | None = None, **extra: object) -> None:
        super().__init__(detail)
        self.detail = detail
        self.field = field
        self.extra = extra

    def __reduce__(self) -> tuple[object, ...]:
        # The default rebuilds with `cls(*args)`, which loses `field` and `extra` and fails for
        # subclasses with required keyword arguments (PlanError's `step`).
        return _rebuild, (type(self), self.args, self.__dict__)


def _rebuild(cls: type[SafeGateError], args: tuple[object, ...],
             state: dict[str, object]) -> SafeGateError:
    error = cls.__new__(cls)
    error.args = args
    error.__dict__.update(state)
    return error


class InvalidInput(SafeGateError):
    title = "Invalid input"


class FormulaError(InvalidInput):
    """A condition that does not parse or does not type-check."""

    title = "Invalid condition"

    def __init__(
        self,
        detail: str,
        *,
        line: int | None = None,
        column: int | None = None,
        field: str | None = None,
    ) -> None:
        super().__init__(detail, field=field, line=line, column=column)
        self.line = line
        self.column = column


class PlanError(InvalidInput):
    title = "Invalid plan"

    def __init__(self, detail: str, *, step: int, field: str | None = None) -> None:
        super().__init__(detail, field=field or f"plan[{step}]", step=step)
        self.step = step


class TemplateInvalid(InvalidInput):
    title = "Invalid template"


class NotFound(SafeGateError):
    title = "Not found"


class Conflict(SafeGateError):
    title = "Conflict"


class AttemptsExhausted(Conflict):
    title = "Verification attempts exhausted"


class Unauthorized(SafeGateError):
    title = "Unauthorized"


class Forbidden(SafeGateError):
    title = "Forbidden"


class Unavailable(SafeGateError):
    title = "Dependency unavailable"


class Busy(Unavailable):
    """Too much work is queued already; the caller should retry after `retry_after` seconds."""

    title = "Busy"

    def __init__(self, detail: str, *, retry_after: int) -> None:
        super().__init__(detail, retry_after=retry_after)
        self.retry_after = retry_after
