"""HTTP fixtures: an in-process client, and a real uvicorn server on loopback.

- `client`: a `TestClient` over a fresh app on its own SQLite file (fast, in-process ASGI).
- `client_on`: the same, on `database_url` (SQLite and PostgreSQL).
- `lines`: SafeGate's log lines as JSON objects, each formatted where it was emitted.
- `live_server`: a factory starting `safegate serve` as a real process on a free 127.0.0.1 port
  with a given database URL and extra environment; it returns a `LiveServer` whose `stop()` and
  `start()` allow restart tests. Every started server is stopped at teardown.
"""

from __future__ import annotations

import json
import logging
import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import httpx
import pytest
from fastapi.testclient import TestClient

from app.api.logs import JsonLogFormatter
from app.config import Settings
from app.main import create_app


@pytest.fixture
def client(sqlite_url: str) -> Iterator[TestClient]:
    with TestClient(create_app(Settings(database_url=sqlite_url))) as test_client:
        yield test_client


@pytest.fixture
def client_on(database_url: str) -> Iterator[TestClient]:
    with TestClient(create_app(Settings(database_url=database_url))) as test_client:
        yield test_client


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@dataclass
class LiveServer:
    """A `safegate serve` process on loopback."""

    database_url: str
    env: dict[str, str] = field(default_factory=dict)
    port: int = field(default_factory=_free_port)
    process: subprocess.Popen[bytes] | None = None

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    @property
    def ws_url(self) -> str:
        return f"ws://127.0.0.1:{self.port}"

    def start(self, timeout: float = 60.0) -> LiveServer:
        env = {**os.environ, "SAFEGATE_DATABASE_URL": self.database_url, **self.env}
        self.process = subprocess.Popen(
            [sys.executable, "-m", "app.cli", "serve", "--port", str(self.port)],
            env=env,
            cwd=Path(__file__).resolve().parents[2],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
        )
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                err = self.process.stderr.read().decode() if self.process.stderr else ""
                raise RuntimeError(f"server exited early: {err[-2000:]}")
            try:
                if httpx.get(self.base_url + "/readyz", timeout=1).status_code == 200:
                    return self
            except httpx.HTTPError:
                pass
            time.sleep(0.1)
        self.stop()
        raise RuntimeError("server did not become ready")

    def stop(self, *, kill: bool = False) -> None:
        if self.process is None or self.process.poll() is not None:
            return
        self.process.send_signal(signal.SIGKILL if kill else signal.SIGTERM)
        try:
            self.process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait(timeout=5)


@pytest.fixture
def live_server(sqlite_url: str) -> Iterator[Callable[..., LiveServer]]:
    started: list[LiveServer] = []

    def start(database_url: str | None = None, **env: str) -> LiveServer:
        server = LiveServer(database_url=database_url or sqlite_url, env=env).start()
        started.append(server)
        return server

    yield start
    for server in started:
        server.stop()


class LogLines(logging.Handler):
    """Formats each record as it is emitted, in the context that emitted it (as stderr does)."""

    def __init__(self) -> None:
        super().__init__(logging.INFO)
        self.setFormatter(JsonLogFormatter())
        self.entries: list[dict[str, Any]] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.entries.append(json.loads(self.format(record)))

    def of(self, logger: str) -> list[dict[str, Any]]:
        return [e for e in self.entries if e["logger"] == logger]


@pytest.fixture
def lines() -> Iterator[LogLines]:
    """SafeGate's log lines while the test runs, as the JSON objects stderr would get."""
    handler = LogLines()
    logger = logging.getLogger("safegate")
    previous = logger.level
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    yield handler
    logger.removeHandler(handler)
    logger.setLevel(previous)
