"""Runtime monitoring (Stage 6) over HTTP and websockets.

- `POST /monitor` opens a session for a contract -> 201 `{"session_id": ...}`.
- `WS /monitor/{session_id}`: the runtime's `before`/`after` messages, one answer each.
- `WS /monitor/{session_id}/events`: violations and refusals as they happen, for any number of
  listeners (each first gets the session's status).
- `GET /monitor/{session_id}/summary`: the MonitorSummary.
A websocket to an unknown session is accepted, told `{"type": "error", ...}` and closed with
code 4404; a database failure while loading closes with 1011. Nothing here decides anything.
Each websocket logs `websocket_open`, then `websocket_close` (or `websocket_refused`) on
`safegate.websocket` with its session id and channel; the request id comes with every line.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from typing import Any, Literal

from fastapi import APIRouter, WebSocket, WebSocketDisconnect, status
from pydantic import BaseModel, ConfigDict, Field

from app.adapters.tracing import Tracing, stages
from app.api.deps import MonitoringDep, ReadAccess, RobotAccess
from app.api.examples import MONITOR_OPEN_EXAMPLE
from app.api.openapi import problem_responses
from app.domain.errors import NotFound, SafeGateError
from app.domain.models import InitialState
from app.services.monitoring import MonitorService
from app.services.monitoring_sessions import LiveSession

router = APIRouter(tags=["monitor"])
_log = logging.getLogger("safegate.websocket")

CLOSE_NOT_FOUND = 4404
CLOSE_UNAVAILABLE = 1011
CLOSE_TOO_SLOW = 1013


class MonitorOpenRequest(BaseModel):
    """Open a monitoring session."""

    model_config = ConfigDict(extra="forbid",
                              json_schema_extra={"examples": [MONITOR_OPEN_EXAMPLE]})

    contract_id: str = Field(min_length=1, max_length=64)
    initial_state: InitialState | None = Field(
        default=None, description="The scene and robot when the run starts; default: the gate "
                                  "request's.")


class MonitorOpenResponse(BaseModel):
    """A new (or, for a halted contract, already halted) session."""

    session_id: str
    contract_id: str
    halted: bool


class ViolationOut(BaseModel):
    """The violation that halted a session (the same shape as on the websocket)."""

    timestamp: str
    action: dict[str, Any]
    kind: Literal["invariant", "guard", "abort", "scope"]
    condition_id: str
    formula: str
    description: str
    seq: int
    phase: Literal["before", "after", "sync"] = Field(
        description="The message it answered: `before` (guards, aborts), `after` or `sync` "
                    "(invariants, aborts).")
    established: bool
    unknown_facts: list[str]
    quote: str | None = None


class MonitorSummaryResponse(BaseModel):
    """The paper's MonitorSummary (guards: one per guard per action of its type; invariants:
    one per invariant per state; aborts: one per abort per state, before and after)."""

    session_id: str
    contract_id: str
    actions_checked: int
    states_checked: int
    guards_checked: int
    invariants_checked: int
    aborts_checked: int
    violations: list[ViolationOut]
    halted: bool
    messages: int
    errors: int
    refused: int
    checks_by_condition: dict[str, int]
    last_seq: int | None = None
    pending_seq: int | None = None


@router.post("/monitor", response_model=MonitorOpenResponse,
             status_code=status.HTTP_201_CREATED, summary="Open a monitoring session",
             responses=problem_responses(
                 403, 404, (409, "The contract is exhausted: its task was rejected."), 503))
def open_monitor(body: MonitorOpenRequest, monitoring: MonitoringDep,
                 _: RobotAccess) -> MonitorOpenResponse:
    """Open a session; the initial state defaults to the gate request's scene and robot."""
    record = monitoring.open_session(body.contract_id, body.initial_state)
    assert record.id is not None
    return MonitorOpenResponse(session_id=record.id, contract_id=record.contract_id,
                               halted=record.halted)


@router.get("/monitor/{session_id}/summary", response_model=MonitorSummaryResponse,
            summary="Read a session's MonitorSummary", responses=problem_responses(404, 503))
