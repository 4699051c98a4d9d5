"""Replicas on one PostgreSQL: halt fan-out latency, and gate throughput with 2 workers against 1.

Run: `.venv/bin/python bench/perf/replicas.py` (or `make perf`). Prints a table.
PostgreSQL: `SAFEGATE_BENCH_POSTGRES_URL` (default `postgresql+psycopg://postgres@127.0.0.1:5432/
test`, the test server) names a database allowed to CREATE DATABASE; a fresh database is made
for the run and dropped after it. Without a reachable server the benchmark says so and exits 0
(like the other benchmarks, it needs nothing `make run` does not).

1. Fan-out: replicas A and B (`safegate serve`, one worker each) on one database. For each of 100
   halts: a session opened on A, a watcher on B's `/monitor/{id}/events`, a runtime on A sending
   one `before` that breaks a guard; the clock runs from the send to the watcher's event (and, for
   comparison, to the runtime's own answer). Target (issue 18): p99 <= 100 ms.
2. Throughput: `POST /gate` from 8 keep-alive clients for 5 s each (`gate_http.py`'s load, after
   as long a warm-up), to one server started with `--workers 1` and then `--workers 2`, same
   database, same run; once with each worker's analysis pool at its default size (one process
   per core: one worker already spreads Stages 1-5 over every core) and once with one analysis
   process per worker (so the second worker adds a core's worth of analysis).
"""

from __future__ import annotations

import asyncio
import json
import statistics
import sys
import time
import uuid
from pathlib import Path

import httpx
from rich.console import Console
from rich.table import Table
from sqlalchemy import create_engine, make_url, text
from sqlalchemy.exc import OperationalError
from websockets.asyncio.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _server import running_server
from gate_http import CONCURRENT_CLIENTS, CONCURRENT_SECONDS, concurrent, percentile, requests

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.store.db import create_engine_for, migrate
from app.store.records import ContractRecord, GateRecord
from app.store.repository import Repository

HALTS = 100
ADMIN_URL_ENV = "SAFEGATE_BENCH_POSTGRES_URL"
DEFAULT_ADMIN_URL = "postgresql+psycopg://postgres@127.0.0.1:5432/test"
QUIET = {"SAFEGATE_LOG_LEVEL": "warning"}
REQUEST = {
    "command": "put the knife back in the block",
    "scene": {"objects": [{"id": "knife_1", "type": "Knife", "room": "kitchen",
                           "properties": {"sharp": True}}]},
    "robot": {"name": "stretch", "room": "kitchen", "skills": ["navigate", "pick", "place"]},
}
NO_KNIFE = ContractCondition(
    id="bench.no_knife", kind=ConditionKind.GUARD, formula="@object != #knife_1",
    description="The knife is not picked up", action="PickupObject", template_id="bench",
    template_version=1, bindings={})
PICK_KNIFE = {"type": "before", "seq": 1,
              "action": {"action": "PickupObject", "object": "knife_1"}}


def fresh_database(admin_url: str) -> str | None:
    """A new empty database on the admin URL's server, or None when there is no server."""
    name = f"safegate_bench_{uuid.uuid4().hex[:12]}"
    engine = create_engine(admin_url, isolation_level="AUTOCOMMIT")
    try:
        with engine.connect() as connection:
            connection.execute(text(f'CREATE DATABASE "{name}"'))
    except OperationalError:
        return None
    finally:
        engine.dispose()
    return make_url(admin_url).set(database=name).render_as_string(hide_password=False)


def drop_database(admin_url: str, url: str) -> None:
    engine = create_engine(admin_url, isolation_level="AUTOCOMMIT")
    with engine.connect() as connection:
        connection.execute(text(f'DROP DATABASE IF EXISTS "{make_url(url).database}" '
                                f"WITH (FORCE)"))
    engine.dispose()


def store_contract(url: str) -> str:
    """Migrate the database and store a contract whose guard forbids picking up the knife."""
    engine = create_engine_for(url)
    try:
        migrate(engine)
        repository = Repository(engine)
        record = repository.save_gate_record(GateRecord(
            request=GateRequest.model_validate(REQUEST), decision="authorize", rule="R4"))
        assert record.id is not None
        stored = repository.save_contract(ContractRecord(
            request_id=record.id, contract=Contract(guards=(NO_KNIFE,)).model_dump(mode="json"),
            max_attempts=3))
        assert stored.id is not None
        return stored.id
    finally:
        engine.dispose()


