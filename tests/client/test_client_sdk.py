"""The client SDK against a real `safegate serve` on loopback (real HTTP, real websockets).

Includes the restart test: a session halted before the server process restarts is still refused
after it, and a running session keeps its pending action and state across a graceful restart.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import httpx
import pytest
from monitor_kit import (
    GO_TO_MUG,
    PICK_MUG,
    REQUEST,
    TOGGLE_STOVE,
    after,
    before,
    store_contract,
)
from safegate_client import (
    ApiError,
    GateClient,
    MonitorClient,
    MonitorError,
    MonitorEvents,
    MonitorHalted,
    MonitorResync,
    UnexpectedAnswer,
)
from safegate_client.models import (
    Action,
    ContractResponse,
    GateResponse,
    InitialState,
    Status,
    ViolationEvent,
)

from app.store.repository import Repository

StartServer = Callable[..., Any]


@pytest.fixture
def server(live_server: StartServer) -> Any:
    return live_server()


def open_session(server: Any, repository: Repository) -> str:
    with GateClient(server.base_url) as gate:
        return gate.open_monitor(store_contract(repository))


class TestGateClient:
    def test_gate_answers_the_servers_decision_as_a_model(self, server: Any) -> None:
        # The mug's temperature is not given: the gate asks before it authorizes.
        with GateClient(server.base_url) as gate:
            body = gate.gate(REQUEST)
        assert isinstance(body, GateResponse)
        assert (body.decision, body.rule, body.defer_kind) == ("defer", "R1b", "clarify")
        assert body.question and "mug_1" in body.question
        assert body.request_id

    def test_gate_asks_for_a_reference_plan_that_verify_passes(self, server: Any) -> None:
        from tests.scope_kit import TEA_REQUEST

        with GateClient(server.base_url) as gate:
            body = gate.gate(TEA_REQUEST, reference_plan=True)
            assert body.decision == "authorize", body
            assert body.contract_id is not None and body.reference_plan is not None
            plan = body.reference_plan.plan
            assert gate.verify(body.contract_id, plan).ok is True
            assert gate.gate(TEA_REQUEST).reference_plan is None

    def test_an_error_status_raises_with_the_problem(self, server: Any) -> None:
        with GateClient(server.base_url) as gate, pytest.raises(ApiError) as raised:
            gate.contract("no-such-contract")
        assert raised.value.status == 404
        assert raised.value.problem["status"] == 404

    def test_a_stored_contract_and_its_summary_are_read_back(
            self, server: Any, server_repository: Repository) -> None:
        contract_id = store_contract(server_repository)
        with GateClient(server.base_url) as gate:
            contract = gate.contract(contract_id)
            session_id = gate.open_monitor(contract_id)
            summary = gate.monitor_summary(session_id)
        assert isinstance(contract, ContractResponse)
        assert {g.id for g in contract.guards} >= {"skill.toggle", "skill.pick"}
        assert (summary.actions_checked, summary.halted) == (0, False)

    def test_verify_posts_the_spec_body(self) -> None:
        seen: list[dict[str, Any]] = []

        def handler(request: httpx.Request) -> httpx.Response:
            seen.append(json.loads(request.content))
            return httpx.Response(200, json={"ok": True, "violations": [], "attempts": 1,
                                             "attempts_left": 2, "decision": "authorize"})

        state = {"scene": {}, "robot": {"holding": None}}
        with GateClient("http://safegate.test", api_key="k",
                        transport=httpx.MockTransport(handler)) as gate:
            assert gate.verify("c1", [PICK_MUG], state).ok is True
            # Models are sent by their wire names, with the fields that were set (an explicit
            # null included: `holding: null` is "holds nothing", not "unknown").
            gate.verify("c1", [Action(action="PickupObject", object="mug_1")],
                        InitialState.model_validate(state))
        expected = {"contract_id": "c1", "plan": [PICK_MUG], "initial_state": state}
        assert seen == [expected, expected]

    def test_an_answer_of_the_wrong_shape_is_never_a_decision(self) -> None:
        def handler(request: httpx.Request) -> httpx.Response:
            return httpx.Response(200, json={"decision": "authorize", "rule": "R9"})

        with GateClient("http://safegate.test", transport=httpx.MockTransport(handler)) as gate, \
                pytest.raises(UnexpectedAnswer, match="not a GateResponse"):
            gate.gate({"command": "x"})


class TestMonitorClient:
    def test_a_safe_step_runs_the_action(self, server: Any,
                                         server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        ran: list[str] = []

        def go() -> None:
            ran.append("go")

        with MonitorClient(server.base_url, session_id) as monitor:
            monitor.step(GO_TO_MUG, go)
            monitor.step(PICK_MUG, lambda: {"robot": {"holding": "mug_1"}})
        assert ran == ["go"]

    def test_a_violation_raises_before_the_action_runs(
            self, server: Any, server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        ran: list[str] = []

        def toggle() -> None:
            ran.append("toggled")

        with MonitorClient(server.base_url, session_id) as monitor, \
                pytest.raises(MonitorHalted) as halted:
            monitor.step(TOGGLE_STOVE, toggle)
        assert ran == []
        assert halted.value.violation is not None
        assert halted.value.violation.condition_id == "skill.toggle"

    def test_an_unchecked_message_raises_monitor_error(
            self, server: Any, server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        with MonitorClient(server.base_url, session_id) as monitor, \
                pytest.raises(MonitorError, match="unknown action"):
            monitor.before({"action": "Teleport", "object": "mug_1"})

    def test_a_runtime_out_of_step_resyncs_and_goes_on(
            self, server: Any, server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        with MonitorClient(server.base_url, session_id) as monitor:
            monitor.step(GO_TO_MUG)
        # The runtime picked the mug up unmonitored (seq 2) and reconnects numbering from 3.
        with MonitorClient(server.base_url, session_id, first_seq=3) as monitor:
            with pytest.raises(MonitorResync) as resync:
                monitor.before(GO_TO_MUG)
            assert (resync.value.last_seq, resync.value.pending_seq) == (1, None)
            monitor.sync({"scene": REQUEST["scene"],
                          "robot": {**REQUEST["robot"], "holding": "mug_1"}}, seq=2)
            assert monitor.before(GO_TO_MUG) == 3
        with GateClient(server.base_url) as gate:
            summary = gate.monitor_summary(session_id)
        assert (summary.last_seq, summary.pending_seq) == (2, 3)

    def test_listeners_see_the_violation(self, server: Any,
                                         server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        with MonitorEvents(server.base_url, session_id) as events:
            status = events.next()
            assert isinstance(status, Status) and status.session_id == session_id
            with MonitorClient(server.base_url, session_id) as monitor, \
                    pytest.raises(MonitorHalted):
                monitor.before(TOGGLE_STOVE)
            event = events.next()
        assert isinstance(event, ViolationEvent)
        assert event.violation.condition_id == "skill.toggle"


class TestRestart:
    def test_a_halted_session_is_still_refused_after_a_server_restart(
            self, server: Any, server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        with MonitorClient(server.base_url, session_id) as monitor, pytest.raises(MonitorHalted):
            monitor.before(TOGGLE_STOVE)
        server.stop(kill=True)  # no graceful shutdown: the halt must already be on disk
        server.start()
        with MonitorClient(server.base_url, session_id, first_seq=2) as monitor, \
                pytest.raises(MonitorHalted) as refused:
            monitor.before(GO_TO_MUG)
        assert refused.value.answer.type == "halted"
        assert refused.value.violation is not None
        assert refused.value.violation.condition_id == "skill.toggle"
        with GateClient(server.base_url) as gate:
            assert gate.monitor_summary(session_id).halted is True

    def test_a_running_session_resumes_its_pending_action_after_a_restart(
            self, server: Any, server_repository: Repository) -> None:
        session_id = open_session(server, server_repository)
        with MonitorClient(server.base_url, session_id) as monitor:
            monitor.step(GO_TO_MUG)
            monitor.before(PICK_MUG)
        server.stop()
        server.start()
        with GateClient(server.base_url) as gate:
            summary = gate.monitor_summary(session_id)
        assert (summary.last_seq, summary.pending_seq) == (1, 2)
        import websockets.sync.client as ws

        with ws.connect(server.ws_url + f"/monitor/{session_id}") as socket:
            socket.send(json.dumps(after(2, PICK_MUG)))
            assert json.loads(socket.recv(timeout=10)) == {"type": "allow", "seq": 2}
            socket.send(json.dumps(before(3, TOGGLE_STOVE)))
            assert json.loads(socket.recv(timeout=10))["type"] == "violation"


class TestOldImports:
    def test_app_client_re_exports_the_sdk(self) -> None:
        import safegate_client

        import app.client

        for name in app.client.__all__:
            assert getattr(app.client, name) is getattr(safegate_client, name), name
