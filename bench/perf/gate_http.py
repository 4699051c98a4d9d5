"""POST /gate over real HTTP on loopback, one uvicorn worker: latency percentiles and throughput.

Run: `.venv/bin/python bench/perf/gate_http.py` (or `make perf`). Prints a table.
Targets (issue 3): p50 <= 3 ms, p99 <= 10 ms sequential; >= 500 requests/s with one worker.
The bodies are the benchmark's 232 requests in turn (varied commands and scenes, no repeats in a
row), sent by a lean keep-alive client (`_rawhttp`) so the load generator, which shares the
machine's cores with the server, does not become what is measured.
"""

from __future__ import annotations

import asyncio
import json
import statistics
import sys
import time
from pathlib import Path

from rich.console import Console
from rich.table import Table

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _rawhttp import Connection, encode_post
from _server import running_server

CASES = Path(__file__).resolve().parents[1] / "cases" / "benchmark.jsonl"
WARM_UP = 300
SEQUENTIAL = 2000
CONCURRENT_CLIENTS = 8
CONCURRENT_SECONDS = 5.0


def requests(base: str) -> list[bytes]:
    lines = CASES.read_text().splitlines()
    return [encode_post(base, "/gate", json.loads(line)["request"]) for line in lines if line]


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


async def sequential(base: str, bodies: list[bytes]) -> list[float]:
    connection = await Connection.open(base)
    latencies: list[float] = []
    for i in range(WARM_UP + SEQUENTIAL):
        started = time.perf_counter()
        status, _ = await connection.exchange(bodies[i % len(bodies)])
        if status != 200:
            raise RuntimeError(f"POST /gate answered {status}")
        if i >= WARM_UP:
            latencies.append((time.perf_counter() - started) * 1000)
    await connection.close()
    return latencies


async def concurrent(base: str, bodies: list[bytes]) -> tuple[int, int, float]:
    done = errors = 0
    stop_at = time.perf_counter() + CONCURRENT_SECONDS

    async def client(slot: int) -> None:
        nonlocal done, errors
        connection = await Connection.open(base)
        i = slot
        while time.perf_counter() < stop_at:
            status, _ = await connection.exchange(bodies[i % len(bodies)])
            if status == 200:
                done += 1
            else:
                errors += 1
            i += CONCURRENT_CLIENTS
        await connection.close()

    started = time.perf_counter()
    await asyncio.gather(*(client(n) for n in range(CONCURRENT_CLIENTS)))
    return done, errors, time.perf_counter() - started


def main() -> None:
    with running_server() as base:
        bodies = requests(base)
        latencies = asyncio.run(sequential(base, bodies))
        done, errors, elapsed = asyncio.run(concurrent(base, bodies))

    table = Table(title="POST /gate, one uvicorn worker, SQLite audit trail, loopback")
    for column in ("measure", "value", "target"):
        table.add_column(column)
    table.add_row("requests (sequential)", str(SEQUENTIAL), "")
    table.add_row("p50 latency", f"{statistics.median(latencies):.2f} ms", "<= 3 ms")
    table.add_row("p99 latency", f"{percentile(latencies, 0.99):.2f} ms", "<= 10 ms")
    table.add_row("max latency", f"{max(latencies):.2f} ms", "")
    table.add_row(f"throughput ({CONCURRENT_CLIENTS} clients, {CONCURRENT_SECONDS:.0f} s)",
                  f"{done / elapsed:.0f} req/s", ">= 500 req/s")
    table.add_row("errors", str(errors), "0")
    Console().print(table)


if __name__ == "__main__":
    main()
