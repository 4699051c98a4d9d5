"""SafeGate's Python SDK, for planners and robot runtimes; installable on its own
(`pip install ./clients/python`: httpx, pydantic and websockets, nothing of the server).

- `GateClient` (HTTP, httpx): `gate`, `answer`, `decision`, `contract`, `planner_constraints`,
  `verify`, `open_monitor`, `monitor_summary`; `AsyncGateClient` the same for asyncio. Both
  take requests as models (`safegate_client.models`) or plain mappings, answer typed models
  (`GateResponse`, `ContractResponse`, `VerifyResponse`, `MonitorSummaryResponse`), and retry
  per `RetryPolicy` (connection failures, timeouts, 502/503/504 with `Retry-After`).
- `MonitorClient` (websocket): `before`, `after`, and `step(action, execute)`, which raises
  `MonitorHalted` when the session halts; `sync(state, seq)` after a `MonitorResync`; it
  reconnects and resumes by itself (`reconnects`, `current_state`).
- `MonitorEvents` (websocket): a dashboard's stream of `Status`, `ViolationEvent` and
  `HaltedEvent`.
The models are generated from the service's OpenAPI and AsyncAPI documents (`make
client-models`). Errors: `safegate_client.errors` (one tree under `SafeGateClientError`). No
failure, of SafeGate, of the network or of an answer the SDK cannot read, is ever turned into
an allow.
"""

from safegate_client.errors import (
    ApiError,
    MonitorConnectionError,
    MonitorError,
    MonitorHalted,
    MonitorResync,
    SafeGateClientError,
    SafeGateUnavailable,
    UnexpectedAnswer,
)
from safegate_client.events import MonitorEvents
from safegate_client.gate import GateClient
from safegate_client.gate_async import AsyncGateClient
from safegate_client.monitor import MonitorClient
from safegate_client.retry import RetryPolicy

__version__ = "0.1.0"

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
    "UnexpectedAnswer",
    "__version__",
]
