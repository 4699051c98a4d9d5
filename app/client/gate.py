"""`GateClient`: the planner's side of SafeGate over HTTP (httpx).

In: a base URL (e.g. `http://127.0.0.1:8000`), an optional API key, and JSON-shaped requests
(`shared/spec/gate-request.md`, `shared/spec/plans-and-monitoring.md`). Out: the decoded JSON
answers as dicts. Fails: `ApiError` for an error status (with the problem+json body), httpx's
own exceptions for transport failures. A rejection or a failed verification is an answer, not an
error: inspect `decision` / `ok`.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import TracebackType
from typing import Any

import httpx

from app.client.errors import ApiError

JsonObject = dict[str, Any]


def auth_headers(api_key: str | None) -> dict[str, str]:
    """The headers that present an API key (none when there is no key)."""
    return {} if api_key is None else {"Authorization": f"Bearer {api_key}"}


class GateClient:
    """A synchronous SafeGate client for planners; use it as a context manager."""

    def __init__(self, base_url: str = "http://127.0.0.1:8000", *, api_key: str | None = None,
                 timeout: float = 30.0, transport: httpx.BaseTransport | None = None) -> None:
        """Connect lazily to a SafeGate server.

        Args:
            base_url: where SafeGate listens.
            api_key: a robot (or admin) key, when the server runs with `auth=keys`.
            timeout: seconds per request.
            transport: an httpx transport (tests may pass one).
        """
        self.base_url = base_url.rstrip("/")
        self.api_key = api_key
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

    def _json(self, response: httpx.Response) -> JsonObject:
        if response.is_error:
            try:
                problem = response.json()
            except ValueError:
                problem = {"detail": response.text}
            raise ApiError(response.status_code,
                           problem if isinstance(problem, dict) else {"detail": problem})
        body: JsonObject = response.json()
        return body

    def gate(self, request: Mapping[str, Any], *, reference_plan: bool = False) -> JsonObject:
        """Ask whether a command may run: `POST /gate`.

        Args:
            request: `{"command": ..., "scene": ..., "user": ..., "robot": ...}`.
            reference_plan: also ask, on an authorize, for a plan proved to keep the contract
                (`reference_plan`, or null and `reference_plan_reason`).

        Returns:
            The decision: `decision` (authorize/defer/reject), `rule`, `question`, `hazards`,
            `unknowns`, `contract_id` (when authorized), `request_id`...
        """
        params = {"reference_plan": "true"} if reference_plan else None
        return self._json(self._http.post("/gate", json=dict(request), params=params))

    def answer(self, request_id: str, answers: Mapping[str, Any]) -> JsonObject:
        """Answer a deferred request's question: `POST /gate/{id}/answers` (a new decision)."""
        return self._json(self._http.post(f"/gate/{request_id}/answers", json=dict(answers)))

    def decision(self, request_id: str) -> JsonObject:
        """A stored decision with the decisions that followed it: `GET /gate/{id}`."""
        return self._json(self._http.get(f"/gate/{request_id}"))

    def contract(self, contract_id: str) -> JsonObject:
        """The Task Safety Contract (invariants, guards, aborts): `GET /contracts/{id}`."""
        return self._json(self._http.get(f"/contracts/{contract_id}"))

    def planner_constraints(self, contract_id: str) -> str:
        """The contract as plain constraints for a planner's prompt."""
        response = self._http.get(f"/contracts/{contract_id}", params={"format": "planner"})
        if response.is_error:
            self._json(response)
        return response.text

    def verify(self, contract_id: str, plan: Sequence[Mapping[str, Any]],
               initial_state: Mapping[str, Any] | None = None) -> JsonObject:
        """Check a plan against its contract before anything moves: `POST /verify`.

        Args:
            contract_id: the contract of the authorized request.
            plan: the actions, e.g. `[{"action": "PickupObject", "object": "mug_1"}, ...]`.
            initial_state: `{"scene": ..., "robot": ...}`; default: the gate request's.

        Returns:
            `ok`, `violations` (step, action, kind, condition_id, formula, counterexample),
            `attempts`, `attempts_left`, `decision`; for a failed plan `repair` (the nearest plan
            proved to pass, or null and `repair_reason`).
        """
        body: JsonObject = {"contract_id": contract_id, "plan": [dict(a) for a in plan]}
        if initial_state is not None:
            body["initial_state"] = dict(initial_state)
        return self._json(self._http.post("/verify", json=body))

    def open_monitor(self, contract_id: str,
                     initial_state: Mapping[str, Any] | None = None) -> str:
        """Open a runtime monitoring session: `POST /monitor`; returns the session id."""
        body: JsonObject = {"contract_id": contract_id}
        if initial_state is not None:
            body["initial_state"] = dict(initial_state)
        session_id: str = self._json(self._http.post("/monitor", json=body))["session_id"]
        return session_id

    def monitor_summary(self, session_id: str) -> JsonObject:
        """The session's MonitorSummary: `GET /monitor/{id}/summary`."""
        return self._json(self._http.get(f"/monitor/{session_id}/summary"))
