"""No network for the suite: a test that reaches beyond this machine fails.

Loaded by `tests/conftest.py` for every test. From configure to unconfigure, `socket.socket`'s
`connect`, `connect_ex` and `sendto` refuse any address that is not loopback (127.0.0.0/8, ::1,
`localhost`), unspecified (0.0.0.0, ::, which Linux routes to this host) or a Unix socket,
raising `NetworkBlockedError`; and because a caller may swallow that error (an HTTP client's
retry, a fail-closed LLM adapter), every refused attempt is also recorded, and the test phase
(setup, call, teardown) in which it happened fails naming the address. Uvicorn, PostgreSQL
and the scripted LLM server on 127.0.0.1 stay reachable.

Limits: only sockets made through Python's `socket` module are seen, in the test process; a
C library's own connection (libpq) or a child process is not.
"""

from __future__ import annotations

import ipaddress
import socket
from collections.abc import Callable, Iterator
from typing import Any

import pytest

_REAL = {name: getattr(socket.socket, name) for name in ("connect", "connect_ex", "sendto")}
LOCAL_NAMES = {"localhost", "localhost.localdomain", "ip6-localhost", ""}
refused: list[str] = []


class NetworkBlockedError(ConnectionRefusedError):
    """A test tried to open a connection to, or send a datagram to, another machine."""


def is_local(family: int, address: Any) -> bool:
    """Whether `address` (of socket family `family`) is on this machine."""
    if family == getattr(socket, "AF_UNIX", None) or not isinstance(address, tuple):
        return True
    host = str(address[0])
    if host.lower() in LOCAL_NAMES:
        return True
    try:
        ip = ipaddress.ip_address(host.split("%")[0])
    except ValueError:
        return False  # a host name other than localhost: resolving it is the network already
    return ip.is_loopback or ip.is_unspecified


def _guard(name: str) -> Callable[..., Any]:
    real = _REAL[name]

    def guarded(self: socket.socket, *args: Any) -> Any:
        address = args[-1]  # connect(address), sendto(data, address), sendto(data, flags, addr)
        if not is_local(self.family, address):
            refused.append(f"{name} to {address!r}")
            raise NetworkBlockedError(f"tests may not reach the network: {name} {address!r}")
        return real(self, *args)

    return guarded


_installed = [0]  # configure calls not yet undone: an in-process pytester run nests one


def pytest_configure(config: pytest.Config) -> None:
    """Install the guard before any test module is imported."""
    if _installed[0] == 0:
        for name in _REAL:
            setattr(socket.socket, name, _guard(name))
    _installed[0] += 1


def pytest_unconfigure(config: pytest.Config) -> None:
    """Put the real socket methods back when the outermost session ends."""
    _installed[0] -= 1
    if _installed[0] == 0:
        for name, real in _REAL.items():
            setattr(socket.socket, name, real)


def _fail_on_attempts() -> None:
    attempts, refused[:] = list(refused), []
    if attempts:
        raise NetworkBlockedError("the test tried to reach the network: " + "; ".join(attempts))


@pytest.hookimpl(wrapper=True)
def pytest_runtest_setup(item: pytest.Item) -> Iterator[None]:
    """Attempts made while setting the test up (or collecting, before it) make it an error."""
    yield
    _fail_on_attempts()


@pytest.hookimpl(wrapper=True)
def pytest_runtest_call(item: pytest.Item) -> Iterator[None]:
    """Attempts made by the test itself fail it, even when the code under test caught them."""
    yield
    _fail_on_attempts()


@pytest.hookimpl(wrapper=True)
def pytest_runtest_teardown(item: pytest.Item, nextitem: pytest.Item | None) -> Iterator[None]:
    """Attempts made while tearing the test down make it an error."""
    yield
    _fail_on_attempts()


@pytest.fixture
def network_attempts() -> list[str]:
    """The refused attempts so far in this test; a test of the guard reads and clears it."""
    return refused
