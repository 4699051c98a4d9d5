"""The analysis pool's worker processes never outlive the server: SIGKILL the server and its
fork server and workers are gone within seconds (they would otherwise wait for work forever,
holding database connections). Linux only: processes are found through /proc."""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from pathlib import Path

import httpx
import pytest

from tests.api.conftest import LiveServer

pytestmark = [pytest.mark.faults,
              pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc (Linux)")]

GONE_WITHIN_SECONDS = 10.0


def _children(pid: int) -> list[int]:
    found = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rpartition(")")[2].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.append(int(stat.parent.name))
    return found


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()[0]
    except OSError:
        return False
    return state != "Z"


def _cmdline(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode()
    except OSError:
        return ""


@pytest.fixture
def live_server_for_faults(sqlite_url: str) -> Iterator[Callable[..., LiveServer]]:
    started: list[LiveServer] = []

    def start(**env: str) -> LiveServer:
        server = LiveServer(database_url=sqlite_url, env=env).start()
        started.append(server)
        return server

    yield start
    for server in started:
        server.stop()


def test_killing_the_server_ends_its_analysis_workers(
        live_server_for_faults: Callable[..., LiveServer]) -> None:
    server = live_server_for_faults(SAFEGATE_GATE_WORKERS="2", SAFEGATE_LOG_LEVEL="warning")
    decided = httpx.post(server.base_url + "/gate", json={"command": "wave hello"}, timeout=30)
    assert decided.status_code == 200
    assert server.process is not None
    fork_servers = [pid for pid in _children(server.process.pid)
                    if "multiprocessing.forkserver" in _cmdline(pid)]
    assert len(fork_servers) == 1, "the server runs its analysis workers from a fork server"
    workers = _children(fork_servers[0])
    assert len(workers) == 2

    server.stop(kill=True)
    deadline = time.monotonic() + GONE_WITHIN_SECONDS
    left = [fork_servers[0], *workers]
    while time.monotonic() < deadline and any(_alive(pid) for pid in left):
        time.sleep(0.2)
    assert not [pid for pid in left if _alive(pid)], "analysis processes outlived the server"
