"""`AsyncGateClient`: `GateClient` for asyncio planners (httpx's `AsyncClient`).

In, out and failures are `GateClient`'s (`safegate_client/gate.py`): the same methods, awaited,
with the same typed answers; the same `RetryPolicy`; `ApiError` for an error status,
`UnexpectedAnswer` for an answer not of the promised shape and `SafeGateUnavailable` when no
answer came through any retry. No failure is ever returned as a decision.
"""

from __future__ import annotations

import asyncio
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


class AsyncGateClient:
    """An asyncio SafeGate client for planners; use it as an async context manager."""

    def __init__(self, base_url: str = "http://127.0.0.1:8000", *, api_key: str | None = None,
                 timeout: float = 30.0, retry: RetryPolicy | None = None,
                 transport: httpx.AsyncBaseTransport | None = None) -> None:
        """Connect lazily to a SafeGate server (arguments as `GateClient`'s)."""
        self.base_url = base_url.rstrip("/")
        self.api_key = api_key
        self.retry = retry or RetryPolicy()
        self._http = httpx.AsyncClient(base_url=self.base_url, headers=auth_headers(api_key),
                                       timeout=timeout, transport=transport)

    async def __aenter__(self) -> AsyncGateClient:
        return self

    async def __aexit__(self, kind: type[BaseException] | None, error: BaseException | None,
                        trace: TracebackType | None) -> None:
        await self.aclose()

    async def aclose(self) -> None:
        """Close the connection pool."""
        await self._http.aclose()

    async def _send(self, method: str, path: str, **options: Any) -> httpx.Response:
        attempt = 1
        while True:
            outcome: httpx.Response | httpx.TransportError
            try:
                outcome = await self._http.request(method, path, **options)
            except httpx.TransportError as error:
                outcome = error
            if not self.retry.retries(attempt, outcome):
                if isinstance(outcome, httpx.TransportError):
                    raise unavailable(method, path, outcome) from outcome
                return outcome
            await asyncio.sleep(self.retry.wait(attempt, outcome))
            attempt += 1

    async def _call(self, call: calls.Call[T]) -> T:
        return call.read(await self._send(call.method, call.path, **call.options))

    async def gate(self, request: Body, *, reference_plan: bool = False) -> GateResponse:
        """Ask whether a command may run: `POST /gate` (see `GateClient.gate`)."""
        return await self._call(calls.gate(request, reference_plan))

    async def answer(self, request_id: str, answers: Mapping[str, Any]) -> GateResponse:
        """Answer a deferred request's question: `POST /gate/{id}/answers`."""
        return await self._call(calls.answer(request_id, answers))

    async def decision(self, request_id: str) -> JsonObject:
        """A stored decision with the decisions that followed it: `GET /gate/{id}`."""
        return await self._call(calls.decision(request_id))

    async def contract(self, contract_id: str) -> ContractResponse:
        """The Task Safety Contract: `GET /contracts/{id}`."""
        return await self._call(calls.contract(contract_id))

    async def planner_constraints(self, contract_id: str) -> str:
        """The contract as plain constraints for a planner's prompt."""
        return await self._call(calls.planner_constraints(contract_id))

    async def verify(self, contract_id: str, plan: Sequence[Body],
                     initial_state: Body | None = None) -> VerifyResponse:
        """Check a plan against its contract: `POST /verify` (see `GateClient.verify`)."""
        return await self._call(calls.verify(contract_id, plan, initial_state))

    async def open_monitor(self, contract_id: str, initial_state: Body | None = None) -> str:
        """Open a runtime monitoring session: `POST /monitor`; returns the session id."""
        return await self._call(calls.open_monitor(contract_id, initial_state))

    async def monitor_summary(self, session_id: str) -> MonitorSummaryResponse:
        """The session's MonitorSummary: `GET /monitor/{id}/summary`."""
        return await self._call(calls.monitor_summary(session_id))
