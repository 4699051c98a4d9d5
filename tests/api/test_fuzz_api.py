"""Schemathesis against the OpenAPI spec of a real `safegate serve` on loopback.

Every operation of the served spec gets `SAFEGATE_FUZZ_EXAMPLES` generated requests (default 15;
`make fuzz` runs more) that fit the schema, and as many that break it, from a derandomized seed,
so a run is repeatable. The caller holds an admin key, so the curator and key endpoints are
fuzzed past their authentication too. The properties, for every answer:
- never a 5xx;
- every 4xx is `application/problem+json` whose `status` is the HTTP status;
- a request that breaks the schema is never accepted (schemathesis's negative-data check), and
  when it is refused for its shape, it is a 422 (never FastAPI's bare 400).
A second test fuzzes plans for `POST /verify` against a real inline contract (the schema alone
says a step is "any JSON"), and a third sends generated runtime messages to a monitor session
over a real websocket: every one gets exactly one well-formed answer.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
import requests
import schemathesis
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st
from hypothesis.errors import Unsatisfiable
from schemathesis import GenerationMode
from schemathesis.checks import negative_data_rejection, not_a_server_error
from websockets.asyncio.client import connect

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import CONTRACT, REQUEST, store_contract

from app.services.access import issue_api_key
from app.store.db import create_engine_for, migrate
from app.store.records import ApiKeyRole
from app.store.repository import Repository

EXAMPLES = int(os.environ.get("SAFEGATE_FUZZ_EXAMPLES", "15"))
PROBLEM_JSON = "application/problem+json"
ANSWER_TYPES = {"allow", "violation", "halted", "error"}

pytestmark = pytest.mark.slow


def fuzz_settings(examples: int) -> Callable[[Any], Any]:
    return settings(max_examples=examples, derandomize=True, deadline=None, database=None,
                    suppress_health_check=list(HealthCheck),
                    phases=[Phase.explicit, Phase.generate])


def prepare_database(url: str) -> tuple[str, str]:
    """Migrate the server's database, store a monitorable contract and issue an admin key."""
    engine = create_engine_for(url)
    try:
        migrate(engine)
        repository = Repository(engine)
        contract_id = store_contract(repository)
        _, secret = issue_api_key(repository, ApiKeyRole.ADMIN, "fuzzer")
        return contract_id, secret
    finally:
        engine.dispose()


def problems_in(response: Any, negative: bool) -> list[str]:
    """What is wrong with one answer (empty when nothing is)."""
    status = response.status_code
    found: list[str] = []
    if status >= 500:
        found.append(f"server error {status}")
    if 400 <= status < 500:
        content_type = response.headers.get("content-type", [""])
        if PROBLEM_JSON not in str(content_type):
            found.append(f"{status} is not problem+json but {content_type}")
        elif response.json().get("status") != status:
            found.append(f"{status} problem says status {response.json().get('status')}")
    if negative and status == 400:
        found.append("an invalid request got a bare 400, not a 422")
    return found


@pytest.fixture
def fuzz_target(live_server: Callable[..., Any], sqlite_url: str) -> tuple[Any, str, str]:
    contract_id, secret = prepare_database(sqlite_url)
    server = live_server(SAFEGATE_LOG_LEVEL="warning")
    return server, contract_id, secret


def fuzz_operation(operation: Any, mode: GenerationMode, base_url: str,
                   session: requests.Session) -> tuple[int, list[str]]:
    """Send one operation's generated requests; how many were sent, and what went wrong."""
    negative = mode is GenerationMode.NEGATIVE
    failures: list[str] = []
    sent = 0

    @fuzz_settings(EXAMPLES)
    @given(operation.as_strategy(generation_mode=mode))
    def exercise(case: Any) -> None:
        nonlocal sent
        response = case.call(base_url=base_url, session=session, timeout=30)
        sent += 1
        found = problems_in(response, negative)
        try:
            case.validate_response(response, checks=[not_a_server_error, negative_data_rejection])
        except AssertionError as error:
            found.append(str(error).strip().splitlines()[0])
        if found:
            failures.append(f"{operation.label}: {'; '.join(found)} <- {case.as_curl_command()}"
                            f"\n    answer: {response.text[:300]}")

    # Unsatisfiable: nothing in this operation can be made invalid (no parameters, no body).
    with contextlib.suppress(Unsatisfiable):
        exercise()
    return sent, failures