async def one_halt(a: str, b: str, contract_id: str, http: httpx.AsyncClient
                   ) -> tuple[float, float]:
    """(ms to the runtime's answer on A, ms to the watcher's event on B) for one halt."""
    opened = await http.post(f"{a}/monitor", json={"contract_id": contract_id})
    session_id = opened.json()["session_id"]
    ws_a, ws_b = a.replace("http://", "ws://"), b.replace("http://", "ws://")
    async with connect(f"{ws_b}/monitor/{session_id}/events") as watcher, \
            connect(f"{ws_a}/monitor/{session_id}") as runtime:
        status = json.loads(await watcher.recv())
        assert status["type"] == "status" and status["halted"] is False, status
        started = time.perf_counter()
        await runtime.send(json.dumps(PICK_KNIFE))

        async def answered() -> float:
            answer = json.loads(await runtime.recv())
            assert answer["type"] == "violation", answer
            return (time.perf_counter() - started) * 1000

        async def heard() -> float:
            event = json.loads(await asyncio.wait_for(watcher.recv(), 5))
            assert event["type"] == "violation" and event["session_id"] == session_id, event
            return (time.perf_counter() - started) * 1000

        answer_ms, event_ms = await asyncio.gather(answered(), heard())
    return answer_ms, event_ms


async def fan_out(a: str, b: str, contract_id: str) -> tuple[list[float], list[float]]:
    answers, events = [], []
    async with httpx.AsyncClient(timeout=10) as http:
        for _ in range(HALTS):
            answer_ms, event_ms = await one_halt(a, b, contract_id, http)
            answers.append(answer_ms)
            events.append(event_ms)
    return answers, events


def throughput(url: str, workers: int, pool: int) -> tuple[float, int]:
    """Gate requests/s (and errors) from `workers` uvicorn workers with `pool` analysis
    processes each (0: one per core, the default)."""
    # Niceness 0: on a machine shared with other work, analysis workers at the default 19 get
    # what the others leave, and the comparison would measure the others.
    env = {"SAFEGATE_DATABASE_URL": url, "SAFEGATE_GATE_WORKER_NICE": "0",
           "SAFEGATE_GATE_WORKERS": str(pool), **QUIET}
    with running_server(env, workers=workers) as base:
        bodies = requests(base)
        asyncio.run(concurrent(base, bodies))  # warm every worker and its analysis pool
        done, errors, elapsed = asyncio.run(concurrent(base, bodies))
    return done / elapsed, errors


def main() -> None:
    import os

    admin_url = os.environ.get(ADMIN_URL_ENV, DEFAULT_ADMIN_URL)
    url = fresh_database(admin_url)
    if url is None:
        print(f"replicas: no PostgreSQL at {ADMIN_URL_ENV} ({admin_url}); skipped")
        return
    try:
        contract_id = store_contract(url)
        env = {"SAFEGATE_DATABASE_URL": url, "SAFEGATE_GATE_WORKERS": "1", **QUIET}
        with running_server(env) as a, running_server(env) as b:
            answers, events = asyncio.run(fan_out(a, b, contract_id))
        rates = {(workers, pool): throughput(url, workers, pool)
                 for pool in (0, 1) for workers in (1, 2)}
    finally:
        drop_database(admin_url, url)

    table = Table(title="Two replicas on one PostgreSQL, loopback, same run")
    for column in ("measure", "p50", "p99", "max", "target"):
        table.add_column(column)
    table.add_row(f"halt on A -> runtime's answer on A ({HALTS} halts)",
                  f"{statistics.median(answers):.1f} ms", f"{percentile(answers, 0.99):.1f} ms",
                  f"{max(answers):.1f} ms", "")
    table.add_row(f"halt on A -> watcher on B ({HALTS} halts)",
                  f"{statistics.median(events):.1f} ms", f"{percentile(events, 0.99):.1f} ms",
                  f"{max(events):.1f} ms", "p99 <= 100 ms")
    lag = [event - answer for answer, event in zip(answers, events, strict=True)]
    table.add_row("the fan-out alone: watcher on B minus answer on A",
                  f"{statistics.median(lag):.1f} ms", f"{percentile(lag, 0.99):.1f} ms",
                  f"{max(lag):.1f} ms", "")
    load = f"{CONCURRENT_CLIENTS} clients, {CONCURRENT_SECONDS:.0f} s"
    for pool, pool_name in ((0, "analysis pool: one per core"), (1, "analysis pool: 1")):
        for workers in (1, 2):
            rate, errors = rates[(workers, pool)]
            ratio = rate / max(rates[(1, pool)][0], 1e-9)
            table.add_row(f"POST /gate, --workers {workers}, {pool_name} ({load})",
                          f"{rate:.0f} req/s", "", "", f"errors: {errors}; x{ratio:.2f}")
    Console().print(table)


if __name__ == "__main__":
    main()
