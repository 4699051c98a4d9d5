"""Fixtures for the LLM adapter tests: a scripted OpenAI-compatible server on loopback.

Every test here is kept off the internet: socket connections to anything but loopback raise.
The live test (`test_live_smollm.py`) is collected only when `SAFEGATE_LLM_LIVE=1`
(`make test-llm-live` sets it), so the default suite never needs a model.
"""

from __future__ import annotations

import ipaddress
import os
import socket
from collections.abc import Callable, Iterator
from typing import Any

import pytest

from app.adapters.llm import LitellmClient, LlmConfig
from tests.adapters.llm.answers import with_cells
from tests.adapters.llm.scripted_server import ScriptedServer, scripted_server

collect_ignore = [] if os.environ.get("SAFEGATE_LLM_LIVE") == "1" else ["test_live_smollm.py"]

SCRIPTED_MODEL = "openai/scripted-model"


def _is_loopback(address: Any) -> bool:
    if not isinstance(address, tuple) or not address:
        return True  # Unix sockets and the like never leave the machine.
    host = str(address[0])
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


@pytest.fixture(autouse=True)
def no_internet(monkeypatch: pytest.MonkeyPatch) -> None:
    """Refuse any connection that would leave the machine."""
    real_connect = socket.socket.connect

    def guarded_connect(self: socket.socket, address: Any) -> Any:
        if not _is_loopback(address):
            raise ConnectionRefusedError(f"test tried to reach {address!r} off loopback")
        return real_connect(self, address)

    monkeypatch.setattr(socket.socket, "connect", guarded_connect)


@pytest.fixture
def llm_server() -> Iterator[ScriptedServer]:
    """A scripted chat-completions server on 127.0.0.1 whose JSON answers fill every matrix
    cell they leave open with "none, because ..." (see `answers.with_cells`)."""
    with scripted_server() as server:
        server.prepare = with_cells
        yield server


@pytest.fixture
def make_client(llm_server: ScriptedServer) -> Callable[..., LitellmClient]:
    """Build a litellm client pointed at the scripted server."""

    def build(timeout: float = 5.0, **overrides: Any) -> LitellmClient:
        return LitellmClient(
            LlmConfig(
                model=SCRIPTED_MODEL,
                api_base=llm_server.base_url,
                api_key="sk-scripted",
                timeout=timeout,
                **overrides,
            )
        )

    return build
