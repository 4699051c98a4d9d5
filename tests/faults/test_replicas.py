"""Two replicas on one PostgreSQL (issue 18, item 5): real `safegate serve` processes on loopback.

- A halt raised through replica A reaches a watcher (`/events` websocket) on replica B, through
  PostgreSQL LISTEN/NOTIFY, and B's summary and a runtime on B see the session halted.
- Replica A is SIGKILLed mid-session with its runtime connected; the runtime (the SDK's
  `MonitorClient`, given B as its fallback) reconnects to B and goes on from the durable state:
  no step lost (step 3, carrying the knife fast towards the seated owner, is a violation only
  because steps 1 and 2, answered by A, left the knife in the robot's hand).
- A runtime that lost its place resumes on B through the resync protocol.
The knife task is `tests/monitor_kit.py`'s (see `test_monitor_crash_window.py`).
"""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import httpx
import pytest
from monitor_kit import (
    CARRY_KNIFE_FAST,
    GO_TO_KNIFE,
    KNIFE_REQUEST,
    PICK_KNIFE,
    after,
    before,
)
from replica_kit import BLADE_NEAR_PERSON, QUIET, knife_contract_in, open_session
from safegate_client import MonitorClient, MonitorHalted
from websockets.sync.client import ClientConnection, connect

pytestmark = [pytest.mark.faults, pytest.mark.slow, pytest.mark.postgres]


def knife_session_on_two_replicas(live_server: Callable[..., Any], url: str
                                  ) -> tuple[Any, Any, str]:
    """Replicas A and B on one database, and a session on the knife contract opened on A."""
    contract_id = knife_contract_in(url)
    a, b = live_server(url, **QUIET), live_server(url, **QUIET)
    return a, b, open_session(a, contract_id)


def socket_to(server: Any, session_id: str, channel: str = "") -> ClientConnection:
    """The session's runtime websocket on `server` (`channel="/events"`: its watcher)."""
    return connect(f"{server.ws_url}/monitor/{session_id}{channel}", open_timeout=10)


def exchange(socket: ClientConnection, message: dict[str, Any]) -> dict[str, Any]:
    socket.send(json.dumps(message))
    answer: dict[str, Any] = json.loads(socket.recv(timeout=10))
    return answer


def next_event(watcher: ClientConnection, timeout: float = 5.0) -> dict[str, Any]:
    event: dict[str, Any] = json.loads(watcher.recv(timeout=timeout))
    return event


def summary_of(server: Any, session_id: str) -> dict[str, Any]:
    answer: dict[str, Any] = httpx.get(f"{server.base_url}/monitor/{session_id}/summary",
                                       timeout=10).json()
    return answer


class TestHaltFanOut:
    def test_a_halt_raised_through_a_reaches_a_watcher_on_b(
        self, live_server: Callable[..., Any], postgres_url: str
    ) -> None:
        a, b, session_id = knife_session_on_two_replicas(live_server, postgres_url)
        with socket_to(b, session_id, "/events") as watcher:
            assert next_event(watcher)["halted"] is False  # the status, from B
            with socket_to(a, session_id) as runtime:
                for message in (before(1, GO_TO_KNIFE), after(1, GO_TO_KNIFE),
                                before(2, PICK_KNIFE), after(2, PICK_KNIFE),
                                before(3, CARRY_KNIFE_FAST)):
                    assert exchange(runtime, message)["type"] == "allow"
                answer = exchange(runtime, after(3, CARRY_KNIFE_FAST))
                assert answer["type"] == "violation"
                event = next_event(watcher)
                refused = exchange(runtime, before(4, GO_TO_KNIFE))
                refusal = next_event(watcher)
        assert event == {"session_id": session_id, **answer}
        assert event["violation"]["condition_id"] == BLADE_NEAR_PERSON
        assert refused["type"] == "halted" and refusal == {"session_id": session_id, **refused}
        assert summary_of(b, session_id)["halted"] is True
        with socket_to(b, session_id) as runtime_on_b:
            assert exchange(runtime_on_b, before(4, GO_TO_KNIFE))["type"] == "halted"

    def test_a_watcher_on_a_replica_that_drives_nothing_gets_nothing_but_the_status(
        self, live_server: Callable[..., Any], postgres_url: str
    ) -> None:
        """Allows are not fanned out; only violations and refusals are events."""
        a, b, session_id = knife_session_on_two_replicas(live_server, postgres_url)
        with socket_to(b, session_id, "/events") as watcher:
            next_event(watcher)
            with socket_to(a, session_id) as runtime:
                assert exchange(runtime, before(1, GO_TO_KNIFE))["type"] == "allow"
            with pytest.raises(TimeoutError):
                watcher.recv(timeout=0.5)


class TestFailover:
    def test_sigkill_of_a_mid_session_the_runtime_goes_on_on_b_with_no_step_lost(
        self, live_server: Callable[..., Any], postgres_url: str
    ) -> None:
        a, b, session_id = knife_session_on_two_replicas(live_server, postgres_url)
        with socket_to(b, session_id, "/events") as watcher, \
                MonitorClient(a.base_url, session_id, fallback_urls=[b.base_url],
                              reconnects=3) as runtime:
            next_event(watcher)
            runtime.step(GO_TO_KNIFE)
            runtime.step(PICK_KNIFE)
            a.stop(kill=True)  # the runtime is still connected to A: nothing gets written
            assert a.process.returncode == -9
            assert summary_of(b, session_id)["last_seq"] == 2
            seq = runtime.before(CARRY_KNIFE_FAST)  # reconnects to B
            assert runtime.url.startswith(b.ws_url)
            with pytest.raises(MonitorHalted) as halted:
                runtime.after()
            event = next_event(watcher)
        assert seq == 3
        assert halted.value.violation is not None
        assert halted.value.violation.condition_id == BLADE_NEAR_PERSON
        assert event["type"] == "violation" and event["seq"] == 3
        summary = summary_of(b, session_id)
        assert (summary["actions_checked"], summary["states_checked"], summary["halted"]) == (
            3, 3, True)
        assert [v["seq"] for v in summary["violations"]] == [3]

    def test_an_action_allowed_by_a_is_finished_on_b_and_a_lost_runtime_resyncs_there(
        self, live_server: Callable[..., Any], postgres_url: str
    ) -> None:
        a, b, session_id = knife_session_on_two_replicas(live_server, postgres_url)
        with MonitorClient(a.base_url, session_id, fallback_urls=[b.base_url]) as runtime:
            runtime.step(GO_TO_KNIFE)
            assert runtime.before(PICK_KNIFE) == 2  # allowed by A, running when A dies
            a.stop(kill=True)
            runtime.after()  # B restored the pending action from A's durable log
        assert summary_of(b, session_id)["last_seq"] == 2
        # A runtime restarted without its place, which moved the knife to the block
        # unmonitored (actions 3 and 4), resumes on B from its current state.
        knife_in_block = {
            "scene": {"objects": [{"id": "knife_1", "type": "Knife", "room": "kitchen",
                                   "in": "block_1", "properties": {"sharp": True}}]},
            "robot": {**KNIFE_REQUEST["robot"], "holding": None},
        }
        with MonitorClient(b.base_url, session_id, first_seq=5,
                           current_state=lambda: knife_in_block) as restarted:
            restarted.step(CARRY_KNIFE_FAST)  # empty-handed now: allowed
        summary = summary_of(b, session_id)
        assert (summary["last_seq"], summary["halted"]) == (5, False)
