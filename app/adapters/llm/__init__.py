"""SafeGate's LLM adapter: the only package that imports litellm (lazily, on the first call).

In: an `LlmConfig` (any litellm model string, api base, key, timeout). Out:
- `LlmAnalyzer`: Stage 1 by an LLM, behind the same `Analyzer` interface as the symbolic one;
- `LlmClassifier`: the paper's LLM classifier baseline (direct authorize/defer/reject);
- `LlmPlanner`: a SMART-LLM-style planner writing plans in the action model under a contract.
Prompts are files under `prompts/<version>/`. Every answer is parsed into a pydantic model.
Fails closed: the analyzer and classifier turn any LLM failure into a deferral; the planner
raises `LlmError` (an `Unavailable`), so no plan exists.
"""

from app.adapters.llm.analyzer import AnalysisCache, LlmAnalyzer, request_hash
from app.adapters.llm.classifier import ClassifierVerdict, LlmClassifier
from app.adapters.llm.client import ChatAnswer, ChatClient, LitellmClient, LlmConfig
from app.adapters.llm.errors import (
    LlmConnectionError,
    LlmError,
    LlmOutputInvalid,
    LlmRateLimited,
    LlmRequestRejected,
    LlmTimeout,
)
from app.adapters.llm.planner import LlmPlanner
from app.adapters.llm.prompting import DEFAULT_PROMPT_VERSION, PromptError, PromptSet

__all__ = [
    "DEFAULT_PROMPT_VERSION",
    "AnalysisCache",
    "ChatAnswer",
    "ChatClient",
    "ClassifierVerdict",
    "LitellmClient",
    "LlmAnalyzer",
    "LlmClassifier",
    "LlmConfig",
    "LlmConnectionError",
    "LlmError",
    "LlmOutputInvalid",
    "LlmPlanner",
    "LlmRateLimited",
    "LlmRequestRejected",
    "LlmTimeout",
    "PromptError",
    "PromptSet",
    "request_hash",
]
