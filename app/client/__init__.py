"""Where the client SDK used to live: `app.client` now re-exports `safegate_client`.

The SDK is its own distribution, `safegate-client` (`clients/python/`, `pip install
./clients/python`), so a planner needs neither the server nor its dependencies. This module
only keeps old imports (`from app.client import GateClient`) working where the SDK is
installed; nothing of the server imports it, and the server does not depend on the SDK (an
import-linter contract says so). New code imports `safegate_client`.
Fails: `ImportError` naming the distribution to install when `safegate_client` is missing.
"""

try:
    from safegate_client import (
        ApiError,
        AsyncGateClient,
        GateClient,
        MonitorClient,
        MonitorConnectionError,
        MonitorError,
        MonitorEvents,
        MonitorHalted,
        MonitorResync,
        RetryPolicy,
        SafeGateClientError,
        SafeGateUnavailable,
        UnexpectedAnswer,
    )
except ModuleNotFoundError as missing:  # pragma: no cover - depends on the environment
    raise ImportError("app.client re-exports the SafeGate SDK: pip install ./clients/python "
                      "(the `safegate-client` distribution)") from missing

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
]
