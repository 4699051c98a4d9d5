"""The SafeGate client SDK, for planners and robot runtimes.

- `GateClient` (HTTP, httpx): `gate`, `answer`, `decision`, `contract`, `planner_constraints`,
  `verify`, `open_monitor`, `monitor_summary`; `AsyncGateClient` the same for asyncio. Both
  take the service's request models (`GateRequest`, `InitialState`) or plain mappings, and
  retry per `RetryPolicy` (connection failures, timeouts, 502/503/504 with `Retry-After`).
- `MonitorClient` (websocket): `before`, `after`, and `step(action, execute)`, which raises
  `MonitorHalted` when the session halts; `sync(state, seq)` after a `MonitorResync`; it
  reconnects and resumes by itself (`reconnects`, `current_state`).
- `MonitorEvents` (websocket): a dashboard's stream of violations and refusals.
Errors: `app.client.errors` (one tree under `SafeGateClientError`). The SDK imports nothing from
the server side, only httpx, websockets and pydantic (any model is sent by its wire names).
No failure, of SafeGate or of the network, is ever turned into an allow.
"""

from app.client.errors import (
    ApiError,
    MonitorConnectionError,
    MonitorError,
    MonitorHalted,
    MonitorResync,
    SafeGateClientError,
    SafeGateUnavailable,
)
from app.client.gate import GateClient
from app.client.gate_async import AsyncGateClient
from app.client.monitor import MonitorClient, MonitorEvents
from app.client.retry import RetryPolicy

__all__ = [
    "ApiError",
    "AsyncGateClient",
    "GateClient",
    "MonitorClient",
    "MonitorConnectionError",
    "MonitorError",
    "MonitorEvents",
    "MonitorHalted",
    "MonitorResync",
    "RetryPolicy",
    "SafeGateClientError",
    "SafeGateUnavailable",
]
