"""The SDK's requests, written once for `GateClient` and `AsyncGateClient`: `Call`s.

In: an operation's arguments (SDK models or JSON-shaped mappings). Out: a `Call[T]`: the HTTP
method, path and httpx options to send, and how to read the answer into `T`. The two clients
only send a `Call` (with their retries, sync or awaited) and hand the response to `call.read`,
so both speak the same wire format and return the same types. Fails: `read` raises what
`safegate_client.wire.read` raises (`ApiError`, `UnexpectedAnswer`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar

import httpx

from safegate_client.models import (
    ContractResponse,
    GateResponse,
    MonitorOpenResponse,
    MonitorSummaryResponse,
    VerifyResponse,
)
from safegate_client.wire import (
    Answer,
    Body,
    JsonObject,
    as_json,
    json_of,
    monitor_body,
    read,
    text_of,
    verify_body,
)

T = TypeVar("T")


@dataclass(frozen=True)
class Call(Generic[T]):
    """One request to send and the reading of its answer."""

    method: str
    path: str
    read: Callable[[httpx.Response], T]
    options: Mapping[str, Any] = field(default_factory=dict)


def _model(model: type[Answer]) -> Callable[[httpx.Response], Answer]:
    return lambda response: read(response, model)


def gate(request: Body, reference_plan: bool) -> Call[GateResponse]:
    params = {"reference_plan": "true"} if reference_plan else None
    return Call("POST", "/gate", _model(GateResponse),
                {"json": as_json(request), "params": params})


def answer(request_id: str, answers: Mapping[str, Any]) -> Call[GateResponse]:
    return Call("POST", f"/gate/{request_id}/answers", _model(GateResponse),
                {"json": dict(answers)})


def _record(response: httpx.Response) -> JsonObject:
    record: JsonObject = json_of(response)
    return record


def decision(request_id: str) -> Call[JsonObject]:
    return Call("GET", f"/gate/{request_id}", _record)


def contract(contract_id: str) -> Call[ContractResponse]:
    return Call("GET", f"/contracts/{contract_id}", _model(ContractResponse))


def planner_constraints(contract_id: str) -> Call[str]:
    return Call("GET", f"/contracts/{contract_id}", text_of, {"params": {"format": "planner"}})


def verify(contract_id: str, plan: Sequence[Body],
           initial_state: Body | None) -> Call[VerifyResponse]:
    return Call("POST", "/verify", _model(VerifyResponse),
                {"json": verify_body(contract_id, plan, initial_state)})


def _session_id(response: httpx.Response) -> str:
    return read(response, MonitorOpenResponse).session_id


def open_monitor(contract_id: str, initial_state: Body | None) -> Call[str]:
    return Call("POST", "/monitor", _session_id,
                {"json": monitor_body(contract_id, initial_state)})


def monitor_summary(session_id: str) -> Call[MonitorSummaryResponse]:
    return Call("GET", f"/monitor/{session_id}/summary", _model(MonitorSummaryResponse))
