"""Load on loopback: 100 concurrent /gate clients and 100 monitor sessions at once, one worker.

Run: `.venv/bin/python bench/perf/load.py [--seconds 10] [--gate-clients 100]
[--monitor-sessions 100] [--monitor-rate 2]` (also part of `make perf`). Prints a table of
latency percentiles, throughput and errors per kind of traffic, with the machine's load average
before and after the run.

In: nothing (starts its own `safegate serve` on a fresh SQLite file at a free 127.0.0.1 port and
stores the 20-condition contract of `monitor_step.py` in it). The gate clients and the monitor
sessions run in two separate client processes (each one asyncio loop), so neither starves the
other; every client holds its own connection. Each gate client posts the benchmark's requests in
turn, as fast as it is answered (closed loop: the gate is saturated, so its latency is mostly
queueing, clients / throughput). Beyond the analysis pool's workers and queue the gate sheds
load with 503 + Retry-After: such answers are counted ("503 shed") and the client tries again
after a short pause; they are not errors. Each monitor session sends `before`/`after` pairs of
actions the contract allows at `--monitor-rate` actions a second (a robot's pace; 0 sends as
fast as answers come) and times the pair. Traffic only goes
to loopback; every loop stops at the deadline and the whole run is bounded by `--seconds` plus
a fixed grace.
Out: the table; exit 1 if any request failed (a 503 with Retry-After is shedding, not failing),
any answer was not the expected kind, or any client could not connect.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import multiprocessing
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import httpx
from rich.console import Console
from rich.table import Table
from websockets.asyncio.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _server import running_server
from monitor_ws import PICK, PUT, store_contract

CASES = Path(__file__).resolve().parents[1] / "cases" / "benchmark.jsonl"
GRACE_SECONDS = 60.0
ANSWER_TIMEOUT = 30.0
BUSY_PAUSE_SECONDS = 0.05


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))] if ordered else 0.0


async def gate_client(base: str, bodies: list[dict[str, Any]], slot: int, deadline: float,
                      latencies: list[float], errors: list[str], shed: list[int]) -> None:
    limits = httpx.Limits(max_connections=1)
    async with httpx.AsyncClient(base_url=base, timeout=ANSWER_TIMEOUT, limits=limits) as client:
        i = slot
        while time.perf_counter() < deadline:
            started = time.perf_counter()
            try:
                response = await client.post("/gate", json=bodies[i % len(bodies)])
            except httpx.HTTPError as error:
                errors.append(type(error).__name__)
                continue
            if response.status_code == 503 and "retry-after" in response.headers:
                shed.append(1)  # the analysis pool is full: the gate sheds load, as it should
                await asyncio.sleep(BUSY_PAUSE_SECONDS)
                continue
            if response.status_code == 200 and "decision" in response.json():
                latencies.append((time.perf_counter() - started) * 1000)
            else:
                errors.append(f"HTTP {response.status_code}")
            i += 1


async def monitor_session(base: str, session_id: str, deadline: float, rate: float,
                          latencies: list[float], errors: list[str]) -> None:
    url = base.replace("http://", "ws://") + f"/monitor/{session_id}"
    try:
        async with connect(url, open_timeout=ANSWER_TIMEOUT) as socket:
            seq = 0
            started_at = time.perf_counter()
            while time.perf_counter() < deadline:
                if rate > 0:  # a robot acts at its own pace: the next action is due then
                    await asyncio.sleep(max(0.0, started_at + seq / rate - time.perf_counter()))
                seq += 1
                action = PICK if seq % 2 else PUT
                started = time.perf_counter()
                for kind in ("before", "after"):
                    await socket.send(json.dumps({"type": kind, "seq": seq, "action": action}))
                    answer = json.loads(await asyncio.wait_for(socket.recv(), ANSWER_TIMEOUT))
                    if answer.get("type") != "allow" or answer.get("seq") != seq:
                        errors.append(f"answer {answer.get('type')}: {answer.get('detail')}")
                        return
                latencies.append((time.perf_counter() - started) * 1000)
    except (OSError, TimeoutError) as error:
        errors.append(type(error).__name__)


async def gate_load(base: str, clients: int, seconds: float) -> dict[str, Any]:
    bodies = [json.loads(line)["request"] for line in CASES.read_text().splitlines() if line]
    latencies: list[float] = []
    errors: list[str] = []
    shed: list[int] = []
    started = time.perf_counter()
    deadline = started + seconds
    await asyncio.wait_for(asyncio.gather(*(
        gate_client(base, bodies, slot * 7, deadline, latencies, errors, shed)
        for slot in range(clients))), seconds + GRACE_SECONDS)
    return {"latencies": latencies, "errors": errors, "shed": len(shed),
            "elapsed": time.perf_counter() - started}


async def monitor_load(base: str, contract_id: str, sessions: int, seconds: float,
                       rate: float) -> dict[str, Any]:
    async with httpx.AsyncClient(base_url=base, timeout=ANSWER_TIMEOUT) as http:
        ids = [(await http.post("/monitor", json={"contract_id": contract_id})).json()[
            "session_id"] for _ in range(sessions)]
    latencies: list[float] = []
    errors: list[str] = []
    started = time.perf_counter()
    deadline = started + seconds
    await asyncio.wait_for(asyncio.gather(*(
        monitor_session(base, session_id, deadline, rate, latencies, errors)
        for session_id in ids)),
        seconds + GRACE_SECONDS)
    return {"latencies": latencies, "errors": errors, "shed": 0,
            "elapsed": time.perf_counter() - started}


def _run_in_process(kind: str, args: tuple[Any, ...], results: Any) -> None:
    if kind == "gate":
        results.put(("gate", asyncio.run(gate_load(*args))))
    else:
        results.put(("monitor", asyncio.run(monitor_load(*args))))


def load_average() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--gate-clients", type=int, default=100)
    parser.add_argument("--monitor-sessions", type=int, default=100)
    parser.add_argument("--monitor-rate", type=float, default=2.0,
                        help="actions per second per session (0: as fast as answers come)")
    options = parser.parse_args()
    before = load_average()
    with tempfile.TemporaryDirectory(prefix="safegate-load-") as tmp:
        url = f"sqlite:///{Path(tmp) / 'load.db'}"
        env = {"SAFEGATE_DATABASE_URL": url, "SAFEGATE_LOG_LEVEL": "warning"}
        with running_server(env) as base:
            contract_id = store_contract(url)
            results: Any = multiprocessing.Queue()
            workers = [
                multiprocessing.Process(target=_run_in_process, args=(
                    "gate", (base, options.gate_clients, options.seconds), results)),
                multiprocessing.Process(target=_run_in_process, args=(
                    "monitor", (base, contract_id, options.monitor_sessions, options.seconds,
                                options.monitor_rate),
                    results)),
            ]
            for worker in workers:
                worker.start()
            collected = dict(results.get(timeout=options.seconds + 2 * GRACE_SECONDS)
                             for _ in workers)
            for worker in workers:
                worker.join(timeout=GRACE_SECONDS)

    table = Table(title=(f"Load on loopback, one uvicorn worker, SQLite: {options.seconds:.0f} s, "
                         f"{os.cpu_count()} CPUs, load average before {before}"))
    for column in ("traffic", "clients", "completed", "errors", "503 shed", "p50 ms", "p90 ms",
                   "p99 ms", "max ms", "per second"):
        table.add_column(column, justify="left" if column == "traffic" else "right")
    rows = (("POST /gate", options.gate_clients, collected["gate"]),
            (f"monitor before+after, {options.monitor_rate:g}/s each" if options.monitor_rate
             else "monitor before+after, unpaced", options.monitor_sessions,
             collected["monitor"]))
    failed = False
    for name, clients, result in rows:
        ms = result["latencies"]
        failed = failed or bool(result["errors"]) or not ms
        table.add_row(name, str(clients), str(len(ms)), str(len(result["errors"])),
                      str(result["shed"]), f"{percentile(ms, 0.5):.1f}",
                      f"{percentile(ms, 0.9):.1f}", f"{percentile(ms, 0.99):.1f}",
                      f"{max(ms, default=0):.1f}",
                      f"{len(ms) / result['elapsed']:.0f}")
    console = Console()
    console.print(table)
    console.print(f"load average after: {load_average()}")
    for name, _, result in rows:
        if result["errors"]:
            console.print(f"{name} errors: {sorted(set(result['errors']))}")
    if failed:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
