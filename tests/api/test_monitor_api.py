"""Runtime monitoring over HTTP and websockets, in process (TestClient) and on SQLite/PostgreSQL.

The restart test and the real-websocket tests live in `tests/client/` (they run uvicorn).
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import (
    GO_TO_MUG,
    PICK_MUG,
    TOGGLE_STOVE,
    after,
    before,
    store_contract,
)

from app.store.repository import Repository


def repository_of(client: TestClient) -> Repository:
    repository: Repository = client.app.state.services.repository  # type: ignore[attr-defined]
    return repository


def open_session(client: TestClient, **body: Any) -> str:
    contract_id = store_contract(repository_of(client))
    response = client.post("/monitor", json={"contract_id": contract_id, **body})
    assert response.status_code == 201, response.text
    session_id: str = response.json()["session_id"]
    return session_id


class TestOpenSession:
    def test_a_session_opens_on_a_stored_contract(self, client_on: TestClient) -> None:
        session_id = open_session(client_on)
        stored = repository_of(client_on).get_monitor_session(session_id)
        assert not stored.halted
        assert stored.initial_state.scene is not None  # defaulted from the gate request

    def test_an_unknown_contract_is_404(self, client: TestClient) -> None:
        response = client.post("/monitor", json={"contract_id": "nope"})
        assert response.status_code == 404
        assert response.headers["content-type"] == "application/problem+json"

    def test_an_exhausted_contract_is_409(self, client: TestClient) -> None:
        contract_id = store_contract(repository_of(client))
        repository_of(client).mark_contract_exhausted(contract_id)
        assert client.post("/monitor", json={"contract_id": contract_id}).status_code == 409

    def test_an_explicit_initial_state_is_used(self, client: TestClient) -> None:
        state = {"scene": {"objects": [{"id": "stove_1", "type": "StoveBurner",
                                        "room": "kitchen"}]},
                 "robot": {"room": "kitchen", "skills": ["toggle"]}}
        session_id = open_session(client, initial_state=state)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(before(1, TOGGLE_STOVE))
            assert socket.receive_json()["type"] == "allow"

    def test_a_malformed_body_is_422(self, client: TestClient) -> None:
        assert client.post("/monitor", json={"contract": "x"}).status_code == 422


class TestMonitorSocket:
    def test_each_message_gets_its_answer_in_order(self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            for message in (before(1, GO_TO_MUG), after(1, GO_TO_MUG), before(2, PICK_MUG)):
                socket.send_json(message)
                assert socket.receive_json() == {"type": "allow", "seq": message["seq"]}

    def test_a_violation_halts_and_is_stored_before_it_is_answered(
            self, client_on: TestClient) -> None:
        session_id = open_session(client_on)
        with client_on.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(before(1, TOGGLE_STOVE))
            answer = socket.receive_json()
            assert answer["type"] == "violation" and answer["halted"] is True
            stored = repository_of(client_on).get_monitor_session(session_id)
            assert stored.halted
            assert stored.halt_violation is not None
            assert stored.halt_violation["condition_id"] == "skill.toggle"

    def test_a_halt_holds_across_reconnects(self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(before(1, TOGGLE_STOVE))
            socket.receive_json()
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(before(2, GO_TO_MUG))
            answer = socket.receive_json()
        assert answer["type"] == "halted"
        assert answer["violation"]["condition_id"] == "skill.toggle"

    def test_garbage_gets_an_error_and_the_session_goes_on(self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_text("{{{")
            assert socket.receive_json()["type"] == "error"
            socket.send_bytes(b"\x00\xff")
            assert socket.receive_json()["type"] == "error"
            socket.send_json({"type": "launch", "seq": 3})
            assert socket.receive_json() == {
                "type": "error", "seq": 3, "halted": False,
                "detail": "unknown message type 'launch': expected 'before' or 'after'"}
            socket.send_json(before(4, GO_TO_MUG))
            assert socket.receive_json()["type"] == "allow"

    def test_an_unknown_session_is_told_and_closed(self, client: TestClient) -> None:
        with client.websocket_connect("/monitor/nope") as socket:
            assert socket.receive_json()["type"] == "error"
            with pytest.raises(WebSocketDisconnect) as closed:
                socket.receive_json()
        assert closed.value.code == 4404

    def test_a_pending_action_survives_a_reconnect(self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(before(1, PICK_MUG))
            socket.receive_json()
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(after(1, PICK_MUG))
            assert socket.receive_json() == {"type": "allow", "seq": 1}


class TestEventsSocket:
    def test_every_listener_gets_the_violation(self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}/events") as first, \
                client.websocket_connect(f"/monitor/{session_id}/events") as second:
            for listener in (first, second):
                assert listener.receive_json() == {"type": "status", "session_id": session_id,
                                                   "halted": False, "violation": None}
            with client.websocket_connect(f"/monitor/{session_id}") as socket:
                socket.send_json(before(1, GO_TO_MUG))
                socket.receive_json()
                socket.send_json(before(1, TOGGLE_STOVE))  # a re-sent before: checked again
                socket.receive_json()
                socket.send_json(before(2, GO_TO_MUG))
                socket.receive_json()
            for listener in (first, second):
                violation = listener.receive_json()
                assert violation["type"] == "violation"
                assert violation["session_id"] == session_id
                assert violation["violation"]["condition_id"] == "skill.toggle"
                refused = listener.receive_json()
                assert (refused["type"], refused["seq"]) == ("halted", 2)

    def test_a_late_listener_learns_the_session_is_halted(self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_json(before(1, TOGGLE_STOVE))
            socket.receive_json()
        with client.websocket_connect(f"/monitor/{session_id}/events") as listener:
            status = listener.receive_json()
        assert status["halted"] is True
        assert status["violation"]["condition_id"] == "skill.toggle"


class TestSummary:
    def test_the_summary_reports_checks_and_the_violation(self, client_on: TestClient) -> None:
        session_id = open_session(client_on)
        with client_on.websocket_connect(f"/monitor/{session_id}") as socket:
            for message in (before(1, PICK_MUG), after(1, PICK_MUG), before(2, TOGGLE_STOVE)):
                socket.send_json(message)
                socket.receive_json()
        body = client_on.get(f"/monitor/{session_id}/summary").json()
        assert body["session_id"] == session_id
        assert (body["actions_checked"], body["guards_checked"]) == (2, 2)
        assert (body["invariants_checked"], body["aborts_checked"]) == (1, 3)
        assert body["halted"] is True
        assert [v["condition_id"] for v in body["violations"]] == ["skill.toggle"]

    def test_an_unknown_session_is_404(self, client: TestClient) -> None:
        assert client.get("/monitor/nope/summary").status_code == 404
