"""Runtime monitor over a real websocket on loopback (one uvicorn worker): latency and isolation.

Run: `.venv/bin/python bench/perf/monitor_ws.py` (or `make perf`). Prints two tables.
Targets (issue 5): p99 <= 2 ms per action (its `before` and `after` round trips), sequential;
100 concurrent sessions x 200 actions with no lost, duplicated or crossed answers.

Each session gets its own seq range (session k sends k * 1_000_000 + i), so an answer delivered
to the wrong session, out of order or twice is detected; after the run every session's summary
must count exactly its own 200 actions. The contract is the 20-condition one of
`monitor_step.py`; the actions pick a cup up and put it back. Everything is bounded in time.
"""

from __future__ import annotations

import asyncio
import json
import sys
import tempfile
import time
from pathlib import Path

import httpx
from rich.console import Console
from rich.table import Table
from websockets.asyncio.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _server import running_server
from monitor_step import CONTRACT, SCENE

from app.domain.models import GateRequest
from app.store.db import create_engine_for
from app.store.records import ContractRecord, GateRecord
from app.store.repository import Repository

SEQUENTIAL_ACTIONS = 2000
SESSIONS = 100
ACTIONS_PER_SESSION = 200
ANSWER_TIMEOUT = 10.0
RUN_TIMEOUT = 240.0
TARGET_P99_MS = 2.0
PICK = {"action": "PickupObject", "object": "cup_3"}
PUT = {"action": "PutObject", "object": "cup_3", "target": "counter_1"}


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def store_contract(database_url: str) -> str:
    engine = create_engine_for(database_url)
    try:
        repository = Repository(engine)
        record = repository.save_gate_record(GateRecord(
            request=GateRequest.model_validate(SCENE), decision="authorize", rule="R4"))
        assert record.id is not None
        stored = repository.save_contract(ContractRecord(
            request_id=record.id, contract=CONTRACT.model_dump(mode="json"), max_attempts=3))
        assert stored.id is not None
        return stored.id
    finally:
        engine.dispose()


class Tally:
    def __init__(self) -> None:
        self.lost = self.crossed = self.duplicated = self.refused = 0
        self.action_ms: list[float] = []


async def run_session(ws_base: str, session_id: str, base_seq: int, actions: int,
                      tally: Tally) -> None:
    async with connect(f"{ws_base}/monitor/{session_id}") as socket:
        for i in range(actions):
            seq = base_seq + i
            action = PICK if i % 2 == 0 else PUT
            started = time.perf_counter()
            for kind in ("before", "after"):
                await socket.send(json.dumps({"type": kind, "seq": seq, "action": action}))
                try:
                    answer = json.loads(await asyncio.wait_for(socket.recv(), ANSWER_TIMEOUT))
                except TimeoutError:
                    tally.lost += 1
                    return
                if answer.get("seq") != seq:
                    tally.crossed += 1
                elif answer.get("type") != "allow":
                    tally.refused += 1
            tally.action_ms.append((time.perf_counter() - started) * 1000)
        try:  # nothing may arrive that was not asked for
            await asyncio.wait_for(socket.recv(), 0.05)
            tally.duplicated += 1
        except TimeoutError:
            pass


async def concurrent_run(base: str, contract_id: str) -> tuple[Tally, float, int]:
    ws_base = base.replace("http://", "ws://")
    async with httpx.AsyncClient(base_url=base, timeout=30) as http:
        ids = [(await http.post("/monitor", json={"contract_id": contract_id})).json()[
            "session_id"] for _ in range(SESSIONS)]
        tally = Tally()
        started = time.perf_counter()
        await asyncio.wait_for(asyncio.gather(*(
            run_session(ws_base, session_id, (k + 1) * 1_000_000, ACTIONS_PER_SESSION, tally)
            for k, session_id in enumerate(ids))), RUN_TIMEOUT)
        elapsed = time.perf_counter() - started
        miscounted = 0
        for session_id in ids:
            summary = (await http.get(f"/monitor/{session_id}/summary")).json()
            if (summary["actions_checked"], summary["states_checked"], summary["messages"]) != (
                    ACTIONS_PER_SESSION, ACTIONS_PER_SESSION, 2 * ACTIONS_PER_SESSION):
                miscounted += 1
    return tally, elapsed, miscounted


async def sequential_run(base: str, contract_id: str) -> Tally:
    async with httpx.AsyncClient(base_url=base, timeout=30) as http:
        warm_up, session_id = [(await http.post("/monitor", json={"contract_id": contract_id})
                                ).json()["session_id"] for _ in range(2)]
    tally = Tally()
    ws_base = base.replace("http://", "ws://")
    await run_session(ws_base, warm_up, 1, 100, Tally())  # warm-up on its own session
    await run_session(ws_base, session_id, 1000, SEQUENTIAL_ACTIONS, tally)
    return tally


def main() -> None:
    console = Console()
    with tempfile.TemporaryDirectory(prefix="safegate-monitor-ws-") as tmp:
        url = f"sqlite:///{Path(tmp) / 'monitor.db'}"
        with running_server({"SAFEGATE_DATABASE_URL": url}) as base:
            contract_id = store_contract(url)
            sequential = asyncio.run(sequential_run(base, contract_id))
            concurrent, elapsed, miscounted = asyncio.run(concurrent_run(base, contract_id))

    table = Table(title="Monitor over a websocket on loopback: ms per action (before + after)")
    for column in ("run", "actions", "p50", "p90", "p99", "max", "target"):
        table.add_column(column, justify="left" if column == "run" else "right")
    for name, tally in (("sequential, 1 session", sequential),
                        (f"{SESSIONS} concurrent sessions", concurrent)):
        ms = tally.action_ms
        target = ""
        if tally is sequential:
            p99 = percentile(ms, 0.99)
            target = f"p99 <= {TARGET_P99_MS} ms " + ("OK" if p99 <= TARGET_P99_MS else "MISSED")
        table.add_row(name, str(len(ms)), f"{percentile(ms, 0.5):.2f}",
                      f"{percentile(ms, 0.9):.2f}", f"{percentile(ms, 0.99):.2f}",
                      f"{max(ms):.2f}", target)
    console.print(table)

    total = SESSIONS * ACTIONS_PER_SESSION
    checks = Table(title=f"{SESSIONS} sessions x {ACTIONS_PER_SESSION} actions, concurrently")
    checks.add_column("measure")
    checks.add_column("value", justify="right")
    for name, value in (
        ("actions completed", f"{len(concurrent.action_ms)} / {total}"),
        ("lost answers", concurrent.lost), ("crossed answers", concurrent.crossed),
        ("duplicated answers", concurrent.duplicated), ("refused actions", concurrent.refused),
        ("sessions whose summary miscounts", miscounted),
        ("wall time", f"{elapsed:.1f} s"), ("messages/s", f"{2 * total / elapsed:.0f}"),
    ):
        checks.add_row(name, str(value))
    console.print(checks)
    clean = (len(concurrent.action_ms) == total and not (
        concurrent.lost or concurrent.crossed or concurrent.duplicated or concurrent.refused
        or miscounted))
    console.print("isolation: OK" if clean else "isolation: FAILED")
    if not clean or sequential.lost or sequential.refused:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
