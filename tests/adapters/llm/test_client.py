"""The litellm client over real HTTP on loopback: dialects, error mapping, no hidden retries."""

from __future__ import annotations

import time
from collections.abc import Callable

import pytest

from app.adapters.llm import (
    LitellmClient,
    LlmConnectionError,
    LlmRateLimited,
    LlmRequestRejected,
    LlmTimeout,
)
from app.adapters.llm.errors import LlmError
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer

MESSAGES = [{"role": "user", "content": "answer"}]
SCHEMA = {"type": "object", "properties": {"a": {"type": "integer"}}}


class TestLitellmClient:
    def test_asks_for_the_openai_json_schema_dialect_first(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        llm_server.answer_json({"a": 1})
        answer = make_client().complete(MESSAGES, schema_name="Probe", schema=SCHEMA)
        assert answer.text == '{"a": 1}'
        sent = llm_server.requests[0]["response_format"]
        assert sent == {"type": "json_schema",
                        "json_schema": {"name": "Probe", "schema": SCHEMA, "strict": False}}

    def test_falls_back_to_the_llama_cpp_dialect_and_keeps_it(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        client = make_client()
        llm_server.queue(Scripted(content='{"a": 2}', reject_json_schema=True),
                         Scripted(content='{"a": 3}'))
        assert client.complete(MESSAGES, schema_name="Probe", schema=SCHEMA).text == '{"a": 2}'
        assert client.complete(MESSAGES, schema_name="Probe", schema=SCHEMA).text == '{"a": 3}'
        formats = [r["response_format"]["type"] for r in llm_server.requests]
        assert formats == ["json_schema", "json_object", "json_object"]
        assert llm_server.requests[1]["response_format"]["schema"] == SCHEMA
        assert client.response_format == "json_object"

    def test_falls_back_when_the_server_names_the_format_in_a_500(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        # What llama-cpp-python's server does with a json_schema response_format.
        llm_server.queue(Scripted(content='{"a": 4}', reject_json_schema=True,
                                  rejection_status=500))
        client = make_client()
        assert client.complete(MESSAGES, schema_name="Probe", schema=SCHEMA).text == '{"a": 4}'
        assert client.response_format == "json_object"

    def test_a_fixed_dialect_does_not_fall_back(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        llm_server.queue(Scripted(content="{}", reject_json_schema=True))
        with pytest.raises(LlmRequestRejected):
            make_client(response_format="json_schema").complete(
                MESSAGES, schema_name="Probe", schema=SCHEMA
            )
        assert len(llm_server.requests) == 1

    @pytest.mark.parametrize(
        ("status", "error"),
        [(500, LlmConnectionError), (503, LlmConnectionError), (429, LlmRateLimited),
         (401, LlmRequestRejected)],
    )
    def test_maps_http_errors_and_does_not_retry(
        self,
        llm_server: ScriptedServer,
        make_client: Callable[..., LitellmClient],
        status: int,
        error: type[LlmError],
    ) -> None:
        llm_server.queue(Scripted(status=status))
        with pytest.raises(error):
            make_client(response_format="json_schema").complete(
                MESSAGES, schema_name="Probe", schema=SCHEMA
            )
        assert len(llm_server.requests) == 1

    def test_a_slow_answer_times_out_at_the_configured_limit(
        self, llm_server: ScriptedServer, make_client: Callable[..., LitellmClient]
    ) -> None:
        llm_server.queue(Scripted(content="{}", delay=3.0))
        started = time.monotonic()
        with pytest.raises(LlmTimeout):
            make_client(timeout=0.5).complete(MESSAGES, schema_name="Probe", schema=SCHEMA)
        assert time.monotonic() - started < 2.5
        assert len(llm_server.requests) == 1

    def test_an_unreachable_server_is_a_connection_error(self) -> None:
        from app.adapters.llm import LlmConfig

        client = LitellmClient(LlmConfig(model="openai/scripted-model",
                                         api_base="http://127.0.0.1:9/v1", api_key="sk-x",
                                         timeout=2.0, response_format="json_schema"))
        with pytest.raises(LlmConnectionError):
            client.complete(MESSAGES, schema_name="Probe", schema=SCHEMA)