async def monitor_summary(session_id: str, monitoring: MonitoringDep,
                          _: ReadAccess) -> MonitorSummaryResponse:
    """What the session has checked, its violations, and whether it is halted."""
    contract_id, summary = await monitoring.summary(session_id)
    return MonitorSummaryResponse(session_id=session_id, contract_id=contract_id,
                                  **summary.to_wire())


def _log_socket(event: str, session_id: str, channel: str, **more: object) -> None:
    if _log.isEnabledFor(logging.INFO):
        _log.info(event, extra={"fields": {
            "event": event, "session_id": session_id, "channel": channel, **more}})


async def _refuse_connection(websocket: WebSocket, session_id: str, channel: str,
                             error: SafeGateError) -> None:
    _log_socket("websocket_refused", session_id, channel, reason=type(error).__name__)
    await websocket.send_json({"type": "error", "seq": None, "detail": error.detail,
                               "halted": False})
    code = CLOSE_NOT_FOUND if isinstance(error, NotFound) else CLOSE_UNAVAILABLE
    await websocket.close(code=code, reason=type(error).__name__)


@router.websocket("/monitor/{session_id}")
async def monitor_socket(websocket: WebSocket, session_id: str, monitoring: MonitoringDep,
                         _: RobotAccess) -> None:
    """The runtime's channel: one answer per message, in order (robot or admin key)."""
    await websocket.accept()
    try:
        live = await monitoring.attach(session_id)
    except SafeGateError as error:
        await _refuse_connection(websocket, session_id, "runtime", error)
        return
    _log_socket("websocket_open", session_id, "runtime")
    flusher = asyncio.get_running_loop().create_task(monitoring.flush_periodically(live))
    tracing: Tracing = websocket.app.state.tracing
    tracing.name_request("WEBSOCKET", "/monitor/{session_id}")
    messages = 0
    try:
        while True:
            message = await websocket.receive()
            if message["type"] == "websocket.disconnect":
                break
            text = message.get("text")
            raw = text if text is not None else message.get("bytes")
            messages += 1
            with stages.recording(tracing.enabled) as checked:
                answer = await monitoring.handle(live, raw)
            tracing.replay(checked)
            await websocket.send_text(answer)
    except (WebSocketDisconnect, OSError):
        pass
    finally:
        flusher.cancel()
        # Before the await: a cancelled handler (server shutdown) stops at the next await.
        _log_socket("websocket_close", session_id, "runtime", messages=messages)
        await monitoring.detach(live)


async def _wait_for_close(websocket: WebSocket) -> None:
    while (await websocket.receive())["type"] != "websocket.disconnect":
        pass  # listeners have nothing to say; anything they send is ignored


async def _forward_events(websocket: WebSocket, live: LiveSession,
                          monitoring: MonitorService) -> None:
    subscriber = monitoring.subscribe(live)
    closed = asyncio.get_running_loop().create_task(_wait_for_close(websocket))
    try:
        while True:
            event_task = asyncio.get_running_loop().create_task(subscriber.queue.get())
            done, _ = await asyncio.wait({event_task, closed},
                                         return_when=asyncio.FIRST_COMPLETED)
            if event_task not in done:
                event_task.cancel()
                return
            event = event_task.result()
            if event is None:
                await websocket.close(code=CLOSE_TOO_SLOW, reason="listener too slow")
                return
            await websocket.send_json(event)
    finally:
        closed.cancel()
        monitoring.unsubscribe(live, subscriber)


@router.websocket("/monitor/{session_id}/events")
async def events_socket(websocket: WebSocket, session_id: str, monitoring: MonitoringDep,
                        _: ReadAccess) -> None:
    """A listener's channel: the session's status, then violations and refusals (any key)."""
    await websocket.accept()
    try:
        live = await monitoring.session(session_id)
    except SafeGateError as error:
        await _refuse_connection(websocket, session_id, "events", error)
        return
    _log_socket("websocket_open", session_id, "events")
    try:
        with contextlib.suppress(WebSocketDisconnect, OSError):
            await _forward_events(websocket, live, monitoring)
    finally:
        _log_socket("websocket_close", session_id, "events")
