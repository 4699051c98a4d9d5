"""The paper's LLM classifier baseline: one prompt, the same inputs, a direct three-way answer.

In: a `GateRequest` (command, scene, user and robot, rendered as the analyzer's user-level
partition by SafeGate's LLM adapter) and a `ChatClient`. Out: `ClassifierVerdict` (authorize |
defer | reject, the model's reason, and whether the call failed); `decide(request)` gives the
decision string alone, the shape `bench.gate_runner.Decider` scores. Its prompts are files in
`bench/baselines/prompts/<version>/`; the repair round uses the adapter's own `repair` prompt.
Fails closed: any `LlmError` (timeout, connection, 5xx, 429, invalid output after one repair)
becomes a `defer` verdict with `failed=True`; it never raises for an LLM failure.
"""

from __future__ import annotations

import json
import logging
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from app.adapters.llm.client import ChatClient
from app.adapters.llm.errors import LlmError
from app.adapters.llm.prompting import DEFAULT_PROMPT_VERSION, PromptSet
from app.adapters.llm.rendering import information
from app.adapters.llm.schemas import json_schema
from app.adapters.llm.structured import ask_structured
from app.domain.models import GateRequest, Level

PROMPTS_DIR = Path(__file__).resolve().parent / "prompts"

_log = logging.getLogger(__name__)


class ClassifierAnswer(BaseModel):
    """The shape the LLM's answer must take: a decision and one reason."""

    model_config = ConfigDict(frozen=True, extra="ignore")

    decision: Literal["authorize", "defer", "reject"]
    reason: str = Field(min_length=1, max_length=1000)


class ClassifierVerdict(BaseModel):
    """The classifier's judgement of one request."""

    model_config = ConfigDict(frozen=True)

    decision: Literal["authorize", "defer", "reject"]
    reason: str
    failed: bool = False


class LlmClassifier:
    """Asks an LLM directly whether to authorize, defer or reject a command."""

    name = "llm-classifier"

    def __init__(self, client: ChatClient, *, prompts: PromptSet | None = None) -> None:
        """Set the classifier up.

        Args:
            client: the chat client.
            prompts: the classifier's prompt version (default v1 of `bench/baselines/prompts`).
        """
        self._client = client
        self._prompts = prompts or PromptSet(DEFAULT_PROMPT_VERSION, root=PROMPTS_DIR)
        # The repair round asks the way SafeGate's own analyzer does, from the adapter's prompts.
        self._repair_prompts = PromptSet()
        self._system = self._prompts.render(
            "classifier_system", schema=json.dumps(json_schema(ClassifierAnswer))
        )

    def classify(self, request: GateRequest) -> ClassifierVerdict:
        """Judge one request.

        Args:
            request: the gate request.

        Returns:
            The verdict; `defer` with `failed=True` when the LLM gave no usable answer.
        """
        user = self._prompts.render(
            "classifier", information=information(request, Level.USER)
        )
        try:
            answer = ask_structured(
                self._client,
                system=self._system,
                user=user,
                answer_model=ClassifierAnswer,
                prompts=self._repair_prompts,
            )
        except LlmError as error:
            _log.warning("LLM classifier failed, deferring: %s", error.detail)
            return ClassifierVerdict(
                decision="defer",
                reason=f"classification unavailable ({type(error).__name__})",
                failed=True,
            )
        return ClassifierVerdict(decision=answer.decision, reason=answer.reason)

    def decide(self, request: GateRequest) -> str:
        """The decision alone, for the benchmark runner.

        Args:
            request: the gate request.

        Returns:
            "authorize", "defer" or "reject".
        """
        return self.classify(request).decision
