"""The SafeGate client SDK, for planners and robot runtimes.

- `GateClient` (HTTP, httpx): `gate`, `answer`, `decision`, `contract`, `planner_constraints`,
  `verify`, `open_monitor`, `monitor_summary`.
- `MonitorClient` (websocket): `before`, `after`, and `step(action, execute)`, which raises
  `MonitorHalted` when the session halts; `sync(state, seq)` after a `MonitorResync`.
- `MonitorEvents` (websocket): a dashboard's stream of violations and refusals.
Errors: `app.client.errors` (one tree under `SafeGateClientError`). The SDK imports nothing from
the server side, only httpx and websockets.
"""

from app.client.errors import (
    ApiError,
    MonitorConnectionError,
    MonitorError,
    MonitorHalted,
    MonitorResync,
    SafeGateClientError,
)
from app.client.gate import GateClient
from app.client.monitor import MonitorClient, MonitorEvents

__all__ = [
    "ApiError",
    "GateClient",
    "MonitorClient",
    "MonitorConnectionError",
    "MonitorError",
    "MonitorEvents",
    "MonitorHalted",
    "MonitorResync",
    "SafeGateClientError",
]
