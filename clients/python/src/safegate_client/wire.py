"""What the HTTP clients share: request bodies out, typed answers in.

In: requests as the SDK's models (`GateRequest`, `InitialState`, `Action`...) or JSON-shaped
mappings; httpx responses. Out: JSON bodies (a model is sent by its wire names, with exactly the
fields that were set: an explicit null stays null, a field left out stays out, which SafeGate
reads as "unknown"), and answers validated into the model the route promises.
Fails: `ApiError` for an error status; `UnexpectedAnswer` for a 2xx answer that is not JSON or
not of the model's shape (a newer server's unknown decision, say): never read as a decision.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, TypeVar

import httpx
from pydantic import BaseModel, ValidationError

from safegate_client.errors import ApiError, SafeGateUnavailable, UnexpectedAnswer

JsonObject = dict[str, Any]
Body = Mapping[str, Any] | BaseModel
Answer = TypeVar("Answer", bound=BaseModel)


def auth_headers(api_key: str | None) -> dict[str, str]:
    """The headers that present an API key (none when there is no key)."""
    return {} if api_key is None else {"Authorization": f"Bearer {api_key}"}


def as_json(body: Body) -> JsonObject:
    """A request body as JSON: a model by its wire names and set fields, or the mapping."""
    if isinstance(body, BaseModel):
        dumped: JsonObject = body.model_dump(mode="json", by_alias=True, exclude_unset=True)
        return dumped
    return dict(body)


def json_of(response: httpx.Response) -> Any:
    """The JSON body of a 2xx response.

    Raises:
        ApiError: an error status, with its problem+json body (or the raw text as `detail`).
        UnexpectedAnswer: a 2xx body that is not JSON.
    """
    if response.is_error:
        try:
            problem = response.json()
        except ValueError:
            problem = {"detail": response.text}
        raise ApiError(response.status_code,
                       problem if isinstance(problem, dict) else {"detail": problem})
    try:
        return response.json()
    except ValueError as error:
        raise UnexpectedAnswer(f"{response.request.method} {response.request.url.path}: "
                               f"the answer is not JSON: {response.text[:200]!r}") from error


def read(response: httpx.Response, model: type[Answer]) -> Answer:
    """A 2xx answer as `model`.

    Raises:
        ApiError: an error status.
        UnexpectedAnswer: the answer is not JSON of `model`'s shape.
    """
    body = json_of(response)
    try:
        return model.model_validate(body)
    except ValidationError as error:
        raise UnexpectedAnswer(f"{response.request.method} {response.request.url.path}: the "
                               f"answer is not a {model.__name__}: {error}") from error


def text_of(response: httpx.Response) -> str:
    """A 2xx answer's text (raises `ApiError` for an error status)."""
    if response.is_error:
        json_of(response)
    return response.text


def verify_body(contract_id: str, plan: Sequence[Body],
                initial_state: Body | None) -> JsonObject:
    """The `POST /verify` body."""
    body: JsonObject = {"contract_id": contract_id, "plan": [as_json(a) for a in plan]}
    if initial_state is not None:
        body["initial_state"] = as_json(initial_state)
    return body


def monitor_body(contract_id: str, initial_state: Body | None) -> JsonObject:
    """The `POST /monitor` body."""
    body: JsonObject = {"contract_id": contract_id}
    if initial_state is not None:
        body["initial_state"] = as_json(initial_state)
    return body


def unavailable(method: str, path: str, error: httpx.TransportError) -> SafeGateUnavailable:
    """The error for a request that never got an answer."""
    return SafeGateUnavailable(f"{method} {path}: SafeGate could not be reached ({error!r}); "
                               "nothing was decided")
