"""kill -9 under load: nothing a client was told is lost.

A real `safegate serve` on a SQLite file answers gate requests from several clients while other
clients drive monitor sessions into a halt, all at once; the process is then SIGKILLed in the
middle of it and started again on the same file. Every decision a client received must be in the
audit trail, unchanged, and every session a client saw halt must still be halted (and refuse the
next action).
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import httpx
import pytest
from monitor_kit import GO_TO_MUG, TOGGLE_STOVE, after, before, store_contract
from websockets.exceptions import WebSocketException
from websockets.sync.client import connect

from app.store.db import create_engine_for, migrate
from app.store.repository import Repository

pytestmark = [pytest.mark.faults, pytest.mark.slow]

CASES = Path(__file__).resolve().parents[2] / "bench" / "cases" / "benchmark.jsonl"
GATE_CLIENTS = 6
MONITOR_CLIENTS = 4
LOAD_SECONDS = 2.0
MAX_LOAD_SECONDS = 60.0
ENOUGH_DECISIONS, ENOUGH_HALTS = 20, 4
"""The kill comes after at least LOAD_SECONDS of load and once the clients have been told
enough to make the check meaningful (a slow machine takes longer to get there)."""


def contract_in(url: str) -> str:
    engine = create_engine_for(url)
    try:
        migrate(engine)
        return store_contract(Repository(engine))
    finally:
        engine.dispose()


class Received:
    """What the clients were told before the kill (thread-safe)."""

    def __init__(self) -> None:
        self.lock = threading.Lock()
        self.decisions: dict[str, str] = {}
        self.halted: list[str] = []
        self.stop = threading.Event()

    def enough(self) -> bool:
        with self.lock:
            return (len(self.decisions) >= ENOUGH_DECISIONS
                    and len(self.halted) >= ENOUGH_HALTS)


def gate_client(base_url: str, bodies: list[dict[str, Any]], slot: int,
                received: Received) -> None:
    with httpx.Client(base_url=base_url, timeout=10) as client:
        i = slot
        while not received.stop.is_set():
            try:
                response = client.post("/gate", json=bodies[i % len(bodies)])
            except httpx.HTTPError:
                if received.stop.is_set():
                    return  # the server is gone
                time.sleep(0.05)  # slow under load, or killed a moment before `stop`
                continue
            if response.status_code == 200:
                body = response.json()
                with received.lock:
                    received.decisions[body["request_id"]] = body["decision"]
            i += GATE_CLIENTS


def monitor_client(server: Any, contract_id: str, received: Received) -> None:
    with httpx.Client(base_url=server.base_url, timeout=10) as client:
        while not received.stop.is_set():
            try:
                session_id = client.post("/monitor", json={"contract_id": contract_id}).json()[
                    "session_id"]
                with connect(f"{server.ws_url}/monitor/{session_id}", open_timeout=10) as socket:
                    for message in (before(1, GO_TO_MUG), after(1, GO_TO_MUG),
                                    before(2, TOGGLE_STOVE)):
                        socket.send(json.dumps(message))
                        answer = json.loads(socket.recv(timeout=10))
                    if answer["type"] == "violation":
                        with received.lock:
                            received.halted.append(session_id)
            except (httpx.HTTPError, WebSocketException, OSError, TimeoutError, KeyError):
                if received.stop.is_set():
                    return  # the server is gone
                time.sleep(0.05)  # slow under load, or killed a moment before `stop`


class TestKillNineUnderLoad:
    def test_every_received_decision_and_halt_survives(
        self, live_server: Callable[..., Any], sqlite_url: str
    ) -> None:
        contract_id = contract_in(sqlite_url)
        bodies = [json.loads(line)["request"] for line in CASES.read_text().splitlines()[:40]]
        server = live_server(SAFEGATE_LOG_LEVEL="warning")
        received = Received()
        threads = [threading.Thread(target=gate_client, args=(server.base_url, bodies, n,
                                                              received)) for n in
                   range(GATE_CLIENTS)]
        threads += [threading.Thread(target=monitor_client, args=(server, contract_id,
                                                                  received))
                    for _ in range(MONITOR_CLIENTS)]
        for thread in threads:
            thread.start()
        started = time.monotonic()
        time.sleep(LOAD_SECONDS)
        while time.monotonic() - started < MAX_LOAD_SECONDS and not received.enough():
            time.sleep(0.1)
        server.stop(kill=True)  # SIGKILL while requests are in flight
        received.stop.set()
        for thread in threads:
            thread.join(timeout=20)
        assert server.process.returncode == -9
        assert received.enough(), (len(received.decisions), len(received.halted))

        server.start()
        with httpx.Client(base_url=server.base_url, timeout=10) as client:
            lost = [request_id for request_id, decision in received.decisions.items()
                    if (answer := client.get(f"/gate/{request_id}")).status_code != 200
                    or answer.json()["decision"] != decision]
            not_halted = [session_id for session_id in received.halted
                          if not client.get(f"/monitor/{session_id}/summary").json()["halted"]]
        assert not lost, f"{len(lost)} of {len(received.decisions)} decisions lost"
        assert not not_halted, f"{len(not_halted)} of {len(received.halted)} halts lost"
        with connect(f"{server.ws_url}/monitor/{received.halted[0]}") as socket:
            socket.send(json.dumps(before(9, GO_TO_MUG)))
            assert json.loads(socket.recv(timeout=10))["type"] == "halted"
