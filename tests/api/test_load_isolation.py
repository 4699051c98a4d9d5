"""Nothing waits behind another request's analysis (issue 18, item 1), on a real uvicorn server.

The gate's Stages 1-5 run in the analysis pool's worker processes. These tests hold every worker
busy with gate requests whose LLM (an endpoint on loopback that accepts and never answers) only
gives up at `SAFEGATE_LLM_TIMEOUT`, and check by order of completion, not by a timing threshold,
that the probe, a read and a monitor step over a real websocket answer while those gate requests
are still waiting; that a gate request beyond the workers and the queue gets 503 problem+json
with Retry-After at once; and that the held requests defer (fail closed) once the timeout passes.
"""

from __future__ import annotations

import asyncio
import json
import socket
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest
from websockets.asyncio.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import GO_TO_MUG, after, before, store_contract

from app.store.db import create_engine_for
from app.store.repository import Repository
from tests.api.conftest import LiveServer

pytestmark = pytest.mark.slow

LLM_TIMEOUT_SECONDS = 4
STARTUP_SECONDS = 180
WORKERS = 2
QUEUE = 1
GATE_BODY = {"command": "bring the mug to the living room"}


class SilentLlm:
    """A TCP endpoint on loopback that accepts connections, reads, and never answers."""

    def __init__(self) -> None:
        self._listener = socket.create_server(("127.0.0.1", 0))
        self.port: int = self._listener.getsockname()[1]
        self._held: list[socket.socket] = []
        self._accepted = threading.Condition()
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        while True:
            try:
                connection, _ = self._listener.accept()
            except OSError:
                return
            with self._accepted:
                self._held.append(connection)
                self._accepted.notify_all()

    def wait_for_connections(self, count: int, timeout: float) -> bool:
        """Whether `count` connections (one per held gate request) arrived within `timeout`."""
        with self._accepted:
            return self._accepted.wait_for(lambda: len(self._held) >= count, timeout)

    def close(self) -> None:
        self._listener.close()
        for connection in self._held:
            connection.close()


@pytest.fixture
def silent_llm() -> Iterator[SilentLlm]:
    server = SilentLlm()
    yield server
    server.close()


@pytest.fixture
def busy_server(sqlite_url: str, silent_llm: SilentLlm) -> Iterator[LiveServer]:
    """A server whose analyzer is an LLM that never answers, with a small pool."""
    server = LiveServer(database_url=sqlite_url, env=dict(
        SAFEGATE_ANALYZER="llm",
        SAFEGATE_LLM_MODEL="openai/silent-model",
        SAFEGATE_LLM_API_BASE=f"http://127.0.0.1:{silent_llm.port}/v1",
        SAFEGATE_LLM_API_KEY="sk-silent",
        SAFEGATE_LLM_TIMEOUT=str(LLM_TIMEOUT_SECONDS),
        SAFEGATE_GATE_WORKERS=str(WORKERS),
        SAFEGATE_GATE_QUEUE=str(QUEUE),
        SAFEGATE_LOG_LEVEL="warning",
    ))
    # Its fork server imports litellm before the server is ready: allow for a loaded machine.
    server.start(timeout=STARTUP_SECONDS)
    yield server
    server.stop()


def _session(server: LiveServer) -> str:
    engine = create_engine_for(server.database_url)
    try:
        contract_id = store_contract(Repository(engine))
    finally:
        engine.dispose()
    opened = httpx.post(server.base_url + "/monitor", json={"contract_id": contract_id},
                        timeout=10)
    assert opened.status_code == 201, opened.text
    session_id: str = opened.json()["session_id"]
    return session_id


async def _monitor_step(server: LiveServer, session_id: str) -> list[dict[str, Any]]:
    async with connect(f"{server.ws_url}/monitor/{session_id}", open_timeout=10) as websocket:
        answers = []
        for message in (before(1, GO_TO_MUG), after(1, GO_TO_MUG)):
            await websocket.send(json.dumps(message))
            answers.append(json.loads(await asyncio.wait_for(websocket.recv(), 10)))
        return answers


async def _hold_the_workers(client: httpx.AsyncClient, silent_llm: SilentLlm,
                            count: int) -> list[asyncio.Task[httpx.Response]]:
    """Post `count` gate requests and return once every worker is waiting on the LLM."""
    held = [asyncio.create_task(client.post("/gate", json=GATE_BODY)) for _ in range(count)]
    arrived = await asyncio.to_thread(silent_llm.wait_for_connections, WORKERS, 60)
    assert arrived, "the gate requests never reached the LLM"
    assert not any(task.done() for task in held)
    return held


def test_probes_reads_and_monitor_answer_while_every_worker_waits_on_the_llm(
        busy_server: LiveServer, silent_llm: SilentLlm) -> None:
    session_id = _session(busy_server)

    async def scenario() -> None:
        timeout = httpx.Timeout(LLM_TIMEOUT_SECONDS * 10)
        async with httpx.AsyncClient(base_url=busy_server.base_url, timeout=timeout) as client:
            held = await _hold_the_workers(client, silent_llm, WORKERS + QUEUE)

            health = await client.get("/healthz")
            ready = await client.get("/readyz")
            templates = await client.get("/templates")
            answers = await _monitor_step(busy_server, session_id)
            summary = await client.get(f"/monitor/{session_id}/summary")

            # Every one of those answered while all the gate requests were still waiting.
            assert not any(task.done() for task in held)
            assert (health.status_code, ready.status_code) == (200, 200)
            assert templates.status_code == 200
            assert [a["type"] for a in answers] == ["allow", "allow"]
            assert summary.json()["actions_checked"] == 1

            # When the LLM's timeout passes, the held requests fail closed: a deferral.
            decided = await asyncio.gather(*held)
            for response in decided:
                assert response.status_code == 200, response.text
                assert response.json()["decision"] == "defer"

    asyncio.run(scenario())


def test_a_full_pool_answers_503_with_retry_after_at_once(
        busy_server: LiveServer, silent_llm: SilentLlm) -> None:
    async def scenario() -> None:
        timeout = httpx.Timeout(LLM_TIMEOUT_SECONDS * 10)
        async with httpx.AsyncClient(base_url=busy_server.base_url, timeout=timeout) as client:
            held = await _hold_the_workers(client, silent_llm, WORKERS + QUEUE)

            refused = await client.post("/gate", json=GATE_BODY)
            assert not any(task.done() for task in held)  # refused without waiting
            assert refused.status_code == 503
            assert refused.headers["content-type"] == "application/problem+json"
            assert int(refused.headers["retry-after"]) >= 1
            body = refused.json()
            assert (body["status"], body["title"]) == (503, "Busy")
            assert body["retry_after"] == int(refused.headers["retry-after"])
            # Reads are not the pool's business: they answer while it is full.
            assert (await client.get("/healthz")).status_code == 200

            for response in await asyncio.gather(*held):
                assert response.status_code == 200
            # Once the pool drained, the gate takes requests again (and they wait for the LLM).
            again = await client.post("/gate", json=GATE_BODY)
            assert again.status_code == 200
            assert again.json()["decision"] == "defer"

    asyncio.run(scenario())
