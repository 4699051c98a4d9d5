"""SafeGate's LLM adapter: the only package that imports litellm (lazily, on the first call).

In: an `LlmConfig` (any litellm model string, api base, key, timeout). Out:
- `LlmAnalyzer`: Stage 1 by an LLM, behind the same `Analyzer` interface as the symbolic one;
- `LitellmClient`, the chat client, which with the prompts, rendering and structured answers
  the evaluation's LLM classifier baseline (`bench/baselines/llm_classifier.py`) reuses.
Prompts are files under `prompts/<version>/`. Every answer is parsed into a pydantic model.
Fails closed: the analyzer turns any LLM failure into a deferral; the client raises `LlmError`
(an `Unavailable`).
"""

from app.adapters.llm.analyzer import AnalysisCache, LlmAnalyzer, request_hash
from app.adapters.llm.client import ChatAnswer, ChatClient, LitellmClient, LlmConfig
from app.adapters.llm.errors import (
    LlmConnectionError,
    LlmError,
    LlmOutputInvalid,
    LlmRateLimited,
    LlmRequestRejected,
    LlmTimeout,
)
from app.adapters.llm.prompting import DEFAULT_PROMPT_VERSION, PromptError, PromptSet

__all__ = [
    "DEFAULT_PROMPT_VERSION",
    "AnalysisCache",
    "ChatAnswer",
    "ChatClient",
    "LitellmClient",
    "LlmAnalyzer",
    "LlmConfig",
    "LlmConnectionError",
    "LlmError",
    "LlmOutputInvalid",
    "LlmRateLimited",
    "LlmRequestRejected",
    "LlmTimeout",
    "PromptError",
    "PromptSet",
    "request_hash",
]
