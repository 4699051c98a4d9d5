"""The compose deployment's proxy for real: `deploy/nginx.conf` in front of two replicas.

nginx runs the repository's configuration, with the compose service names replaced by the two
loopback replicas' ports. A runtime that only knows the proxy's URL checks two steps, the
replica it landed on (the one whose `/metrics` counts an open session: the multiprocess gauge)
is SIGKILLed, and the runtime's next step goes through the proxy to the other replica, which
goes on from the durable state. Skipped, saying why, where nginx is not installed (`apt-get
install nginx-light`); docker-compose itself cannot run in the test environment.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest
from monitor_kit import CARRY_KNIFE_FAST, GO_TO_KNIFE, PICK_KNIFE
from replica_kit import BLADE_NEAR_PERSON, QUIET, knife_contract_in, open_session
from safegate_client import MonitorClient, MonitorHalted

pytestmark = [pytest.mark.faults, pytest.mark.slow, pytest.mark.postgres]

NGINX_CONF = Path(__file__).resolve().parents[2] / "deploy" / "nginx.conf"
OPEN_SESSIONS = re.compile(r"^safegate_monitor_sessions_open (\S+)$", re.MULTILINE)


def free_port() -> int:
    import socket

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@pytest.fixture
def proxy(tmp_path: Path) -> Iterator[Callable[[int, int], str]]:
    nginx = shutil.which("nginx") or ("/usr/sbin/nginx" if Path("/usr/sbin/nginx").exists()
                                      else None)
    if nginx is None:
        pytest.skip("nginx is not installed (apt-get install nginx-light)")
    started: list[subprocess.Popen[bytes]] = []

    def start(port_a: int, port_b: int) -> str:
        port = free_port()
        conf = NGINX_CONF.read_text()
        conf = conf.replace("api_a:8000", f"127.0.0.1:{port_a}")
        conf = conf.replace("api_b:8000", f"127.0.0.1:{port_b}")
        conf = conf.replace("listen 8000;", f"listen 127.0.0.1:{port};")
        conf = conf.replace("http {", "http {\n    access_log off;", 1)
        (tmp_path / "nginx.conf").write_text(conf)
        process = subprocess.Popen(
            [nginx, "-p", str(tmp_path), "-c", str(tmp_path / "nginx.conf"), "-e", "stderr",
             "-g", f"daemon off; pid {tmp_path / 'nginx.pid'};"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        started.append(process)
        base = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            try:
                if httpx.get(f"{base}/healthz", timeout=1).status_code == 200:
                    return base
            except httpx.HTTPError:
                time.sleep(0.1)
        raise RuntimeError("nginx did not start")

    yield start
    for process in started:
        process.terminate()
        process.wait(timeout=10)


def open_sessions(server: Any) -> float:
    match = OPEN_SESSIONS.search(httpx.get(f"{server.base_url}/metrics", timeout=10).text)
    assert match is not None
    return float(match.group(1))


class TestThroughTheProxy:
    def test_the_runtime_reconnects_through_the_proxy_to_the_surviving_replica(
        self, live_server: Callable[..., Any], postgres_url: str,
        proxy: Callable[[int, int], str], tmp_path: Path,
    ) -> None:
        contract_id = knife_contract_in(postgres_url)
        replicas = [live_server(postgres_url, **QUIET,
                                PROMETHEUS_MULTIPROC_DIR=str(tmp_path / f"metrics_{name}"))
                    for name in ("a", "b")]
        base = proxy(replicas[0].port, replicas[1].port)
        session_id = open_session(replicas[0], contract_id)
        with MonitorClient(base, session_id, reconnects=3) as runtime:
            runtime.step(GO_TO_KNIFE)
            runtime.step(PICK_KNIFE)
            counts = [open_sessions(server) for server in replicas]
            assert sorted(counts) == [0.0, 1.0], counts
            landed, survivor = (replicas if counts[0] == 1.0 else replicas[::-1])
            landed.stop(kill=True)
            assert runtime.before(CARRY_KNIFE_FAST) == 3
            with pytest.raises(MonitorHalted) as halted:
                runtime.after()
        assert halted.value.violation is not None
        assert halted.value.violation.condition_id == BLADE_NEAR_PERSON
        summary = httpx.get(f"{survivor.base_url}/monitor/{session_id}/summary",
                            timeout=10).json()
        assert (summary["actions_checked"], summary["halted"]) == (3, True)
        assert open_sessions(survivor) == 0.0  # the runtime has gone
