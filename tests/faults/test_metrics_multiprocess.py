"""Prometheus in multiprocess mode: `safegate serve --workers 2` with `PROMETHEUS_MULTIPROC_DIR`.

Each request may land on either worker (they share the listening socket); whichever answers
`/metrics` must report both: the requests both counted, and the open monitor sessions and the
analysis pools' queue as gauges summed over the live processes. A runtime connected to one
worker shows as one open session on every scrape, and as none once it has gone.
"""

from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest
from monitor_kit import store_contract
from websockets.sync.client import connect

from app.store.db import create_engine_for, migrate
from app.store.repository import Repository

pytestmark = [pytest.mark.faults, pytest.mark.slow]

ROOT = Path(__file__).resolve().parents[2]


def sample(text: str, name: str, labels: str = "") -> float:
    pattern = "^" + re.escape(name) + (re.escape("{" + labels + "}") if labels else "") + r" (\S+)$"
    match = re.search(pattern, text, re.MULTILINE)
    assert match is not None, f"{name}{{{labels}}} not in /metrics"
    return float(match.group(1))


@pytest.fixture
def two_workers(tmp_path: Path, sqlite_url: str) -> Iterator[tuple[str, str]]:
    engine = create_engine_for(sqlite_url)
    migrate(engine)
    contract_id = store_contract(Repository(engine))
    engine.dispose()
    metrics_dir = tmp_path / "metrics"
    metrics_dir.mkdir()
    (metrics_dir / "counter_999999.db").write_bytes(b"stale")  # `serve` must clear it
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    process = subprocess.Popen(
        [sys.executable, "-m", "app.cli", "serve", "--port", str(port), "--workers", "2"],
        env={**os.environ, "SAFEGATE_DATABASE_URL": sqlite_url, "SAFEGATE_LOG_LEVEL": "warning",
             "SAFEGATE_GATE_WORKERS": "1", "PROMETHEUS_MULTIPROC_DIR": str(metrics_dir)},
        cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 90
        ready = 0
        while ready < 6 and time.monotonic() < deadline:  # both workers up, most likely
            try:
                ready += httpx.get(f"{base}/readyz", timeout=2).status_code == 200
            except httpx.HTTPError:
                time.sleep(0.2)
        assert ready == 6, "safegate serve --workers 2 did not become ready"
        yield base, contract_id
    finally:
        process.send_signal(signal.SIGTERM)
        process.wait(timeout=30)


class TestMultiprocessMetrics:
    def test_every_worker_reports_all_processes_and_the_live_gauges(
        self, two_workers: tuple[str, str]
    ) -> None:
        base, contract_id = two_workers
        for _ in range(20):  # a new connection each: the kernel spreads them over the workers
            assert httpx.get(f"{base}/healthz").status_code == 200
        scrape = httpx.get(f"{base}/metrics").text
        counted = sample(scrape, "safegate_http_requests_total",
                         'method="GET",route="/healthz",status="200"')
        assert counted == 20.0
        session_id = httpx.post(f"{base}/monitor", json={"contract_id": contract_id}
                                ).json()["session_id"]
        with connect(f"{base.replace('http', 'ws')}/monitor/{session_id}") as runtime:
            runtime.send('{"type": "before", "seq": 1, "action": {"action": "GoToObject", '
                         '"object": "mug_1"}}')
            assert '"allow"' in str(runtime.recv(timeout=10))
            open_counts = {sample(httpx.get(f"{base}/metrics").text,
                                  "safegate_monitor_sessions_open") for _ in range(10)}
            assert open_counts == {1.0}
        time.sleep(0.5)
        scrape = httpx.get(f"{base}/metrics").text
        assert sample(scrape, "safegate_monitor_sessions_open") == 0.0
        assert sample(scrape, "safegate_analysis_pool_queued") == 0.0
        assert sample(scrape, "safegate_analysis_pool_in_flight") == 0.0
