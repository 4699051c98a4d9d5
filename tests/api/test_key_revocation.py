"""Revoking an API key closes its open websockets within a second (issue 18, item 3).

On a real uvicorn server with `SAFEGATE_AUTH=keys`, over real websockets: a robot key's monitor
channel and a listener's events channel are open; the key is revoked through `DELETE /keys/{id}`
(this process: closed before the answer) or straight in the database, as `safegate keys revoke`
or another replica does (found by the poll). Each socket gets close code 4401 with the reason,
another key's socket stays open, and the revoked key cannot connect again.
"""

from __future__ import annotations

import asyncio
import json
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import httpx
import pytest
from websockets.asyncio.client import ClientConnection, connect
from websockets.exceptions import ConnectionClosed, InvalidStatus

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import GO_TO_MUG, after, before, store_contract

from app.api.revocations import CLOSE_KEY_REVOKED, REVOKED_REASON
from app.services.access import issue_api_key
from app.store.db import create_engine_for
from app.store.records import ApiKeyRecord, ApiKeyRole
from app.store.repository import Repository
from tests.api.conftest import LiveServer

WITHIN_SECONDS = 1.0


@pytest.fixture
def locked_server(live_server: Callable[..., LiveServer]) -> LiveServer:
    return live_server(SAFEGATE_AUTH="keys", SAFEGATE_LOG_LEVEL="warning")


@pytest.fixture
def repository(locked_server: LiveServer) -> Iterator[Repository]:
    """The server's database, as the CLI (or another replica) sees it."""
    engine = create_engine_for(locked_server.database_url)
    yield Repository(engine)
    engine.dispose()


def _key(repository: Repository, role: ApiKeyRole, name: str) -> tuple[ApiKeyRecord, str]:
    return issue_api_key(repository, role, name)


def _session(server: LiveServer, repository: Repository, robot: str) -> str:
    contract_id = store_contract(repository)
    opened = httpx.post(server.base_url + "/monitor", json={"contract_id": contract_id},
                        headers={"X-API-Key": robot}, timeout=10)
    assert opened.status_code == 201, opened.text
    session_id: str = opened.json()["session_id"]
    return session_id


async def _step(websocket: ClientConnection, seq: int) -> str:
    await websocket.send(json.dumps(before(seq, GO_TO_MUG)))
    answer: str = json.loads(await asyncio.wait_for(websocket.recv(), 10))["type"]
    await websocket.send(json.dumps(after(seq, GO_TO_MUG)))
    await asyncio.wait_for(websocket.recv(), 10)
    return answer


async def _closed(websocket: ClientConnection) -> tuple[int | None, str, float]:
    """Wait (at most a few seconds) for the server to close; its code, reason and when."""
    started = time.monotonic()
    try:
        while True:
            await asyncio.wait_for(websocket.recv(), 5)  # events a listener may still get
    except ConnectionClosed as closed:
        frame = closed.rcvd
        return (frame.code if frame else None, frame.reason if frame else "",
                time.monotonic() - started)


@pytest.mark.parametrize("how", ["api", "database"])
def test_revoking_a_key_closes_its_websockets_within_a_second(
        locked_server: LiveServer, repository: Repository, how: str) -> None:
    admin = _key(repository, ApiKeyRole.ADMIN, "admin")[1]
    robot_record, robot = _key(repository, ApiKeyRole.ROBOT, "robot to revoke")
    other = _key(repository, ApiKeyRole.ROBOT, "robot that stays")[1]
    session_id = _session(locked_server, repository, robot)
    base = f"{locked_server.ws_url}/monitor/{session_id}"

    async def scenario() -> None:
        async with connect(f"{base}?api_key={robot}") as runtime, \
                connect(f"{base}/events?api_key={robot}") as listener, \
                connect(f"{base}/events?api_key={other}") as bystander:
            assert await _step(runtime, 1) == "allow"
            assert json.loads(await listener.recv())["type"] == "status"
            assert json.loads(await bystander.recv())["type"] == "status"

            assert robot_record.id is not None
            if how == "api":
                revoked = await asyncio.to_thread(
                    httpx.delete, f"{locked_server.base_url}/keys/{robot_record.id}",
                    headers={"Authorization": f"Bearer {admin}"}, timeout=10)
                assert revoked.status_code == 200 and revoked.json()["revoked"] is True
            else:
                await asyncio.to_thread(repository.revoke_api_key, robot_record.id)

            for code, reason, seconds in await asyncio.gather(_closed(runtime),
                                                              _closed(listener)):
                assert (code, reason) == (CLOSE_KEY_REVOKED, REVOKED_REASON)
                assert seconds < WITHIN_SECONDS
            # Another key's socket is untouched.
            await bystander.ping()
            with pytest.raises(TimeoutError):
                await asyncio.wait_for(bystander.recv(), 0.2)

        # And the revoked key cannot open a new one.
        with pytest.raises(InvalidStatus):
            async with connect(f"{base}?api_key={robot}"):
                pass

    asyncio.run(scenario())


def test_a_session_survives_its_runtimes_key_being_revoked(
        locked_server: LiveServer, repository: Repository) -> None:
    """The session is not the key's: a runtime with a new key carries on where it was."""
    old_record, old = _key(repository, ApiKeyRole.ROBOT, "old robot key")
    new = _key(repository, ApiKeyRole.ROBOT, "new robot key")[1]
    session_id = _session(locked_server, repository, old)
    base = f"{locked_server.ws_url}/monitor/{session_id}"

    async def scenario() -> None:
        async with connect(f"{base}?api_key={old}") as runtime:
            assert await _step(runtime, 1) == "allow"
            assert old_record.id is not None
            await asyncio.to_thread(repository.revoke_api_key, old_record.id)
            assert (await _closed(runtime))[0] == CLOSE_KEY_REVOKED
        async with connect(f"{base}?api_key={new}") as runtime:
            assert await _step(runtime, 2) == "allow"
        summary = await asyncio.to_thread(
            httpx.get, f"{locked_server.base_url}/monitor/{session_id}/summary",
            headers={"X-API-Key": new}, timeout=10)
        assert summary.json()["actions_checked"] == 2

    asyncio.run(scenario())
