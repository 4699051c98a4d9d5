"""One benchmark case: the JSONL line shape of `shared/spec/benchmark-format.md`.

In: a dict decoded from one JSONL line. Out: a frozen `BenchmarkCase` whose `request` is a
validated `GateRequest`. Extra keys (a builder's `steps`, `missing`...) are accepted and ignored.
Fails: pydantic `ValidationError` when a required key is missing or a value is not allowed.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from app.domain.models import GateRequest

Label = Literal["safe", "unsafe", "ambiguous"]
Domain = Literal["manipulation", "navigation", "assistance"]
Complexity = Literal["simple", "medium", "complex"]
CaseCategory = Literal["physical", "psychological", "operational", "consequential"]
Reasoning = Literal["compositional", "incomplete_information", "consequential_state", "direct"]
Decision = Literal["authorize", "defer", "reject"]

LABELS: tuple[Label, ...] = ("safe", "unsafe", "ambiguous")
DOMAINS: tuple[Domain, ...] = ("manipulation", "navigation", "assistance")
COMPLEXITIES: tuple[Complexity, ...] = ("simple", "medium", "complex")
CATEGORIES: tuple[CaseCategory, ...] = ("physical", "psychological", "operational", "consequential")
REASONINGS: tuple[Reasoning, ...] = (
    "compositional",
    "incomplete_information",
    "consequential_state",
    "direct",
)
DECISIONS: tuple[Decision, ...] = ("authorize", "defer", "reject")


class BenchmarkCase(BaseModel):
    """A labelled gate request: the ground truth the gate's decision is scored against."""

    model_config = ConfigDict(frozen=True, extra="ignore")

    id: str = Field(min_length=1)
    domain: Domain
    complexity: Complexity
    label: Label
    category: CaseCategory | None = None
    reasoning: Reasoning | None = None
    why: str = Field(min_length=1)
    request: GateRequest


class BenchmarkError(ValueError):
    """A benchmark input that cannot be scored (bad line, unknown decision, mismatched runs)."""
