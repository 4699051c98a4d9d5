"""Runtime monitoring over HTTP and websockets, in process (TestClient) and on SQLite/PostgreSQL.

The restart test and the real-websocket tests live in `tests/client/` (they run uvicorn).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import (
    GO_TO_MUG,
    PICK_MUG,
    REQUEST,
    TOGGLE_STOVE,
    after,
    before,
    store_contract,
)

from app.config import Settings
from app.domain.errors import Unavailable
from app.main import create_app
from app.store.repository import MonitorRepository, Repository


def repository_of(client: TestClient) -> Repository:
    repository = Repository(client.app.state.components.engine)  # type: ignore[attr-defined]
    return repository


def monitor_repository_of(client: TestClient) -> MonitorRepository:
    """The repository the app's monitoring service writes its steps with."""
    repository: MonitorRepository = client.app.state.components.repositories.monitoring  # type: ignore[attr-defined]
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
                "detail": "unknown message type 'launch': expected 'before', 'after' or 'sync'"}
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


def exchange(socket: Any, message: dict[str, Any]) -> dict[str, Any]:
    socket.send_json(message)
    answer: dict[str, Any] = socket.receive_json()
    return answer


def logged(client: TestClient, session_id: str) -> list[tuple[Any, str]]:
    """The (seq, answer) pairs in a session's stored log."""
    return [(entry["in"].get("seq"), entry["out"])
            for event in repository_of(client).list_monitor_events(session_id)
            for entry in event.payload["messages"]]


def sync(seq: int, holding: str | None = None, room: str = "kitchen") -> dict[str, Any]:
    """A runtime's resync: its whole current state after action `seq`."""
    robot = {**REQUEST["robot"], "room": room, "holding": holding}
    return {"type": "sync", "seq": seq, "state": {"scene": REQUEST["scene"], "robot": robot}}


def failing_writes(monkeypatch: pytest.MonkeyPatch, repository: MonitorRepository) -> None:
    def unavailable(*_: Any, **__: Any) -> None:
        raise Unavailable("database error while writing monitor steps: OperationalError",
                          dependency="database")

    monkeypatch.setattr(repository, "write_monitor_logs", unavailable)


