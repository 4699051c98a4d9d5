"""`GateClient`: the planner's side of SafeGate over HTTP (httpx); `AsyncGateClient` is the same
for asyncio (`app/client/gate_async.py`).

In: a base URL (e.g. `http://127.0.0.1:8000`), an optional API key, and requests as the
service's own models (`GateRequest`, `InitialState` from `app.domain.models`, which need only
pydantic) or as JSON-shaped mappings (`docs/api/gate.md`, `docs/api/plans-and-verify.md`).
Out: the decoded JSON answers as dicts. Fails: `ApiError` for an error status (with the
problem+json body), `SafeGateUnavailable` when SafeGate could not be reached or stayed busy
through every retry (`RetryPolicy`: connection failures, timeouts, 502/503/504, honouring
`Retry-After`). A rejection or a failed verification is an answer, not an error: inspect
`decision` / `ok`. No failure is ever returned as a decision.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from types import TracebackType
from typing import Any

import httpx
from pydantic import BaseModel

from app.client.errors import ApiError, SafeGateUnavailable
from app.client.retry import RetryPolicy

JsonObject = dict[str, Any]
Body = Mapping[str, Any] | BaseModel


def auth_headers(api_key: str | None) -> dict[str, str]:
    """The headers that present an API key (none when there is no key)."""
    return {} if api_key is None else {"Authorization": f"Bearer {api_key}"}


def as_json(body: Body) -> JsonObject:
    """A request body as JSON: a service model by its wire names, or the mapping as given."""
    if isinstance(body, BaseModel):
        dumped: JsonObject = body.model_dump(mode="json", by_alias=True, exclude_none=True)
        return dumped
    return dict(body)


def decode(response: httpx.Response) -> JsonObject:
    """The JSON answer of a 2xx response.

    Raises:
        ApiError: an error status, with its problem+json body (or the raw text as `detail`).
    """
    if response.is_error:
        try:
            problem = response.json()
        except ValueError:
            problem = {"detail": response.text}
        raise ApiError(response.status_code,
                       problem if isinstance(problem, dict) else {"detail": problem})
    body: JsonObject = response.json()
    return body


def verify_body(contract_id: str, plan: Sequence[Mapping[str, Any]],
                initial_state: Body | None) -> JsonObject:
    """The `POST /verify` body."""
    body: JsonObject = {"contract_id": contract_id, "plan": [dict(a) for a in plan]}
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
    return SafeGateUnavailable(f"{method} {path}: SafeGate could not be reached ({error!r}); "
                               "nothing was decided")


class GateClient:
    """A synchronous SafeGate client for planners; use it as a context manager."""

    def __init__(self, base_url: str = "http://127.0.0.1:8000", *, api_key: str | None = None,
                 timeout: float = 30.0, retry: RetryPolicy | None = None,
                 transport: httpx.BaseTransport | None = None) -> None:
        """Connect lazily to a SafeGate server.

        Args:
            base_url: where SafeGate listens.
            api_key: a robot (or admin) key, when the server runs with `auth=keys`.
            timeout: seconds per attempt.
            retry: when to try again (default `RetryPolicy()`: 3 attempts).
            transport: an httpx transport (tests may pass one).
        """
        self.base_url = base_url.rstrip("/")
        self.api_key = api_key
        self.retry = retry or RetryPolicy()
        self._http = httpx.Client(base_url=self.base_url, headers=auth_headers(api_key),
                                  timeout=timeout, transport=transport)

    def __enter__(self) -> GateClient:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        self.close()

    def close(self) -> None:
        """Close the connection pool."""
        self._http.close()

    def _send(self, method: str, path: str, **options: Any) -> httpx.Response:
        attempt = 1
        while True:
            outcome: httpx.Response | httpx.TransportError
            try:
                outcome = self._http.request(method, path, **options)
            except httpx.TransportError as error:
                outcome = error
            if not self.retry.retries(attempt, outcome):
                if isinstance(outcome, httpx.TransportError):
                    raise unavailable(method, path, outcome) from outcome
                return outcome
            time.sleep(self.retry.wait(attempt, outcome))
            attempt += 1

    def gate(self, request: Body, *, reference_plan: bool = False) -> JsonObject:
        """Ask whether a command may run: `POST /gate`.

        Args:
            request: a `GateRequest`, or `{"command": ..., "scene": ..., "user": ...,
                "robot": ...}`.
            reference_plan: also ask, on an authorize, for a plan proved to keep the contract
                (`reference_plan`, or null and `reference_plan_reason`).

        Returns:
            The decision: `decision` (authorize/defer/reject), `rule`, `question`, `hazards`,
            `unknowns`, `contract_id` (when authorized), `request_id`...
        """
        params = {"reference_plan": "true"} if reference_plan else None
        return decode(self._send("POST", "/gate", json=as_json(request), params=params))

    def answer(self, request_id: str, answers: Mapping[str, Any]) -> JsonObject:
        """Answer a deferred request's question: `POST /gate/{id}/answers` (a new decision)."""
        return decode(self._send("POST", f"/gate/{request_id}/answers", json=dict(answers)))

    def decision(self, request_id: str) -> JsonObject:
        """A stored decision with the decisions that followed it: `GET /gate/{id}`."""
        return decode(self._send("GET", f"/gate/{request_id}"))

    def contract(self, contract_id: str) -> JsonObject:
        """The Task Safety Contract (invariants, guards, aborts): `GET /contracts/{id}`."""
        return decode(self._send("GET", f"/contracts/{contract_id}"))

    def planner_constraints(self, contract_id: str) -> str:
        """The contract as plain constraints for a planner's prompt."""
        response = self._send("GET", f"/contracts/{contract_id}",
                              params={"format": "planner"})
        if response.is_error:
            decode(response)
        return response.text

    def verify(self, contract_id: str, plan: Sequence[Mapping[str, Any]],
               initial_state: Body | None = None) -> JsonObject:
        """Check a plan against its contract before anything moves: `POST /verify`.

        Args:
            contract_id: the contract of the authorized request.
            plan: the actions, e.g. `[{"action": "PickupObject", "object": "mug_1"}, ...]`.
            initial_state: an `InitialState` or `{"scene": ..., "robot": ...}`; default: the
                gate request's.

        Returns:
            `ok`, `violations` (step, action, kind, condition_id, formula, counterexample),
            `attempts`, `attempts_left`, `decision`; for a failed plan `repair` (the nearest plan
            proved to pass, or null and `repair_reason`).
        """
        return decode(self._send("POST", "/verify",
                                 json=verify_body(contract_id, plan, initial_state)))

    def open_monitor(self, contract_id: str, initial_state: Body | None = None) -> str:
        """Open a runtime monitoring session: `POST /monitor`; returns the session id."""
        answer = decode(self._send("POST", "/monitor",
                                   json=monitor_body(contract_id, initial_state)))
        session_id: str = answer["session_id"]
        return session_id

    def monitor_summary(self, session_id: str) -> JsonObject:
        """The session's MonitorSummary: `GET /monitor/{id}/summary`."""
        return decode(self._send("GET", f"/monitor/{session_id}/summary"))
