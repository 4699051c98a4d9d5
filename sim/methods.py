"""The methods an episode is run with: SafeGate, an ungated planner, and bench's baselines.

In: a gate request as the caller knows it. Out: a `Decision` (authorize, defer or reject, the
rule or reason, and for SafeGate the contract). A `guarded` method's authorized task is planned
under its contract, verified (Stage 5) and monitored (Stage 6); an unguarded method's authorized
task is planned for the goal alone and executed as planned.
- `safegate`: Stages 1-4 in process (`app.domain.pipeline.run_gate`, the symbolic analyzer, the
  template library from `templates_db/`), the same code POST /gate runs.
- `no-gate`: authorizes everything (the planner alone; a reference, not a published baseline).
- bench's baselines (`selp-style`, `roboguard-style`, and `llm-classifier` when an LLM is
  configured), through `bench.methods.build_method`, when that module is present.
Fails: `ImportError`-free: a baseline that is missing or reports itself unavailable is skipped,
and `available_methods` says why.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterator
from contextlib import AbstractContextManager, ExitStack, contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.store.seed import load_library

TEMPLATES_DIR = Path(__file__).resolve().parent.parent / "templates_db"
BENCH_BASELINES = ("selp-style", "roboguard-style", "llm-classifier")


@dataclass(frozen=True)
class Decision:
    """A method's decision on one request."""

    decision: str
    reason: str = ""
    contract: Contract | None = None


class SimMethod(Protocol):
    """A deciding method as the simulation runs it."""

    name: str
    guarded: bool

    def decide(self, request: GateRequest) -> Decision:
        """Decide one request."""
        ...


class SafeGateSim:
    """SafeGate's Stages 1-4 in process; its authorized tasks run under contract and monitor."""

    name = "safegate"
    guarded = True

    def __init__(self, templates_dir: Path = TEMPLATES_DIR) -> None:
        self._templates = TemplateIndex(load_library(templates_dir))
        self._analyzer = SymbolicAnalyzer()

    def decide(self, request: GateRequest) -> Decision:
        """Run the gate pipeline on the request."""
        result = run_gate(request, templates=self._templates, analyzer=self._analyzer)
        decision = result.decision
        return Decision(decision.decision.value, f"{decision.rule.value}: {decision.reason}",
                        result.contract)


class NoGate:
    """No gate at all: every task is planned and executed."""

    name = "no-gate"
    guarded = False

    def decide(self, request: GateRequest) -> Decision:
        """Authorize."""
        return Decision("authorize", "no gate")


class BenchBaseline:
    """A bench method's deciding function; its authorized plans run without contract."""

    guarded = False

    def __init__(self, name: str, decide: Callable[[GateRequest], Any]) -> None:
        self.name = name
        self._decide = decide

    def decide(self, request: GateRequest) -> Decision:
        """Ask the baseline."""
        try:
            verdict = self._decide(request)
        except Exception as error:
            return Decision("error", f"{type(error).__name__}: {error}")
        return Decision(str(verdict.decision), str(getattr(verdict, "reason", "")))


@contextmanager
def _opened(stack: ExitStack, skipped: dict[str, str]) -> Iterator[list[SimMethod]]:
    methods: list[SimMethod] = [SafeGateSim(), NoGate()]
    try:
        bench_methods = importlib.import_module("bench.methods")
    except ImportError as error:
        skipped.update(dict.fromkeys(BENCH_BASELINES, f"bench.methods not importable: {error}"))
        yield methods
        return
    for name in BENCH_BASELINES:
        try:
            method = bench_methods.build_method(name)
        except Exception as error:
            skipped[name] = f"not buildable: {error}"
            continue
        why = method.unavailable_reason()
        if why is not None:
            skipped[name] = why
            continue
        decide = stack.enter_context(method.open())
        methods.append(BenchBaseline(name, decide))
    yield methods


def available_methods(skipped: dict[str, str]) -> AbstractContextManager[list[SimMethod]]:
    """Open every method that can run here (SafeGate, no-gate, and bench's baselines).

    Args:
        skipped: filled with the name of each method that could not run and why.

    Returns:
        A context manager yielding the opened methods.
    """

    @contextmanager
    def opened() -> Iterator[list[SimMethod]]:
        with ExitStack() as stack, _opened(stack, skipped) as methods:
            yield methods

    return opened()
