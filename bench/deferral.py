"""The paper's deferral analysis: what every other method did with the tasks SafeGate deferred.

In: the cases, the reference method's decisions (SafeGate's) and each other method's decisions,
all keyed by case id. Out: a `DeferralAnalysis`: the deferred case ids, their labels, and per
other method the decision counts on exactly those cases, overall and within each label (so
"authorized 9 of the 12 deferred ambiguous tasks" can be read off).
Fails: `BenchmarkError` when a method's decisions miss a case or hold an unknown decision.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from bench.case import LABELS, BenchmarkCase, BenchmarkError, Label
from bench.metrics import DecisionCounts, count_decisions


@dataclass(frozen=True)
class DeferralRow:
    """One other method's decisions on the reference's deferred tasks."""

    method: str
    overall: DecisionCounts
    by_label: dict[Label, DecisionCounts]

    @property
    def authorized_unsafe(self) -> int:
        """Deferred tasks labelled unsafe that this method authorized."""
        return self.by_label["unsafe"].authorized

    @property
    def authorized_ambiguous(self) -> int:
        """Deferred tasks labelled ambiguous that this method authorized without asking."""
        return self.by_label["ambiguous"].authorized


@dataclass(frozen=True)
class DeferralAnalysis:
    """The reference's deferrals and how each other method decided them."""

    reference: str
    deferred_ids: tuple[str, ...]
    labels: dict[Label, int]
    rows: tuple[DeferralRow, ...]


def deferral_analysis(
    cases: Sequence[BenchmarkCase],
    reference: str,
    decisions: Mapping[str, Mapping[str, str]],
) -> DeferralAnalysis:
    """Cross-tabulate the reference method's deferrals against every other method.

    Args:
        cases: the benchmark cases (their order fixes the order of `deferred_ids`).
        reference: the name of the reference method (a key of `decisions`).
        decisions: method name -> (case id -> decision) for every method that ran.

    Returns:
        The analysis; `rows` follow the order of `decisions`, the reference left out.

    Raises:
        BenchmarkError: the reference is missing, or a method has no decision for a case.
    """
    if reference not in decisions:
        raise BenchmarkError(f"no decisions for the reference method {reference!r}")
    for name, by_id in decisions.items():
        missing = [c.id for c in cases if c.id not in by_id]
        if missing:
            raise BenchmarkError(f"{name} has no decision for e.g. {missing[:5]}")
    deferred = [c for c in cases if decisions[reference][c.id] == "defer"]
    labels: dict[Label, int] = {
        label: sum(1 for c in deferred if c.label == label) for label in LABELS
    }
    rows = tuple(
        DeferralRow(
            method=name,
            overall=count_decisions(by_id[c.id] for c in deferred),
            by_label={
                label: count_decisions(by_id[c.id] for c in deferred if c.label == label)
                for label in LABELS
            },
        )
        for name, by_id in decisions.items()
        if name != reference
    )
    return DeferralAnalysis(
        reference=reference,
        deferred_ids=tuple(c.id for c in deferred),
        labels=labels,
        rows=rows,
    )
