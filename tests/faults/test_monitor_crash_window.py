"""The crash window: a monitor's answer is durable before it is sent (issue 18, item 2).

A real `safegate serve`, on SQLite and on PostgreSQL, monitors the knife-to-the-block task:
`GoToObject knife_1` and `PickupObject knife_1` are allowed; the process is then SIGKILLed 0,
0.05, 0.25 or 0.6 s after that last answer, with the runtime still connected (so no disconnect
gets a chance to write anything), and started again on the same database. The session must stand
exactly where the answers left it (last seq 2, two actions and two states checked, the robot
holding the knife), so step 3, carrying the knife towards the seated owner at 1 m/s, is a
violation as it would have been without the crash. From the forgotten initial state (the knife
still on the counter) the same step is allowed twice: `test_..._forgotten_state_...` shows it,
so the crash test tells the two apart.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from typing import Any

import httpx
import pytest
from fastapi.testclient import TestClient
from monitor_kit import (
    CARRY_KNIFE_FAST,
    GO_TO_KNIFE,
    PICK_KNIFE,
    after,
    before,
    store_knife_contract,
)
from replica_kit import BLADE_NEAR_PERSON, knife_contract_in
from websockets.sync.client import ClientConnection, connect

from app.store.repository import Repository

pytestmark = [pytest.mark.faults, pytest.mark.slow]

KILL_DELAYS = [0.0, 0.05, 0.25, 0.6]


def exchange(socket: ClientConnection, message: dict[str, Any]) -> dict[str, Any]:
    socket.send(json.dumps(message))
    answer: dict[str, Any] = json.loads(socket.recv(timeout=10))
    return answer


def summary_of(server: Any, session_id: str) -> dict[str, Any]:
    answer: dict[str, Any] = httpx.get(f"{server.base_url}/monitor/{session_id}/summary",
                                       timeout=10).json()
    return answer


def crash_after_two_steps(server: Any, contract_id: str, delay: float) -> str:
    """Open a session, get steps 1 and 2 allowed, SIGKILL the server `delay` s after the last
    answer with the runtime still connected, and start it again; returns the session id."""
    session_id: str = httpx.post(f"{server.base_url}/monitor", json={"contract_id": contract_id},
                                 timeout=10).json()["session_id"]
    with connect(f"{server.ws_url}/monitor/{session_id}", open_timeout=10) as socket:
        answers = [exchange(socket, message) for message in (
            before(1, GO_TO_KNIFE), after(1, GO_TO_KNIFE),
            before(2, PICK_KNIFE), after(2, PICK_KNIFE))]
        assert [a["type"] for a in answers] == ["allow"] * 4
        time.sleep(delay)
        server.stop(kill=True)  # still connected: no disconnect gets to write anything
    assert server.process.returncode == -9
    server.start()
    return session_id


class TestCrashWindow:
    def test_after_a_sigkill_the_next_step_is_checked_against_the_last_answered_state(
        self, live_server: Callable[..., Any], database_url: str
    ) -> None:
        contract_id = knife_contract_in(database_url)
        server = live_server(database_url, SAFEGATE_LOG_LEVEL="warning")
        for delay in KILL_DELAYS:  # one server, killed and restarted once per delay
            session_id = crash_after_two_steps(server, contract_id, delay)
            summary = summary_of(server, session_id)
            assert (summary["last_seq"], summary["pending_seq"], summary["actions_checked"],
                    summary["states_checked"], summary["halted"]) == (2, None, 2, 2, False), (
                delay, summary)
            with connect(f"{server.ws_url}/monitor/{session_id}", open_timeout=10) as socket:
                step3 = [exchange(socket, before(3, CARRY_KNIFE_FAST)),
                         exchange(socket, after(3, CARRY_KNIFE_FAST))]
            assert [a["type"] for a in step3] == ["allow", "violation"], (delay, step3)
            assert step3[1]["violation"]["condition_id"] == BLADE_NEAR_PERSON
            assert summary_of(server, session_id)["halted"] is True

    def test_from_the_forgotten_state_the_same_step_would_be_allowed(
        self, client: TestClient
    ) -> None:
        """What the crash test guards against: step 3 checked against the initial state."""
        engine = client.app.state.components.engine  # type: ignore[attr-defined]
        contract_id = store_knife_contract(Repository(engine))
        session_id = client.post("/monitor", json={"contract_id": contract_id}).json()[
            "session_id"]
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            for message in (before(3, CARRY_KNIFE_FAST), after(3, CARRY_KNIFE_FAST)):
                socket.send_json(message)
                assert socket.receive_json() == {"type": "allow", "seq": 3}
