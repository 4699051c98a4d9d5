"""The methods the suite can run, by name: SafeGate, the LLM classifier and the two baselines.

In: a method name from the command line. Out: a `Method` (see `bench/method.py`).
- `safegate`: every case is POSTed to /gate of an embedded app, exactly as a caller does.
- `llm-classifier`: the paper's one-prompt, three-way LLM judgement, `LlmClassifier` of
  `bench/baselines/llm_classifier.py` (built on SafeGate's `LitellmClient` from the `SAFEGATE_*`
  settings; its `classify(request)` answers decision, reason and whether the call failed). It
  runs only when `SAFEGATE_LLM_MODEL` is set and litellm (the `llm` extra) is installed. A
  failed LLM call is the classifier's fail-closed `defer`; the verdict's reason starts with
  "LLM call failed" so such cases can be counted.
- `selp-style`, `roboguard-style`: our re-implementations of the published baselines
  (`bench/baselines/`).
Fails: `BenchmarkError` on an unknown method name. A method that cannot run reports why through
`unavailable_reason()`; it is never silently replaced by another.
"""

from __future__ import annotations

import importlib.util
import os
from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager
from typing import cast

from app.domain.models import GateRequest
from bench.baselines.roboguard_style import RoboGuardStyle
from bench.baselines.selp_style import SelpStyle
from bench.case import BenchmarkError, Decision
from bench.gate_runner import embedded_client
from bench.method import Decide, Method, Verdict

METHOD_NAMES: tuple[str, ...] = ("safegate", "llm-classifier", "selp-style", "roboguard-style")


class SafeGateMethod:
    """SafeGate through its HTTP API: POST /gate of a fresh embedded app per run."""

    name = "safegate"

    def __init__(self, analyzer: str = "symbolic") -> None:
        """Args: analyzer: the `SAFEGATE_ANALYZER` setting the embedded app runs with."""
        self.analyzer = analyzer

    @property
    def description(self) -> str:
        """What is evaluated."""
        return (
            f"SafeGate, POST /gate of the embedded app ({self.analyzer} analyzer, "
            "template library from templates_db/, throwaway SQLite audit database)."
        )

    def unavailable_reason(self) -> str | None:
        """SafeGate always runs."""
        return None

    def open(self) -> AbstractContextManager[Decide]:
        """An embedded app whose /gate decides each request."""
        return self._deciding()

    @contextmanager
    def _deciding(self) -> Iterator[Decide]:
        with embedded_client(analyzer=self.analyzer) as client:

            def decide(request: GateRequest) -> Verdict:
                response = client.post(
                    "/gate",
                    json=request.model_dump(mode="json", by_alias=True, exclude_none=True),
                )
                response.raise_for_status()
                body = response.json()
                return Verdict(
                    decision=cast(Decision, body["decision"]),
                    reason=f"{body.get('rule', '?')}: {body.get('reason', '')}",
                )

            yield decide


class LLMClassifierMethod:
    """The paper's LLM classifier, run only when an LLM is configured."""

    name = "llm-classifier"
    description = (
        "The paper's LLM classifier: one prompt with the same inputs (command, scene, user, "
        "robot) and a direct authorize/defer/reject judgement (bench/baselines/llm_classifier.py)."
    )

    def unavailable_reason(self) -> str | None:
        """Why it cannot run: no model configured, or litellm is not installed."""
        if not os.environ.get("SAFEGATE_LLM_MODEL"):
            return "no LLM configured"
        if importlib.util.find_spec("litellm") is None:
            return "litellm is not installed (pip install -e '.[llm]')"
        return None

    def open(self) -> AbstractContextManager[Decide]:
        """The classifier built from `SAFEGATE_*` settings."""
        return self._deciding()

    @contextmanager
    def _deciding(self) -> Iterator[Decide]:
        from app.adapters.llm import LitellmClient
        from app.config import Settings
        from app.services.container import llm_config
        from bench.baselines.llm_classifier import LlmClassifier

        classifier = LlmClassifier(LitellmClient(llm_config(Settings())))

        def decide(request: GateRequest) -> Verdict:
            verdict = classifier.classify(request)
            prefix = "LLM call failed, deferred: " if verdict.failed else ""
            return Verdict(decision=cast(Decision, verdict.decision),
                           reason=prefix + verdict.reason)

        yield decide


def build_method(name: str, *, safegate_analyzer: str = "symbolic") -> Method:
    """The method called `name`.

    Args:
        name: one of `METHOD_NAMES`.
        safegate_analyzer: the analyzer setting SafeGate's embedded app runs with.

    Returns:
        A fresh method object.

    Raises:
        BenchmarkError: on an unknown name.
    """
    if name == "safegate":
        return SafeGateMethod(safegate_analyzer)
    if name == "llm-classifier":
        return LLMClassifierMethod()
    if name == "selp-style":
        return SelpStyle.from_data()
    if name == "roboguard-style":
        return RoboGuardStyle.from_data()
    raise BenchmarkError(f"unknown method {name!r}; expected one of {METHOD_NAMES}")
