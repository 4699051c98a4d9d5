"""`GateClient`: the planner's side of SafeGate over HTTP (httpx); `AsyncGateClient`
(`safegate_client/gate_async.py`) is the same for asyncio.

In: a base URL (e.g. `http://127.0.0.1:8000`), an optional API key, and requests as the SDK's
models (`GateRequest`, `InitialState`, `Action`) or JSON-shaped mappings (`docs/api/gate.md`,
`docs/api/plans-and-verify.md`). Out: typed answers (`GateResponse`, `ContractResponse`,
`VerifyResponse`, `MonitorSummaryResponse`). Fails: `ApiError` for an error status (with the
problem+json body), `UnexpectedAnswer` for an answer not of the promised shape,
`SafeGateUnavailable` when SafeGate could not be reached or stayed busy through every retry
(`RetryPolicy`: connection failures, timeouts, 502/503/504, honouring `Retry-After`). A
rejection or a failed verification is an answer, not an error: inspect `decision` / `ok`. No
failure is ever returned as a decision.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from types import TracebackType
from typing import Any

import httpx

from safegate_client import calls
from safegate_client.calls import T
from safegate_client.models import (
    ContractResponse,
    GateResponse,
    MonitorSummaryResponse,
    VerifyResponse,
)
from safegate_client.retry import RetryPolicy
from safegate_client.wire import Body, JsonObject, auth_headers, unavailable


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

    def _call(self, call: calls.Call[T]) -> T:
        return call.read(self._send(call.method, call.path, **call.options))

    def gate(self, request: Body, *, reference_plan: bool = False) -> GateResponse:
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
        return self._call(calls.gate(request, reference_plan))

    def answer(self, request_id: str, answers: Mapping[str, Any]) -> GateResponse:
        """Answer a deferred request's question: `POST /gate/{id}/answers` (a new decision)."""
        return self._call(calls.answer(request_id, answers))

    def decision(self, request_id: str) -> JsonObject:
        """A stored decision with the decisions that followed it: `GET /gate/{id}` (the audit
        record, which the service describes as a free-form object)."""
        return self._call(calls.decision(request_id))

    def contract(self, contract_id: str) -> ContractResponse:
        """The Task Safety Contract (invariants, guards, aborts): `GET /contracts/{id}`."""
        return self._call(calls.contract(contract_id))

    def planner_constraints(self, contract_id: str) -> str:
        """The contract as plain constraints for a planner's prompt."""
        return self._call(calls.planner_constraints(contract_id))

    def verify(self, contract_id: str, plan: Sequence[Body],
               initial_state: Body | None = None) -> VerifyResponse:
        """Check a plan against its contract before anything moves: `POST /verify`.

        Args:
            contract_id: the contract of the authorized request.
            plan: the actions, as `Action`s or mappings, e.g. `[{"action": "PickupObject",
                "object": "mug_1"}, ...]`.
            initial_state: an `InitialState` or `{"scene": ..., "robot": ...}`; default: the
                gate request's.

        Returns:
            `ok`, `violations` (step, action, kind, condition_id, formula, counterexample),
            `attempts`, `attempts_left`, `decision`; for a failed plan `repair` (the nearest plan
            proved to pass, or null and `repair_reason`).
        """
        return self._call(calls.verify(contract_id, plan, initial_state))

    def open_monitor(self, contract_id: str, initial_state: Body | None = None) -> str:
        """Open a runtime monitoring session: `POST /monitor`; returns the session id."""
        return self._call(calls.open_monitor(contract_id, initial_state))

    def monitor_summary(self, session_id: str) -> MonitorSummaryResponse:
        """The session's MonitorSummary: `GET /monitor/{id}/summary`."""
        return self._call(calls.monitor_summary(session_id))
