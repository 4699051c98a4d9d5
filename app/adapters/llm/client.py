"""The one place SafeGate talks to an LLM: a chat call through litellm asking for JSON.

In: an `LlmConfig` (any litellm model string, optional api base and key, a timeout) and, per
call, chat messages plus the JSON schema the answer must follow. Out: `ChatAnswer`, the raw text
and the finish reason; parsing and validating it is the caller's job (`structured.py`).
Fails: every failure is an `LlmError` subclass (timeout, rate limit, connection or 5xx,
rejected request); nothing from litellm or openai escapes.

litellm is imported lazily, on the first call, with `LITELLM_LOCAL_MODEL_COST_MAP=True` set
first (otherwise its import fetches a price list from the network) and its debug banner off.
Retries are ours to decide (one repair, then fail closed), so litellm's and the OpenAI SDK's
own retries are switched off.

Structured output is asked for in one of two dialects: OpenAI's
`{"type": "json_schema", "json_schema": {...}}`, or `{"type": "json_object", "schema": S}`,
which llama.cpp-style servers understand. In `auto` mode the client starts with the first and,
if the server rejects the request as malformed (HTTP 400/422, or any error naming
`response_format`, as llama-cpp-python's 500 does), switches to the second for good.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal, Protocol

from app.adapters.llm.errors import (
    LlmConnectionError,
    LlmError,
    LlmRateLimited,
    LlmRequestRejected,
    LlmTimeout,
)

ResponseFormat = Literal["auto", "json_schema", "json_object"]
Message = Mapping[str, str]


@dataclass(frozen=True)
class LlmConfig:
    """How to reach the LLM.

    Attributes:
        model: any litellm model string (`openai/gpt-4o-mini`, `anthropic/claude-...`,
            `gemini/...`, `ollama/llama3`, `openai/<name>` with `api_base` for vLLM or llama.cpp).
        api_base: the server's base URL, for self-hosted or proxied models.
        api_key: the provider key; None lets litellm read the provider's usual variable.
        timeout: seconds one call may take before it counts as failed.
        response_format: the structured-output dialect, or `auto` to detect it.
        max_tokens: the answer's length limit; an answer cut there is invalid.
    """

    model: str
    api_base: str | None = None
    api_key: str | None = None
    timeout: float = 20.0
    response_format: ResponseFormat = "auto"
    max_tokens: int = 2048
    temperature: float = 0.0


@dataclass(frozen=True)
class ChatAnswer:
    """The raw answer of one call: its text and why the model stopped (`length` = cut short)."""

    text: str
    finish_reason: str | None


class ChatClient(Protocol):
    """Anything that answers chat messages with JSON text (the litellm client, or a test fake)."""

    @property
    def model(self) -> str:
        """The model string, part of cache keys and report provenance."""
        ...

    @property
    def identity(self) -> str:
        """The model and every setting that changes its answers, for cache keys."""
        ...

    def complete(
        self, messages: Sequence[Message], *, schema_name: str, schema: Mapping[str, Any]
    ) -> ChatAnswer:
        """Send the messages and return the answer, asking for JSON following `schema`."""
        ...


def load_litellm() -> Any:
    """Import litellm the safe way: local price map, no debug banner.

    Returns:
        The `litellm` module.
    """
    os.environ["LITELLM_LOCAL_MODEL_COST_MAP"] = "True"
    import litellm

    litellm.suppress_debug_info = True
    return litellm


class LitellmClient:
    """A `ChatClient` over `litellm.completion`."""

    def __init__(self, config: LlmConfig) -> None:
        self._config = config
        self._format: ResponseFormat = config.response_format
        self._lock = threading.Lock()

    @property
    def model(self) -> str:
        """The litellm model string."""
        return self._config.model

    @property
    def identity(self) -> str:
        """The model with its temperature, length limit and requested output dialect."""
        config = self._config
        return (f"{config.model}|temperature={config.temperature:g}|"
                f"max_tokens={config.max_tokens}|format={config.response_format}")

    @property
    def response_format(self) -> ResponseFormat:
        """The dialect in use now (`auto` until a first call settles it)."""
        return self._format

    def complete(
        self, messages: Sequence[Message], *, schema_name: str, schema: Mapping[str, Any]
    ) -> ChatAnswer:
        """Send one chat call asking for JSON that follows `schema`.

        Args:
            messages: the conversation, OpenAI-style `{"role": ..., "content": ...}` dicts.
            schema_name: a short identifier for the schema (OpenAI requires one).
            schema: the JSON schema of the expected answer.

        Returns:
            The answer's text and finish reason.

        Raises:
            LlmError: timeout, rate limit, connection failure or rejected request.
        """
        litellm = load_litellm()
        dialect = self._format
        if dialect != "auto":
            return self._call_or_raise(litellm, messages, dialect, schema_name, schema)
        try:
            answer = self._call(litellm, messages, "json_schema", schema_name, schema)
        except _SchemaDialectRejected:
            answer = self._call_or_raise(litellm, messages, "json_object", schema_name, schema)
            self._settle("json_object")
            return answer
        self._settle("json_schema")
        return answer

    def _call_or_raise(
        self,
        litellm: Any,
        messages: Sequence[Message],
        dialect: Literal["json_schema", "json_object"],
        schema_name: str,
        schema: Mapping[str, Any],
    ) -> ChatAnswer:
        try:
            return self._call(litellm, messages, dialect, schema_name, schema)
        except _SchemaDialectRejected as rejected:
            raise rejected.error from rejected.__cause__

    def _settle(self, dialect: ResponseFormat) -> None:
        with self._lock:
            self._format = dialect

    def _call(
        self,
        litellm: Any,
        messages: Sequence[Message],
        dialect: Literal["json_schema", "json_object"],
        schema_name: str,
        schema: Mapping[str, Any],
    ) -> ChatAnswer:
        config = self._config
        try:
            response = litellm.completion(
                model=config.model,
                messages=[dict(m) for m in messages],
                api_base=config.api_base,
                api_key=config.api_key,
                timeout=config.timeout,
                temperature=config.temperature,
                max_tokens=config.max_tokens,
                response_format=_response_format(dialect, schema_name, schema),
                num_retries=0,
                max_retries=0,
            )
        except Exception as error:
            raise _translate(litellm, error, config) from error
        try:
            choice = response.choices[0]
            text = choice.message.content
            finish_reason = choice.finish_reason
        except (AttributeError, IndexError, TypeError) as error:
            raise LlmConnectionError(f"{config.model} sent a response without a choice") from error
        return ChatAnswer(text=text if isinstance(text, str) else "", finish_reason=finish_reason)


class _SchemaDialectRejected(LlmError):
    """The server refused the request as malformed; perhaps it speaks the other JSON dialect."""

    def __init__(self, error: LlmRequestRejected) -> None:
        super().__init__(error.detail)
        self.error = error


def _response_format(
    dialect: Literal["json_schema", "json_object"], name: str, schema: Mapping[str, Any]
) -> dict[str, Any]:
    if dialect == "json_object":
        return {"type": "json_object", "schema": dict(schema)}
    return {
        "type": "json_schema",
        "json_schema": {"name": name, "schema": dict(schema), "strict": False},
    }


def _translate(litellm: Any, error: Exception, config: LlmConfig) -> LlmError:
    who = config.model
    detail = f"{type(error).__name__}: {str(error)[:300]}"
    # Timeout subclasses APIConnectionError, so it is tested first.
    if isinstance(error, litellm.Timeout):
        return LlmTimeout(f"{who} did not answer within {config.timeout:g} s ({detail})")
    if isinstance(error, litellm.RateLimitError):
        return LlmRateLimited(f"{who} is rate limited ({detail})")
    if isinstance(error, litellm.ContextWindowExceededError):
        return LlmRequestRejected(f"{who} cannot take a prompt this long ({detail})")
    if isinstance(error, litellm.BadRequestError | litellm.UnprocessableEntityError):
        return _SchemaDialectRejected(
            LlmRequestRejected(f"{who} rejected the request ({detail})")
        )
    if "response_format" in str(error):
        # llama-cpp-python's server answers an unknown response_format with a 500 naming it.
        return _SchemaDialectRejected(
            LlmRequestRejected(f"{who} rejected the response format ({detail})")
        )
    if isinstance(error, litellm.AuthenticationError | litellm.NotFoundError):
        return LlmRequestRejected(f"{who} rejected the request ({detail})")
    return LlmConnectionError(f"{who} failed ({detail})")
