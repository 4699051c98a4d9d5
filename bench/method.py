"""The interface every evaluated method implements, so that all are run the same way.

In: a `GateRequest` (the same inputs a caller gives SafeGate: command, scene, user, robot).
Out: a `Verdict`: one of "authorize" | "defer" | "reject" and a short reason saying which rule,
constraint or stage decided. A method is opened once per run (`Method.open()` is a context
manager yielding the deciding function), so it can hold a client, a model or a database.
Fails: a method that cannot run at all says so through `unavailable_reason()` (the run reports
it as "not run (...)"); an exception while deciding one case propagates (a case a method could
not decide is a failure to look at, never a silent score).
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager
from dataclasses import dataclass
from typing import Protocol

from app.domain.models import GateRequest
from bench.case import DECISIONS, BenchmarkError, Decision


@dataclass(frozen=True)
class Verdict:
    """One method's decision on one request, with the reason it gives."""

    decision: Decision
    reason: str = ""

    def __post_init__(self) -> None:
        if self.decision not in DECISIONS:
            raise BenchmarkError(f"unknown decision {self.decision!r}; expected {DECISIONS}")


Decide = Callable[[GateRequest], Verdict]


class Method(Protocol):
    """A way of deciding gate requests: SafeGate itself, a baseline or an LLM classifier."""

    @property
    def name(self) -> str:
        """The short name used on the command line and in reports (e.g. "selp-style")."""

    @property
    def description(self) -> str:
        """One sentence for the report: what the method is and where it comes from."""

    def unavailable_reason(self) -> str | None:
        """None when the method can run here, else why not (e.g. "no LLM configured")."""

    def open(self) -> AbstractContextManager[Decide]:
        """Acquire the method's resources and yield its deciding function."""
