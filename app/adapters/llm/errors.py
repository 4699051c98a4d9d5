"""What can go wrong talking to an LLM, as one small branch of SafeGate's `Unavailable` tree.

    Unavailable (app.domain.errors)
    └── LlmError                 any failure of an LLM call; callers fail closed on it
        ├── LlmTimeout           no answer within the configured timeout
        ├── LlmRateLimited       the provider refused for quota or rate (HTTP 429)
        ├── LlmConnectionError   unreachable server, HTTP 5xx, refused or reset connection
        ├── LlmRequestRejected   the provider refused the request itself (HTTP 4xx but 429)
        └── LlmOutputInvalid     an answer that is not JSON, is cut short or fails validation

In: raised by `app.adapters.llm.client` and the structured-answer loop. Out: nothing. Every
caller in this package turns an `LlmError` into a deferral, never into an authorization.
"""

from __future__ import annotations

from collections.abc import Sequence

from app.domain.errors import Unavailable


class LlmError(Unavailable):
    """An LLM call that did not produce a usable answer."""

    title = "LLM unavailable"


class LlmTimeout(LlmError):
    """The LLM did not answer within the timeout."""


class LlmRateLimited(LlmError):
    """The provider answered 429: too many requests or quota exhausted."""


class LlmConnectionError(LlmError):
    """The server could not be reached or failed on its side (HTTP 5xx)."""


class LlmRequestRejected(LlmError):
    """The provider rejected the request (HTTP 4xx other than 429: auth, bad parameters)."""


class LlmOutputInvalid(LlmError):
    """The answer was not valid JSON, was truncated, or did not validate against the schema."""

    def __init__(self, detail: str, *, problems: Sequence[str] = ()) -> None:
        """Args: detail: what went wrong; problems: the last answer's problems, one each."""
        super().__init__(detail)
        self.problems = tuple(problems)