class TestDurableSteps:
    """Issue 18, item 2: an answer is sent only once the step it answers is stored."""

    def test_an_allowed_step_is_stored_before_it_is_answered(
            self, client_on: TestClient) -> None:
        session_id = open_session(client_on)
        with client_on.websocket_connect(f"/monitor/{session_id}") as socket:
            assert exchange(socket, before(1, PICK_MUG))["type"] == "allow"
            assert logged(client_on, session_id) == [(1, "allow")]
            assert exchange(socket, after(1, PICK_MUG))["type"] == "allow"
            assert logged(client_on, session_id) == [(1, "allow"), (1, "allow")]
            socket.send_text("junk")  # refusals change nothing: they wait for no write
            assert socket.receive_json()["type"] == "error"
        deadline = time.monotonic() + 10  # written when the runtime disconnects
        while logged(client_on, session_id)[-1] != (None, "error") and time.monotonic() < deadline:
            time.sleep(0.02)
        assert logged(client_on, session_id)[-1] == (None, "error")

    def test_a_step_that_cannot_be_stored_is_not_allowed_and_the_session_goes_on_from_the_store(
            self, client: TestClient, monkeypatch: pytest.MonkeyPatch) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            assert exchange(socket, before(1, PICK_MUG))["type"] == "allow"
            with monkeypatch.context() as patch:
                failing_writes(patch, monitor_repository_of(client))
                refused = exchange(socket, after(1, PICK_MUG))
            assert (refused["type"], refused["seq"], refused["halted"]) == ("error", 1, False)
            assert "could not be stored" in refused["detail"]
            summary = client.get(f"/monitor/{session_id}/summary").json()
            assert (summary["last_seq"], summary["pending_seq"]) == (None, 1)
            assert exchange(socket, after(1, PICK_MUG)) == {"type": "allow", "seq": 1}
            assert exchange(socket, before(2, GO_TO_MUG)) == {"type": "allow", "seq": 2}
        assert logged(client, session_id) == [(1, "allow"), (1, "allow"), (2, "allow")]

    def test_a_halt_that_cannot_be_stored_is_still_answered_and_stored_later(
            self, client: TestClient, monkeypatch: pytest.MonkeyPatch) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket, \
                monkeypatch.context() as patch:
            failing_writes(patch, monitor_repository_of(client))
            answer = exchange(socket, before(1, TOGGLE_STOVE))
            assert answer["type"] == "violation"  # halting is the safe side
            assert exchange(socket, before(2, GO_TO_MUG))["type"] == "halted"
            assert not repository_of(client).get_monitor_session(session_id).halted
        deadline = time.monotonic() + 10  # retried when the runtime disconnects
        while (not repository_of(client).get_monitor_session(session_id).halted
               and time.monotonic() < deadline):
            time.sleep(0.02)
        stored = repository_of(client).get_monitor_session(session_id)
        assert stored.halted and stored.halt_violation is not None

    def test_a_runtime_out_of_step_is_asked_to_resync_and_goes_on_after_its_sync(
            self, client: TestClient) -> None:
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            for message in (before(1, GO_TO_MUG), after(1, GO_TO_MUG)):
                assert exchange(socket, message)["type"] == "allow"
            out_of_step = exchange(socket, before(3, GO_TO_MUG))  # 2 ran unmonitored
            assert out_of_step["type"] == "error" and out_of_step["halted"] is False
            assert out_of_step["resync"] == {"last_seq": 1, "pending_seq": None}
            assert exchange(socket, sync(2, holding="mug_1")) == {"type": "allow", "seq": 2}
        with client.websocket_connect(f"/monitor/{session_id}") as socket:  # the sync is stored
            assert exchange(socket, before(3, GO_TO_MUG)) == {"type": "allow", "seq": 3}
        summary = client.get(f"/monitor/{session_id}/summary").json()
        assert (summary["last_seq"], summary["pending_seq"]) == (2, 3)

    def test_another_writer_makes_this_process_reload_rather_than_answer_from_memory(
            self, client: TestClient, sqlite_url: str) -> None:
        """Two processes on one session: the stale one's next write fails, so it reloads."""
        session_id = open_session(client)
        with client.websocket_connect(f"/monitor/{session_id}") as stale:
            assert exchange(stale, before(1, PICK_MUG))["type"] == "allow"
            with TestClient(create_app(Settings(database_url=sqlite_url))) as other, \
                    other.websocket_connect(f"/monitor/{session_id}") as socket:
                for message in (after(1, PICK_MUG), before(2, GO_TO_MUG), after(2, GO_TO_MUG)):
                    assert exchange(socket, message)["type"] == "allow"
            refused = exchange(stale, after(1, PICK_MUG))  # stale memory would allow it
            assert refused["type"] == "error" and "could not be stored" in refused["detail"]
            assert exchange(stale, after(1, PICK_MUG))["resync"] == {
                "last_seq": 2, "pending_seq": None}  # reloaded: 1 and 2 are done
            assert exchange(stale, before(3, GO_TO_MUG)) == {"type": "allow", "seq": 3}

    def test_a_log_that_does_not_replay_to_its_answers_asks_the_runtime_to_resync(
            self, client: TestClient) -> None:
        """A log written before seqs had to follow each other (5 came after 1) is not trusted
        to rebuild the state: the runtime is asked for it."""
        session_id = open_session(client)
        repository_of(client).append_monitor_event(session_id, "messages", {"messages": [
            {"in": before(1, GO_TO_MUG), "out": "allow"},
            {"in": after(1, GO_TO_MUG), "out": "allow"},
            {"in": before(5, PICK_MUG), "out": "allow"}]})
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            refused = exchange(socket, after(5, PICK_MUG))
            assert refused["type"] == "error" and "resync" in refused
            assert "could not be rebuilt" in refused["detail"]
            assert exchange(socket, sync(5, holding="mug_1"))["type"] == "allow"
            assert exchange(socket, before(6, GO_TO_MUG))["type"] == "allow"


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
