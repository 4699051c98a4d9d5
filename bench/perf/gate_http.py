"""POST /gate over real HTTP on loopback, one uvicorn worker: latency percentiles and throughput.

Run: `.venv/bin/python bench/perf/gate_http.py` (or `make perf`). Prints a table.
Targets (issue 3): p50 <= 3 ms, p99 <= 10 ms sequential; >= 500 requests/s with one worker.
"""

from __future__ import annotations

import json
import statistics
import sys
import threading
import time
from pathlib import Path

import httpx
from rich.console import Console
from rich.table import Table

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _server import running_server

CASES = Path(__file__).resolve().parents[1] / "cases" / "benchmark.jsonl"
SEQUENTIAL = 1000
CONCURRENT_CLIENTS = 8
CONCURRENT_SECONDS = 5.0


def requests() -> list[dict[str, object]]:
    lines = CASES.read_text().splitlines()
    return [json.loads(line)["request"] for line in lines if line.strip()]


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def main() -> None:
    bodies = requests()
    with running_server() as base:
        latencies: list[float] = []
        with httpx.Client(base_url=base) as client:
            for i in range(100):  # warm-up
                client.post("/gate", json=bodies[i % len(bodies)])
            for i in range(SEQUENTIAL):
                started = time.perf_counter()
                response = client.post("/gate", json=bodies[i % len(bodies)])
                latencies.append((time.perf_counter() - started) * 1000)
                response.raise_for_status()

        done = [0] * CONCURRENT_CLIENTS
        errors = [0] * CONCURRENT_CLIENTS
        stop_at = time.perf_counter() + CONCURRENT_SECONDS

        def worker(slot: int) -> None:
            with httpx.Client(base_url=base) as client:
                i = slot
                while time.perf_counter() < stop_at:
                    response = client.post("/gate", json=bodies[i % len(bodies)])
                    if response.status_code == 200:
                        done[slot] += 1
                    else:
                        errors[slot] += 1
                    i += CONCURRENT_CLIENTS

        threads = [threading.Thread(target=worker, args=(n,)) for n in range(CONCURRENT_CLIENTS)]
        started = time.perf_counter()
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        elapsed = time.perf_counter() - started

    table = Table(title="POST /gate, one uvicorn worker, SQLite audit trail, loopback")
    for column in ("measure", "value", "target"):
        table.add_column(column)
    table.add_row("requests (sequential)", str(SEQUENTIAL), "")
    table.add_row("p50 latency", f"{statistics.median(latencies):.2f} ms", "<= 3 ms")
    table.add_row("p99 latency", f"{percentile(latencies, 0.99):.2f} ms", "<= 10 ms")
    table.add_row("max latency", f"{max(latencies):.2f} ms", "")
    table.add_row(f"throughput ({CONCURRENT_CLIENTS} clients, {CONCURRENT_SECONDS:.0f} s)",
                  f"{sum(done) / elapsed:.0f} req/s", ">= 500 req/s")
    table.add_row("errors", str(sum(errors)), "0")
    Console().print(table)


if __name__ == "__main__":
    main()
