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
- `llm-scripted`, `ensemble-scripted` (reported as `llm (scripted)`, `ensemble (scripted)`):
  SafeGate with the `llm` or `ensemble` analyzer whose "model" is a scripted server on loopback
  (`bench/scripted_llm.py`) answering by a fixed rule from the prompt's words
  (`bench/scripted_analyst.py`): the LLM path checked end to end, not a model's score.
Fails: `BenchmarkError` on an unknown method name. A method that cannot run reports why through
`unavailable_reason()`; it is never silently replaced by another.
"""

from __future__ import annotations

import importlib.util
import os
from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager
from typing import cast

from fastapi.testclient import TestClient

from app.domain.models import GateRequest
from bench.baselines.roboguard_style import RoboGuardStyle
from bench.baselines.selp_style import SelpStyle
from bench.case import BenchmarkError, Decision
from bench.gate_runner import embedded_client
from bench.method import Decide, Method, Verdict

METHOD_NAMES: tuple[str, ...] = ("safegate", "llm-classifier", "selp-style", "roboguard-style",
                                 "llm-scripted", "ensemble-scripted")
SCRIPTED_MODEL = "openai/scripted-analyst"


def _gate_decider(client: TestClient) -> Decide:
    def decide(request: GateRequest) -> Verdict:
        response = client.post(
            "/gate", json=request.model_dump(mode="json", by_alias=True, exclude_none=True),
        )
        response.raise_for_status()
        body = response.json()
        return Verdict(decision=cast(Decision, body["decision"]),
                       reason=f"{body.get('rule', '?')}: {body.get('reason', '')}")

    return decide



def _litellm_missing() -> str | None:
    """Why an LLM method cannot run when the `llm` extra is absent, else None."""
    if importlib.util.find_spec("litellm") is None:
        return "litellm is not installed (pip install -e '.[llm]')"
    return None

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
            yield _gate_decider(client)


class ScriptedLlmMethod:
    """SafeGate's LLM path (`llm` or `ensemble` analyzer) against a scripted server, not a model.

    The server is `bench/scripted_llm.py` on 127.0.0.1 and its answers come from
    `bench/scripted_analyst.py`, which reads only the prompt: a plumbing check, not a score.
    """

    def __init__(self, analyzer: str) -> None:
        """Args: analyzer: `llm` or `ensemble`, the `SAFEGATE_ANALYZER` of the embedded app."""
        self.analyzer = analyzer
        self.name = f"{analyzer} (scripted)"

    @property
    def description(self) -> str:
        """What is evaluated, saying plainly that no model was involved."""
        member = "alone" if self.analyzer == "llm" else "with the symbolic analyzer (union)"
        return (
            f"SafeGate's LLM analyzer {member}, POST /gate of the embedded app, talking through "
            "litellm to a scripted OpenAI-compatible server on 127.0.0.1, NOT a real model: "
            "the server answers from the prompt's words by a fixed rule "
            "(bench/scripted_analyst.py), so this checks the LLM path end to end and is not a "
            "model score."
        )

    def unavailable_reason(self) -> str | None:
        """Why it cannot run: litellm (the `llm` extra) is not installed."""
        return _litellm_missing()

    def open(self) -> AbstractContextManager[Decide]:
        """A scripted server and an embedded app whose LLM is that server."""
        return self._deciding()

    @contextmanager
    def _deciding(self) -> Iterator[Decide]:
        from bench.scripted_analyst import answer
        from bench.scripted_llm import scripted_server

        # litellm would otherwise fetch its model cost map from the internet on import.
        os.environ.setdefault("LITELLM_LOCAL_MODEL_COST_MAP", "True")
        with scripted_server() as server:
            server.responder = answer
            with embedded_client(analyzer=self.analyzer, llm_model=SCRIPTED_MODEL,
                                 llm_api_base=server.base_url, llm_api_key="sk-scripted",
                                 llm_timeout=30.0) as client:
                yield _gate_decider(client)


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
        return _litellm_missing()

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
    if name in ("llm-scripted", "llm (scripted)"):
        return ScriptedLlmMethod("llm")
    if name in ("ensemble-scripted", "ensemble (scripted)"):
        return ScriptedLlmMethod("ensemble")
    raise BenchmarkError(f"unknown method {name!r}; expected one of {METHOD_NAMES}")
