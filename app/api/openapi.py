"""The OpenAPI document: FastAPI's, completed with what FastAPI cannot see.

In: the app's routes, each declaring the errors only it can answer (403, 404, 409, 503) with
`problem_responses`. Out: the schema served at `/openapi.json` (`install` makes `app.openapi()`
build it), in which
- every error status is `application/problem+json` with the `Problem` schema of
  `app/api/problems.py`; the statuses every route of a kind can answer are added here, from
  what causes them: 401 wherever the key check runs, 413 and 422 wherever a body is taken, 422
  wherever there are parameters;
- FastAPI's default 422 (`HTTPValidationError`, `application/json`), which SafeGate never sends,
  is gone;
- the probes carry no security requirement (they never need a key);
- the two websockets, which OpenAPI cannot describe, are pointed to in `docs/api/`.
Fails: never once built; the document is built on first use and cached on the app.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from fastapi import FastAPI
from fastapi.openapi.utils import get_openapi

from app.api.auth import is_open_path
from app.api.problems import PROBLEM_JSON, Problem

_REF = "#/components/schemas/"
_ERROR_MEANINGS: dict[int, str] = {
    401: "No API key where one is needed (every route with `SAFEGATE_AUTH=keys`; template "
         "writes and `/keys` always), or a key that is unknown, revoked or malformed.",
    403: "The key's role may not do this (e.g. a curator key on `POST /gate`).",
    404: "Nothing has this id.",
    409: "Refused in the current state.",
    413: "The body is larger than `SAFEGATE_MAX_BODY_BYTES`.",
    422: "The input does not fit: `errors` names every offending field; nothing was stored.",
    503: "A dependency failed (database, solver, LLM, an analysis worker), or the analysis "
         "workers and their queue are full (then with `Retry-After`). Never a decision.",
}
_RETRY_AFTER = {"Retry-After": {
    "description": "Seconds to wait before retrying (when the analysis workers are full).",
    "schema": {"type": "integer"}}}

DESCRIPTION = """\
SafeGate decides whether a robot may carry out a natural-language command (`POST /gate`), gives
an authorized task its Task Safety Contract (`GET /contracts/{id}`), checks plans against it
before anything moves (`POST /verify`) and monitors the run action by action (`POST /monitor`,
then the websocket `/monitor/{session_id}`).

A rejection or a failed verification is a `200` with its reasons; an error status means SafeGate
could not decide, and its body is always `application/problem+json`.

The two websockets are described in AsyncAPI (`docs/api/asyncapi.yaml`); the wire formats, with
worked examples, in `docs/api/`.
"""

TAGS: list[dict[str, Any]] = [
    {"name": "gate", "description": "Decide a command: authorize, defer or reject, with the "
                                    "rule and the hazards behind it; the audit trail."},
    {"name": "contracts", "description": "The Task Safety Contract of an authorized request."},
    {"name": "verify", "description": "Stage 5: a plan checked against its contract with Z3."},
    {"name": "monitor", "description": "Stage 6: runtime monitoring sessions. The runtime's "
                                       "websocket `/monitor/{session_id}` and the listeners' "
                                       "`/monitor/{session_id}/events` are in "
                                       "`docs/api/asyncapi.yaml`."},
    {"name": "templates", "description": "The Hazard Template Library: browse, validate, "
                                         "write, activate."},
    {"name": "extensions", "description": "Requests waiting for the library to grow, and "
                                          "deciding them again."},
    {"name": "vocabulary", "description": "The condition language and the action model."},
    {"name": "keys", "description": "API keys (admin)."},
    {"name": "health", "description": "Liveness and readiness probes (never need a key)."},
]


def _problem(status: int, meaning: str | None = None) -> dict[str, Any]:
    response: dict[str, Any] = {
        "description": meaning or _ERROR_MEANINGS[status],
        "content": {PROBLEM_JSON: {"schema": {"$ref": _REF + "Problem"}}},
    }
    if status == 503:
        response["headers"] = dict(_RETRY_AFTER)
    return response


def problem_responses(*statuses: int | tuple[int, str]) -> dict[int | str, dict[str, Any]]:
    """Error answers for a route's `responses=`, each a problem+json.

    Args:
        statuses: status codes, or (status, what it means on this route) pairs.

    Returns:
        The `responses` mapping FastAPI takes.
    """
    responses: dict[int | str, dict[str, Any]] = {}
    for item in statuses:
        status, meaning = item if isinstance(item, tuple) else (item, None)
        responses[status] = _problem(status, meaning)
    return responses


def _complete_operation(path: str, operation: dict[str, Any]) -> None:
    responses: dict[str, Any] = operation.setdefault("responses", {})
    implied: list[int] = []
    if is_open_path(path):
        operation.pop("security", None)
    elif "security" in operation:
        implied.append(401)
    if "requestBody" in operation:
        implied += [413, 422]
    if operation.get("parameters"):
        implied.append(422)
    for status in implied:
        responses.setdefault(str(status), _problem(status))
    for code, response in responses.items():
        content = response.get("content", {})
        if code.startswith(("4", "5")) and PROBLEM_JSON not in content:
            # FastAPI's default 422 (or any other error declared as plain JSON).
            response["content"] = {PROBLEM_JSON: {"schema": {"$ref": _REF + "Problem"}}}
            response["description"] = _ERROR_MEANINGS.get(int(code), response["description"])


def _add_problem_schemas(components: dict[str, Any]) -> None:
    schemas: dict[str, Any] = components.setdefault("schemas", {})
    problem = Problem.model_json_schema(ref_template=_REF + "{model}")
    schemas.update(problem.pop("$defs", {}))
    schemas["Problem"] = problem
    for unused in ("HTTPValidationError", "ValidationError"):
        schemas.pop(unused, None)


def build(app: FastAPI) -> dict[str, Any]:
    """The app's OpenAPI document, built once and cached on the app."""
    if app.openapi_schema is not None:
        return app.openapi_schema
    document = get_openapi(title=app.title, version=app.version, summary=app.summary,
                           description=DESCRIPTION, routes=app.routes, tags=TAGS)
    for path, operations in document.get("paths", {}).items():
        for operation in _operations(operations):
            _complete_operation(path, operation)
    _add_problem_schemas(document.setdefault("components", {}))
    app.openapi_schema = document
    return document


def _operations(path_item: dict[str, Any]) -> Iterable[dict[str, Any]]:
    return (value for key, value in path_item.items()
            if key in ("get", "put", "post", "delete", "patch", "head", "options"))


def install(app: FastAPI) -> None:
    """Make `app.openapi()` (and so `/openapi.json`) answer the completed document."""
    app.openapi = lambda: build(app)  # type: ignore[method-assign]
