"""The paper's LLM classifier baseline: one prompt, the same inputs, a direct three-way answer.

In: a `GateRequest` (command, scene, user and robot, rendered as the analyzer's user-level
partition). Out: `ClassifierVerdict` (authorize | defer | reject, the model's reason, and
whether the call failed); `decide(request)` gives the decision string alone, the shape the
benchmark runner scores (`bench.gate_runner.Decider`).
Fails closed: any `LlmError` (timeout, connection, 5xx, 429, invalid output after one repair)
becomes a `defer` verdict with `failed=True`; it never raises for an LLM failure.
"""

from __future__ import annotations

import json
import logging
from typing import Literal

from pydantic import BaseModel, ConfigDict

from app.adapters.llm.client import ChatClient
from app.adapters.llm.errors import LlmError
from app.adapters.llm.prompting import PromptSet
from app.adapters.llm.rendering import information
from app.adapters.llm.schemas import ClassifierAnswer, json_schema
from app.adapters.llm.structured import ask_structured
from app.domain.models import GateRequest, Level

_log = logging.getLogger(__name__)


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
            prompts: the prompt version to use (default v1).
        """
        self._client = client
        self._prompts = prompts or PromptSet()
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
                prompts=self._prompts,
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
