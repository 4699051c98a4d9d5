"""Start SafeGate under uvicorn on a free loopback port for a benchmark, and stop it after."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import httpx


def wait_until_ready(base: str, seconds: float, what: str) -> None:
    """Poll `/readyz` until it answers 200; RuntimeError after `seconds`."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            if httpx.get(base + "/readyz", timeout=1).status_code == 200:
                return
        except httpx.HTTPError:
            pass
        time.sleep(0.1)
    raise RuntimeError(f"{what} did not become ready in {seconds:.0f} s")


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@contextmanager
def running_server(extra_env: dict[str, str] | None = None,
                   checkout: Path | None = None, workers: int = 1) -> Iterator[str]:
    """Yield the base URL of a SafeGate (`workers` uvicorn workers, one by default) on a fresh
    SQLite file (or the database `extra_env` names), run from `checkout` (another copy of the
    code) when given."""
    port = free_port()
    with tempfile.TemporaryDirectory(prefix="safegate-perf-") as tmp:
        env = {
            **os.environ,
            "SAFEGATE_DATABASE_URL": f"sqlite:///{Path(tmp) / 'perf.db'}",
            **(extra_env or {}),
        }
        if checkout is not None:
            env["PYTHONPATH"] = str(checkout)
        process = subprocess.Popen(
            [sys.executable, "-m", "app.cli", "serve", "--port", str(port),
             "--workers", str(workers)],
            env=env,
            cwd=checkout,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        base = f"http://127.0.0.1:{port}"
        try:
            wait_until_ready(base, 60, "SafeGate")
            yield base
        finally:
            process.terminate()
            process.wait(timeout=20)