class TestOpenApiFuzzing:
    @pytest.mark.parametrize("mode", [GenerationMode.POSITIVE, GenerationMode.NEGATIVE],
                             ids=["fits-schema", "breaks-schema"])
    def test_no_operation_errors_or_accepts_bad_input(
        self, fuzz_target: tuple[Any, str, str], mode: GenerationMode
    ) -> None:
        server, _, secret = fuzz_target
        schema = schemathesis.openapi.from_url(server.base_url + "/openapi.json")
        session = requests.Session()
        session.headers["Authorization"] = f"Bearer {secret}"
        failures: list[str] = []
        exercised: dict[str, int] = {}
        for result in schema.get_all_operations():
            operation = result.ok()
            sent, found = fuzz_operation(operation, mode, server.base_url, session)
            exercised[operation.label] = sent
            failures += found
        assert not failures, f"{len(failures)} bad answers:\n" + "\n".join(failures[:20])
        # The fuzzer reached the operations that matter (with the admin key past auth; a body
        # of any JSON, as templates take, cannot break the schema).
        required = ["POST /gate", "POST /verify", "POST /monitor", "POST /keys"]
        if mode is GenerationMode.POSITIVE:
            required += ["POST /templates", "POST /gate/{request_id}/answers"]
        for label in required:
            assert exercised.get(label, 0) > 0, f"{label} was never exercised"


STEP_NAMES = ["PickupObject", "PutObject", "GoToObject", "navigate", "HandOver", "Pour",
              "ToggleObjectOn", "Wait", "pick", "Teleport", ""]
ENTITY_IDS = ["mug_1", "counter_1", "knife_1", "stove_1", "p1", "child_1", "kitchen",
              "living_room", "unicorn_9", ""]
JSON_SCALARS = (st.none() | st.booleans() | st.integers(-10**15, 10**15)
                | st.floats(allow_nan=False, allow_infinity=False, min_value=-1e15,
                            max_value=1e15)
                | st.text(max_size=20))
STEPS = st.one_of(
    st.fixed_dictionaries(
        {"action": st.sampled_from(STEP_NAMES)},
        optional={"object": st.sampled_from(ENTITY_IDS), "target": st.sampled_from(ENTITY_IDS),
                  "seconds": JSON_SCALARS, "liquid": JSON_SCALARS}),
    st.recursive(JSON_SCALARS, lambda inner: st.lists(inner, max_size=3)
                 | st.dictionaries(st.text(max_size=8), inner, max_size=3), max_leaves=8),
)


def inline_contract() -> dict[str, Any]:
    def conditions(items: tuple[Any, ...]) -> list[dict[str, Any]]:
        return [{"id": c.id, "formula": c.formula, "action": c.action} for c in items]

    return {"invariants": conditions(CONTRACT.invariants), "guards": conditions(CONTRACT.guards),
            "aborts": conditions(CONTRACT.aborts)}


class TestPlanFuzzing:
    def test_generated_plans_are_verified_or_refused_never_crash(
        self, fuzz_target: tuple[Any, str, str]
    ) -> None:
        server, _, _ = fuzz_target
        session = requests.Session()
        initial_state = {"scene": REQUEST["scene"], "robot": REQUEST["robot"]}
        seen: dict[int, int] = {}

        @fuzz_settings(EXAMPLES * 4)
        @given(st.lists(STEPS, max_size=6))
        def exercise(plan: list[Any]) -> None:
            response = session.post(server.base_url + "/verify", timeout=30, json={
                "contract": inline_contract(), "initial_state": initial_state, "plan": plan})
            seen[response.status_code] = seen.get(response.status_code, 0) + 1
            assert response.status_code in (200, 422), (plan, response.text)
            if response.status_code == 422:
                assert response.headers["content-type"] == PROBLEM_JSON
                assert response.json()["errors"][0]["field"].startswith("plan")

        exercise()
        assert seen.get(200, 0) > 0 and seen.get(422, 0) > 0, seen


MESSAGES = st.one_of(
    st.fixed_dictionaries(
        {"type": st.sampled_from(["before", "after", "status", ""]),
         "seq": st.integers(-3, 10**12) | JSON_SCALARS},
        optional={"action": STEPS, "state": st.dictionaries(st.text(max_size=6), JSON_SCALARS,
                                                            max_size=3)}),
    STEPS,
).map(json.dumps) | st.text(max_size=40)


class TestMonitorFuzzing:
    def test_every_generated_message_gets_one_well_formed_answer(
        self, fuzz_target: tuple[Any, str, str]
    ) -> None:
        server, contract_id, _ = fuzz_target
        session_id = requests.post(server.base_url + "/monitor", timeout=30,
                                   json={"contract_id": contract_id}).json()["session_id"]
        answers: list[dict[str, Any]] = []

        @fuzz_settings(EXAMPLES * 4)
        @given(st.lists(MESSAGES, min_size=1, max_size=8))
        def exercise(messages: list[str]) -> None:
            async def talk() -> None:
                async with connect(f"{server.ws_url}/monitor/{session_id}") as socket:
                    for message in messages:
                        await socket.send(message)
                        answer = json.loads(await asyncio.wait_for(socket.recv(), 10))
                        assert answer["type"] in ANSWER_TYPES, answer
                        answers.append(answer)

            asyncio.run(talk())

        exercise()
        summary = requests.get(f"{server.base_url}/monitor/{session_id}/summary",
                               timeout=30).json()
        assert summary["messages"] == len(answers)
