"""POST /gate latency with OpenTelemetry tracing off and on, measured in the same run.

Run: `.venv/bin/python bench/perf/tracing_overhead.py` (or `make perf`). Prints a table.
Two servers on loopback, each a fresh SQLite file and its own analysis workers, started by
`_traced_server.py`: one untraced (the default), one with tracing on and its spans kept by the
in-memory exporter behind the batch processor (nothing leaves the machine, so the difference is
the cost of making the request span and the stage spans, replaying the workers' stages and
writing trace ids into the log lines). The benchmark's requests go to both in turns, rounds in
alternating order, so drift on the shared machine falls on both alike. The traced server reports
how many spans it made, which shows tracing was really on.
"""

from __future__ import annotations

import asyncio
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path

import httpx
from rich.console import Console
from rich.table import Table

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _rawhttp import Connection, encode_post
from _server import free_port, wait_until_ready

REPO = Path(__file__).resolve().parents[2]
CASES = REPO / "bench" / "cases" / "benchmark.jsonl"
WARM_UP = 100
ROUNDS = 8
PER_ROUND = 150


@contextmanager
def server(mode: str) -> Iterator[str]:
    """Yield the base URL of a `_traced_server.py` in `mode`."""
    port = free_port()
    with tempfile.TemporaryDirectory(prefix="safegate-otel-") as tmp:
        env = {**os.environ, "SAFEGATE_DATABASE_URL": f"sqlite:///{Path(tmp) / 'perf.db'}",
               "PYTHONPATH": str(REPO)}
        process = subprocess.Popen(
            [sys.executable, str(Path(__file__).with_name("_traced_server.py")), str(port), mode],
            env=env, cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        base = f"http://127.0.0.1:{port}"
        try:
            wait_until_ready(base, 90, f"the {mode} server")
            yield base
        finally:
            process.terminate()
            process.wait(timeout=30)


def bodies(base: str) -> list[bytes]:
    lines = CASES.read_text().splitlines()
    return [encode_post(base, "/gate", json.loads(line)["request"]) for line in lines if line]


async def timed(base: str, requests: list[bytes], start: int, count: int) -> list[float]:
    """`count` requests in turn on one keep-alive connection (a new one for each block: the
    other server's block outlasts uvicorn's keep-alive)."""
    connection = await Connection.open(base)
    latencies = []
    for i in range(start, start + count):
        began = time.perf_counter()
        status, _ = await connection.exchange(requests[i % len(requests)])
        if status != 200:
            raise RuntimeError(f"POST /gate answered {status}")
        latencies.append((time.perf_counter() - began) * 1000)
    await connection.close()
    return latencies


async def measure(bases: dict[str, str]) -> dict[str, list[float]]:
    requests = {mode: bodies(base) for mode, base in bases.items()}
    latencies: dict[str, list[float]] = {mode: [] for mode in bases}
    for mode, base in bases.items():
        await timed(base, requests[mode], 0, WARM_UP)
    for round_ in range(ROUNDS):
        order = list(bases) if round_ % 2 == 0 else list(reversed(bases))
        for mode in order:
            latencies[mode] += await timed(bases[mode], requests[mode],
                                           WARM_UP + round_ * PER_ROUND, PER_ROUND)
    return latencies


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def main() -> None:
    with ExitStack() as stack:
        off = stack.enter_context(server("off"))
        on = stack.enter_context(server("on"))
        latencies = asyncio.run(measure({"off": off, "on": on}))
        spans = int(httpx.get(on + "/_bench/spans", timeout=30).json())
    requests = WARM_UP + ROUNDS * PER_ROUND

    table = Table(title="POST /gate with tracing off and on (same run, loopback, "
                        "in-memory span exporter)")
    for column in ("tracing", "requests", "p50 ms", "p90 ms", "p99 ms", "mean ms", "spans"):
        table.add_column(column)
    for mode in ("off", "on"):
        values = latencies[mode]
        table.add_row(mode, str(len(values)), f"{statistics.median(values):.2f}",
                      f"{percentile(values, 0.9):.2f}", f"{percentile(values, 0.99):.2f}",
                      f"{statistics.fmean(values):.2f}",
                      f"{spans} ({spans / requests:.1f}/request)" if mode == "on" else "0")
    off_values, on_values = latencies["off"], latencies["on"]
    table.add_row("on - off", "",
                  f"{statistics.median(on_values) - statistics.median(off_values):+.2f}",
                  f"{percentile(on_values, 0.9) - percentile(off_values, 0.9):+.2f}",
                  f"{percentile(on_values, 0.99) - percentile(off_values, 0.99):+.2f}",
                  f"{statistics.fmean(on_values) - statistics.fmean(off_values):+.2f}", "")
    Console().print(table)
    if spans < requests:
        raise SystemExit(f"tracing was not on: {spans} spans for {requests} requests")


if __name__ == "__main__":
    main()
