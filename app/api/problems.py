"""RFC 9457 problem+json: the one place where errors become HTTP answers.

In: exceptions from the domain tree (`app.domain.errors`), request validation errors, and anything
unexpected. Out: `application/problem+json` bodies with `type`, `title`, `status`, `detail` and,
for invalid input, `errors`: each with the offending field's path (e.g. `body.scene.objects.0.id`),
and where known a line/column or plan step. `Busy` (the analysis pool is full) is a 503 with a
`Retry-After` header. Unexpected exceptions are 500s with no internals. `Problem` is the body's
schema, which the OpenAPI document declares for every error status (`app/api/openapi.py`).
"""

from __future__ import annotations

import logging
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from fastapi.routing import iter_route_contexts
from pydantic import BaseModel, ConfigDict, Field
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.routing import Match

from app.domain import errors

PROBLEM_JSON = "application/problem+json"
_log = logging.getLogger("safegate.problems")

_STATUS: list[tuple[type[errors.SafeGateError], int]] = [
    (errors.InvalidInput, 422),
    (errors.NotFound, 404),
    (errors.Conflict, 409),
    (errors.Forbidden, 403),
    (errors.Unauthorized, 401),
    (errors.Unavailable, 503),
]


class ProblemField(BaseModel):
    """One thing wrong with the input: where it is, and why."""

    model_config = ConfigDict(extra="allow")

    field: str = Field(description="The offending place, from the top of the request, e.g. "
                                   "`body.scene.objects.0.properties.mass_kg` or `plan[3]`.")
    message: str = Field(description="What is wrong with it, in words.")
    type: str | None = Field(default=None, description="A machine-readable kind of problem "
                                                       "(`missing`, `literal_error`...).")


class Problem(BaseModel):
    """An RFC 9457 problem: every error SafeGate answers has this body, as
    `application/problem+json`. More members may follow the ones listed (`limit`, `step`,
    `warnings`...)."""

    model_config = ConfigDict(extra="allow", json_schema_extra={"examples": [{
        "type": "https://safegate.dev/problems/validation", "title": "Invalid request",
        "status": 422,
        "detail": "the request does not fit the expected shape at: "
                  "body.scene.objects.0.properties.mass_kg",
        "errors": [{"field": "body.scene.objects.0.properties.mass_kg",
                    "message": "Input should be greater than or equal to 0",
                    "type": "greater_than_equal"}]}]})

    type: str = Field(description="A URI naming the kind of problem (`about:blank` when the "
                                  "HTTP status says it all).")
    title: str = Field(description="A short summary of the kind of problem.")
    status: int = Field(description="The HTTP status code, repeated.")
    detail: str = Field(description="What went wrong with this request.")
    errors: list[ProblemField] | None = Field(
        default=None, description="For invalid input: every offending field.")


def problem(
    status: int, title: str, detail: str, *, type_: str = "about:blank",
    headers: dict[str, str] | None = None, **extra: Any
) -> JSONResponse:
    """Build a problem+json response."""
    body: dict[str, Any] = {"type": type_, "title": title, "status": status, "detail": detail}
    body.update({k: v for k, v in extra.items() if v is not None})
    return JSONResponse(body, status_code=status, media_type=PROBLEM_JSON, headers=headers)


def status_for(error: errors.SafeGateError) -> int:
    for cls, status in _STATUS:
        if isinstance(error, cls):
            return status
    return 500


def _slug(error: errors.SafeGateError) -> str:
    return "https://safegate.dev/problems/" + type(error).__name__.lower()


async def _domain_error(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, errors.SafeGateError)
    status = status_for(exc)
    extra: dict[str, Any] = dict(exc.extra)
    if exc.field is not None:
        extra["errors"] = [{"field": exc.field, "message": exc.detail, **exc.extra}]
    headers = ({"Retry-After": str(exc.retry_after)} if isinstance(exc, errors.Busy)
               else None)
    return problem(status, exc.title, exc.detail, type_=_slug(exc), headers=headers, **extra)


async def _validation_error(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestValidationError)
    problems = [
        {
            "field": ".".join(str(part) for part in item.get("loc", ())),
            "message": item.get("msg", "invalid"),
            "type": item.get("type", "value_error"),
        }
        for item in exc.errors()
    ]
    fields = ", ".join(p["field"] for p in problems[:5])
    return problem(
        422,
        "Invalid request",
        f"the request does not fit the expected shape at: {fields}",
        type_="https://safegate.dev/problems/validation",
        errors=problems,
    )


# FastAPI's answer to a body it could not decode at all (not UTF-8, nested past Python's
# recursion limit, an integer with thousands of digits): invalid input like any other, so 422.
_UNPARSABLE_BODY = "There was an error parsing the body"


def _allowed_methods(request: Request) -> str:
    """Every method the path's routes serve: Starlette's 405 names only the first route's,
    though several may share a path (`GET` and `POST /keys`). A path some route spells out
    (`/keys/me`) is that route's alone, as the OpenAPI document says, not also `{key_id}`'s."""
    scope = {**request.scope, "method": ""}
    # Routes of included routers sit inside them; `iter_route_contexts` reaches each one.
    matching = [route for route in iter_route_contexts(request.app.routes)
                if route.matches(scope)[0] is not Match.NONE]
    literal = [route for route in matching if route.path == request.url.path]
    methods = {method for route in literal or matching for method in route.methods or ()}
    return ", ".join(sorted(methods))


async def _http_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, StarletteHTTPException)
    headers = dict(exc.headers) if exc.headers else None
    if exc.status_code == 405:
        headers = {**(headers or {}), "Allow": _allowed_methods(request)}
    if exc.status_code == 400 and exc.detail == _UNPARSABLE_BODY:
        return problem(
            422,
            "Invalid request",
            "the body is not decodable JSON (bad encoding, too deeply nested, or a number "
            "too long)",
            type_="https://safegate.dev/problems/validation",
            errors=[{"field": "body", "message": "the body could not be decoded as JSON",
                     "type": "json_invalid"}],
        )
    return problem(exc.status_code, str(exc.detail), str(exc.detail), headers=headers)


async def _unexpected(_: Request, exc: Exception) -> JSONResponse:
    _log.exception("unhandled error", exc_info=exc)
    return problem(500, "Internal error", "SafeGate could not process this request")


def install(app: FastAPI) -> None:
    """Register the handlers on an app."""
    app.add_exception_handler(errors.SafeGateError, _domain_error)
    app.add_exception_handler(RequestValidationError, _validation_error)
    app.add_exception_handler(StarletteHTTPException, _http_error)
    app.add_exception_handler(Exception, _unexpected)
