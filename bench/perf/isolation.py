"""Isolation under gate load: monitor answers and /healthz, idle and with clients saturating /gate.

Run: `.venv/bin/python bench/perf/isolation.py [--seconds 10] [--gate-clients 8] [--rate 50]`
(also part of `make perf`). Prints one table: monitor-answer and /healthz latency percentiles
idle and then, in the same run against the same server, while `--gate-clients` clients saturate
`POST /gate`, with the gate's own throughput and any 503s beside them.
Targets (issue 18): monitor answers p99 <= 5 ms and /healthz p99 <= 5 ms while 8 clients
saturate /gate; the idle p99 is printed beside them.

In: nothing (starts its own `safegate serve` on a fresh SQLite file at a free 127.0.0.1 port, one
uvicorn worker with its analysis pool, and stores the 20-condition contract of `monitor_step.py`).
The probes run in their own client process (one asyncio loop): one monitor session sends
`before`/`after` messages of actions the contract allows and times each answer; one keep-alive
connection (the lean client of `_rawhttp.py`) times `GET /healthz`; each at `--rate` a second.
The gate clients run in another process, each on its own keep-alive connection posting the
benchmark's requests in turn as fast as it is answered (closed loop, so the analysis workers
never idle); a 503 (pool full) is counted and retried after a short pause.
Traffic only goes to loopback; every loop stops at its deadline.
Out: the table; exit 1 if a probe failed or got a wrong answer, or a gate request failed
other than with 503.
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
from urllib.parse import urlsplit

import httpx
from rich.console import Console
from rich.table import Table
from websockets.asyncio.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _rawhttp import Connection, encode_post
from _server import running_server
from monitor_ws import PICK, PUT, store_contract

CASES = Path(__file__).resolve().parents[1] / "cases" / "benchmark.jsonl"
ANSWER_TIMEOUT = 30.0
GRACE_SECONDS = 60.0
BUSY_PAUSE_SECONDS = 0.05
TARGET_P99_MS = 5.0


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))] if ordered else 0.0


async def monitor_probe(base: str, session_id: str, deadline: float, rate: float,
                        seq: int, latencies: list[float], errors: list[str]) -> int:
    """Send before/after messages at `rate` a second until the deadline; time each answer."""
    url = base.replace("http://", "ws://") + f"/monitor/{session_id}"
    async with connect(url, open_timeout=ANSWER_TIMEOUT) as socket:
        started_at = time.perf_counter()
        sent = 0
        while time.perf_counter() < deadline:
            await asyncio.sleep(max(0.0, started_at + sent / rate - time.perf_counter()))
            kind = "before" if sent % 2 == 0 else "after"
            if kind == "before":
                seq += 1
            action = PICK if seq % 2 else PUT
            started = time.perf_counter()
            await socket.send(json.dumps({"type": kind, "seq": seq, "action": action}))
            answer = json.loads(await asyncio.wait_for(socket.recv(), ANSWER_TIMEOUT))
            latencies.append((time.perf_counter() - started) * 1000)
            sent += 1
            if answer.get("type") != "allow" or answer.get("seq") != seq:
                errors.append(f"monitor answered {answer.get('type')}: {answer.get('detail')}")
                return seq
        if sent % 2:  # leave the session between actions
            await socket.send(json.dumps({"type": "after", "seq": seq,
                                          "action": PICK if seq % 2 else PUT}))
            await asyncio.wait_for(socket.recv(), ANSWER_TIMEOUT)
    return seq


async def health_probe(base: str, deadline: float, rate: float, latencies: list[float],
                       errors: list[str]) -> None:
    request = f"GET /healthz HTTP/1.1\r\nhost: {urlsplit(base).netloc}\r\n\r\n".encode()
    connection = await Connection.open(base)
    try:
        await connection.exchange(request)  # the connection is open before timing
        started_at = time.perf_counter()
        sent = 0
        while time.perf_counter() < deadline:
            await asyncio.sleep(max(0.0, started_at + sent / rate - time.perf_counter()))
            started = time.perf_counter()
            status, _ = await asyncio.wait_for(connection.exchange(request), ANSWER_TIMEOUT)
            latencies.append((time.perf_counter() - started) * 1000)
            sent += 1
            if status != 200:
                errors.append(f"/healthz HTTP {status}")
    finally:
        await connection.close()


async def probes(base: str, session_id: str, seconds: float, rate: float,
                 seq: int) -> dict[str, Any]:
    deadline = time.perf_counter() + seconds
    monitor_ms: list[float] = []
    health_ms: list[float] = []
    errors: list[str] = []
    seq, _ = await asyncio.wait_for(asyncio.gather(
        monitor_probe(base, session_id, deadline, rate, seq, monitor_ms, errors),
        health_probe(base, deadline, rate, health_ms, errors)), seconds + GRACE_SECONDS)
    return {"monitor": monitor_ms, "health": health_ms, "errors": errors, "seq": seq}


async def gate_client(base: str, requests: list[bytes], slot: int, deadline: float,
                      result: dict[str, Any]) -> None:
    connection = await Connection.open(base)
    try:
        i = slot
        while time.perf_counter() < deadline:
            started = time.perf_counter()
            try:
                status, body = await asyncio.wait_for(
                    connection.exchange(requests[i % len(requests)]), ANSWER_TIMEOUT)
            except (OSError, asyncio.IncompleteReadError, TimeoutError) as error:
                result["errors"].append(type(error).__name__)
                return
            if status == 503:
                result["busy"] += 1
                await asyncio.sleep(BUSY_PAUSE_SECONDS)
                continue
            if status == 200 and b'"decision"' in body:
                result["latencies"].append((time.perf_counter() - started) * 1000)
            else:
                result["errors"].append(f"HTTP {status}")
            i += 1
    finally:
        await connection.close()


async def gate_load(base: str, clients: int, seconds: float) -> dict[str, Any]:
    requests = [encode_post(base, "/gate", json.loads(line)["request"])
                for line in CASES.read_text().splitlines() if line]
    result: dict[str, Any] = {"latencies": [], "errors": [], "busy": 0}
    started = time.perf_counter()
    deadline = started + seconds
    await asyncio.wait_for(asyncio.gather(*(
        gate_client(base, requests, slot * 7, deadline, result) for slot in range(clients))),
        seconds + GRACE_SECONDS)
    result["elapsed"] = time.perf_counter() - started
    return result


def _gate_process(base: str, clients: int, seconds: float, results: Any) -> None:
    results.put(asyncio.run(gate_load(base, clients, seconds)))


def _warm_up(base: str, clients: int) -> None:
    """A few gate requests first, so the loaded phase measures steady state, not first calls."""
    asyncio.run(gate_load(base, clients, 2.0))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0, help="length of each phase")
    parser.add_argument("--gate-clients", type=int, default=8)
    parser.add_argument("--rate", type=float, default=50.0,
                        help="monitor messages and /healthz requests a second, each")
    options = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="safegate-isolation-") as tmp:
        url = f"sqlite:///{Path(tmp) / 'isolation.db'}"
        env = {"SAFEGATE_DATABASE_URL": url, "SAFEGATE_LOG_LEVEL": "warning"}
        with running_server(env) as base:
            contract_id = store_contract(url)
            session_id = httpx.post(base + "/monitor", json={"contract_id": contract_id},
                                    timeout=ANSWER_TIMEOUT).json()["session_id"]
            _warm_up(base, options.gate_clients)
            idle = asyncio.run(probes(base, session_id, options.seconds, options.rate, 0))

            results: Any = multiprocessing.Queue()
            gate = multiprocessing.Process(target=_gate_process, args=(
                base, options.gate_clients, options.seconds + 2.0, results))
            gate.start()
            time.sleep(1.0)  # let the gate clients fill the workers before measuring
            loaded = asyncio.run(probes(base, session_id, options.seconds, options.rate,
                                        idle["seq"]))
            gate_result = results.get(timeout=options.seconds + 2 * GRACE_SECONDS)
            gate.join(timeout=GRACE_SECONDS)

    console = Console()
    table = Table(title=(
        f"Monitor and probe latency, idle vs {options.gate_clients} clients saturating POST "
        f"/gate: one uvicorn worker, SQLite, {os.cpu_count()} CPUs, {options.seconds:.0f} s "
        f"each, probes at {options.rate:g}/s"))
    for column in ("traffic", "while", "answers", "p50 ms", "p90 ms", "p99 ms", "max ms"):
        table.add_column(column, justify="left" if column in ("traffic", "while") else "right")
    busy = f"{options.gate_clients} gate clients"
    rows = [("monitor answer", "idle", idle["monitor"]),
            ("monitor answer", busy, loaded["monitor"]),
            ("GET /healthz", "idle", idle["health"]),
            ("GET /healthz", busy, loaded["health"]),
            ("POST /gate", busy, gate_result["latencies"])]
    for name, during, ms in rows:
        table.add_row(name, during, str(len(ms)), f"{percentile(ms, 0.5):.2f}",
                      f"{percentile(ms, 0.9):.2f}", f"{percentile(ms, 0.99):.2f}",
                      f"{max(ms, default=0):.2f}")
    console.print(table)
    gate_ms = gate_result["latencies"]
    console.print(f"gate: {len(gate_ms) / gate_result['elapsed']:.1f} decisions/s, "
                  f"{gate_result['busy']} answered 503 (pool full), "
                  f"{len(gate_result['errors'])} errors")
    for name, ms in (("monitor answer", loaded["monitor"]), ("GET /healthz", loaded["health"])):
        p99 = percentile(ms, 0.99)
        verdict = "meets" if p99 <= TARGET_P99_MS else "misses"
        console.print(f"{name} p99 under gate load {p99:.2f} ms {verdict} the "
                      f"{TARGET_P99_MS:g} ms target")
    errors = idle["errors"] + loaded["errors"] + gate_result["errors"]
    if errors:
        console.print(f"errors: {sorted(set(errors))}")
    if errors or not gate_ms or not loaded["monitor"] or not loaded["health"]:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
