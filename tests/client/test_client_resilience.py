"""The SDK under failure: retries and timeouts never become an allow; the async client; the
monitor client reconnecting and resuming with the resync protocol (real server on loopback).
"""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable, Iterator
from typing import Any

import httpx
import pytest
from monitor_kit import GO_TO_MUG, PICK_MUG, REQUEST, TOGGLE_STOVE, store_contract
from safegate_client import (
    ApiError,
    AsyncGateClient,
    GateClient,
    MonitorClient,
    MonitorHalted,
    RetryPolicy,
    SafeGateUnavailable,
    UnexpectedAnswer,
)
from safegate_client.models import GateRequest, GateResponse, VerifyResponse
from websockets.sync.server import Server, ServerConnection, serve

from app.store.repository import Repository

FAST = RetryPolicy(attempts=3, backoff=0.01, max_wait=0.05)
BUSY = {"type": "https://safegate.dev/problems/busy", "title": "Busy", "status": 503,
        "detail": "the analysis workers are full"}


def counting(answers: list[httpx.Response | Exception]) -> tuple[httpx.MockTransport, list[int]]:
    """A transport giving `answers` in turn (the last one again and again), and a call count."""
    calls = [0]

    def handler(request: httpx.Request) -> httpx.Response:
        answer = answers[min(calls[0], len(answers) - 1)]
        calls[0] += 1
        if isinstance(answer, Exception):
            raise answer
        return answer

    return httpx.MockTransport(handler), calls


class TestRetries:
    def test_a_busy_gate_is_asked_again_and_its_answer_used(self) -> None:
        decision = {"request_id": "r1", "decision": "reject", "rule": "R1", "defer_kind": None,
                    "question": None, "reason": "a child", "hazards": [], "unknowns": [],
                    "triggers": [], "contract_id": None, "analyzer": "symbolic"}
        transport, calls = counting([
            httpx.Response(503, json=BUSY, headers={"Retry-After": "0"}),
            httpx.Response(200, json=decision)])
        with GateClient("http://safegate.test", retry=FAST, transport=transport) as gate:
            assert gate.gate({"command": "x"}) == GateResponse.model_validate(decision)
        assert calls[0] == 2

    def test_a_gate_busy_through_every_retry_raises_and_never_decides(self) -> None:
        transport, calls = counting([httpx.Response(503, json=BUSY)])
        with GateClient("http://safegate.test", retry=FAST, transport=transport) as gate, \
                pytest.raises(ApiError) as raised:
            gate.gate({"command": "x"})
        assert (raised.value.status, calls[0]) == (503, 3)

    def test_an_unreachable_gate_raises_unavailable(self) -> None:
        transport, calls = counting([httpx.ConnectError("refused")])
        with GateClient("http://safegate.test", retry=FAST, transport=transport) as gate, \
                pytest.raises(SafeGateUnavailable, match="nothing was decided"):
            gate.gate({"command": "x"})
        assert calls[0] == 3

    def test_a_timeout_is_retried_then_raised(self) -> None:
        transport, calls = counting([httpx.ReadTimeout("slow")])
        with GateClient("http://safegate.test", retry=FAST, transport=transport) as gate, \
                pytest.raises(SafeGateUnavailable):
            gate.verify("c1", [PICK_MUG])
        assert calls[0] == 3

    def test_bad_input_is_not_retried(self) -> None:
        problem = {"type": "x", "title": "Invalid request", "status": 422, "detail": "bad"}
        transport, calls = counting([httpx.Response(422, json=problem)])
        with GateClient("http://safegate.test", retry=FAST, transport=transport) as gate, \
                pytest.raises(ApiError):
            gate.gate({"command": ""})
        assert calls[0] == 1

    def test_retry_after_is_honoured_up_to_the_cap(self) -> None:
        policy = RetryPolicy(attempts=3, backoff=0.1, max_wait=2.0)
        assert policy.wait(1, httpx.Response(503, headers={"Retry-After": "1"})) == 1.0
        assert policy.wait(1, httpx.Response(503, headers={"Retry-After": "60"})) == 2.0
        assert policy.wait(2, httpx.ConnectError("x")) == pytest.approx(0.2)


class TestAsyncGateClient:
    def test_the_async_client_decides_verifies_and_opens_a_session(
            self, live_server: Callable[..., Any], server_repository: Repository) -> None:
        server = live_server()
        contract_id = store_contract(server_repository)

        async def run() -> tuple[GateResponse, VerifyResponse, str]:
            async with AsyncGateClient(server.base_url) as gate:
                decision = await gate.gate(GateRequest.model_validate(REQUEST))
                verdict = await gate.verify(contract_id, [GO_TO_MUG, PICK_MUG])
                return decision, verdict, await gate.open_monitor(contract_id)

        decision, verdict, session_id = asyncio.run(run())
        assert (decision.decision, decision.rule) == ("defer", "R1b")
        assert verdict.ok is True
        assert session_id

    def test_the_async_client_raises_for_an_error_status(
            self, live_server: Callable[..., Any]) -> None:
        server = live_server()

        async def run() -> None:
            async with AsyncGateClient(server.base_url) as gate:
                await gate.contract("no-such-contract")

        with pytest.raises(ApiError) as raised:
            asyncio.run(run())
        assert raised.value.status == 404


class TestMonitorReconnect:
    def test_a_dropped_socket_is_reopened_and_the_step_goes_on(
            self, live_server: Callable[..., Any], server_repository: Repository) -> None:
        server = live_server()
        with GateClient(server.base_url) as gate:
            session_id = gate.open_monitor(store_contract(server_repository))
        with MonitorClient(server.base_url, session_id) as monitor:
            monitor.before(GO_TO_MUG)
            assert monitor._socket is not None
            monitor._socket.close()  # the network drops between before and after
            monitor.after()
            monitor.step(PICK_MUG, lambda: {"robot": {"holding": "mug_1"}})
        with GateClient(server.base_url) as gate:
            summary = gate.monitor_summary(session_id)
        assert (summary.last_seq, summary.pending_seq, summary.errors) == (2, None, 0)

    def test_an_after_the_monitor_already_holds_counts_as_accepted(
            self, live_server: Callable[..., Any], server_repository: Repository) -> None:
        server = live_server()
        with GateClient(server.base_url) as gate:
            session_id = gate.open_monitor(store_contract(server_repository))
        with MonitorClient(server.base_url, session_id) as monitor:
            monitor.before(GO_TO_MUG)
            socket = monitor._socket
            assert socket is not None
            # The `after` reaches the server, but its answer is lost with the connection.
            socket.send('{"type": "after", "seq": 1, "action": ' +
                        '{"action": "GoToObject", "object": "mug_1"}}')
            socket.recv(timeout=10)
            socket.close()
            monitor.after()  # resent on a new socket: the monitor answers "already at 1"
            assert monitor.before(PICK_MUG) == 2

    def test_out_of_step_it_syncs_the_current_state_and_resends(
            self, live_server: Callable[..., Any], server_repository: Repository) -> None:
        server = live_server()
        with GateClient(server.base_url) as gate:
            session_id = gate.open_monitor(store_contract(server_repository))
        with MonitorClient(server.base_url, session_id) as monitor:
            monitor.step(GO_TO_MUG)
        holding = {"scene": REQUEST["scene"], "robot": {**REQUEST["robot"], "holding": "mug_1"}}
        # The runtime picked the mug up unmonitored (seq 2) and comes back numbering from 3.
        with MonitorClient(server.base_url, session_id, first_seq=3,
                           current_state=lambda: holding) as monitor:
            assert monitor.before(GO_TO_MUG) == 3
        with GateClient(server.base_url) as gate:
            summary = gate.monitor_summary(session_id)
        assert (summary.last_seq, summary.pending_seq) == (2, 3)

    def test_a_halt_is_never_resumed_past(
            self, live_server: Callable[..., Any], server_repository: Repository) -> None:
        server = live_server()
        with GateClient(server.base_url) as gate:
            session_id = gate.open_monitor(store_contract(server_repository))
        with MonitorClient(server.base_url, session_id,
                           current_state=lambda: {"scene": {}, "robot": {}}) as monitor:
            with pytest.raises(MonitorHalted):
                monitor.before(TOGGLE_STOVE)
            assert monitor._socket is not None
            monitor._socket.close()
            with pytest.raises(MonitorHalted):
                monitor.before(GO_TO_MUG)


@pytest.fixture
def garbling_monitor() -> Iterator[str]:
    """A websocket server on loopback answering every message with something that is none of
    the protocol's answers (`"allowed"` is not `"allow"`); yields its base URL."""
    def answer(connection: ServerConnection) -> None:
        for _ in connection:
            connection.send('{"type": "allowed", "seq": 1}')

    server: Server = serve(answer, "127.0.0.1", 0)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{server.socket.getsockname()[1]}"
    server.shutdown()
    thread.join(timeout=10)


class TestUnreadableMonitorAnswers:
    def test_an_answer_of_no_known_type_never_lets_the_action_run(
            self, garbling_monitor: str) -> None:
        ran: list[str] = []
        with MonitorClient(garbling_monitor, "s1") as monitor, \
                pytest.raises(UnexpectedAnswer, match="none of the protocol's"):
            monitor.step(GO_TO_MUG, lambda: ran.append("moved"))
        assert ran == []
