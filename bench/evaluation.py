"""Run several methods over the same cases and compute everything the report shows.

In: benchmark cases and `Method`s (see `bench/method.py`). Out: `MethodRun`s (each method's
verdict per case, or why it did not run) and an `Evaluation`: per method the `ScoreReport`
(rates, confusion, ambiguous row, breakdowns), McNemar's test of the reference method (SafeGate)
against every other method that ran, and the deferral analysis; `evaluation_json` turns it into
plain JSON data. Every case goes through every method that runs: comparisons are paired.
Fails: an exception raised by a method while deciding propagates (no partial, silent scores);
`BenchmarkError` on a malformed verdict.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from typing import Any

from bench.case import BenchmarkCase
from bench.deferral import DeferralAnalysis, deferral_analysis
from bench.method import Method, Verdict
from bench.metrics import McNemarResult, ScoredCase, mcnemar
from bench.score import ScoreReport, score

REFERENCE = "safegate"
Tick = Callable[[str], None]


@dataclass(frozen=True)
class MethodRun:
    """One method's pass over the cases; `skipped` says why it did not run, else None."""

    name: str
    description: str
    verdicts: tuple[Verdict, ...]
    seconds: float
    skipped: str | None = None

    @property
    def ran(self) -> bool:
        """Whether the method decided every case."""
        return self.skipped is None


def run_method(
    method: Method, cases: Sequence[BenchmarkCase], tick: Tick | None = None
) -> MethodRun:
    """Decide every case with one method.

    Args:
        method: the method; if `unavailable_reason()` is not None it is skipped, not run.
        cases: the benchmark cases.
        tick: called with the case id after each case (a progress bar's advance).

    Returns:
        The verdicts in case order and the wall time, or a skipped run.
    """
    reason = method.unavailable_reason()
    if reason is not None:
        return MethodRun(method.name, method.description, (), 0.0, skipped=reason)
    started = time.perf_counter()
    verdicts: list[Verdict] = []
    with method.open() as decide:
        for case in cases:
            verdicts.append(decide(case.request))
            if tick is not None:
                tick(case.id)
    return MethodRun(method.name, method.description, tuple(verdicts),
                     time.perf_counter() - started)


@dataclass(frozen=True)
class Evaluation:
    """Everything one evaluation run measured."""

    cases: tuple[BenchmarkCase, ...]
    runs: tuple[MethodRun, ...]
    scores: dict[str, ScoreReport]
    mcnemar: dict[str, McNemarResult]
    deferral: DeferralAnalysis | None

    def decisions(self, name: str) -> dict[str, str]:
        """Case id -> decision of a method that ran."""
        run = next(r for r in self.runs if r.name == name)
        return {c.id: v.decision for c, v in zip(self.cases, run.verdicts, strict=True)}


def evaluate(cases: Sequence[BenchmarkCase], runs: Sequence[MethodRun]) -> Evaluation:
    """Score every method that ran and compare each with the reference (SafeGate).

    Args:
        cases: the cases all runs decided, in the same order.
        runs: the method runs (skipped ones are carried along, unscored).

    Returns:
        The evaluation; McNemar and the deferral analysis are empty without a SafeGate run.
    """
    ran = [r for r in runs if r.ran]
    scored: dict[str, tuple[ScoredCase, ...]] = {
        r.name: tuple(zip(cases, (v.decision for v in r.verdicts), strict=True)) for r in ran
    }
    scores = {r.name: score(cases, [v.decision for v in r.verdicts]) for r in ran}
    tests: dict[str, McNemarResult] = {}
    deferral: DeferralAnalysis | None = None
    if REFERENCE in scored:
        tests = {
            name: mcnemar(scored[REFERENCE], pairs)
            for name, pairs in scored.items() if name != REFERENCE
        }
        decisions = {name: {c.id: d for c, d in pairs} for name, pairs in scored.items()}
        deferral = deferral_analysis(cases, REFERENCE, decisions)
    return Evaluation(tuple(cases), tuple(runs), scores, tests, deferral)


def _score_json(report: ScoreReport) -> dict[str, Any]:
    m = report.confusion
    return {
        "n": report.n,
        "rates": asdict(report.rates),
        "confusion": {**asdict(m), "precision": m.precision, "recall": m.recall, "f1": m.f1},
        "by_label": {k: asdict(v) for k, v in report.label_counts.items()},
        "breakdowns": {
            key: [
                {"value": g.value, "rates": asdict(g.rates),
                 "confusion": {**asdict(g.confusion), "precision": g.confusion.precision,
                               "recall": g.confusion.recall, "f1": g.confusion.f1},
                 "ambiguous": asdict(g.ambiguous)}
                for g in groups
            ]
            for key, groups in report.breakdowns.items()
        },
        "unsafe_authorized": list(report.unsafe_authorized),
        "safe_blocked": list(report.safe_blocked),
    }


def evaluation_json(evaluation: Evaluation) -> dict[str, Any]:
    """The evaluation as plain JSON data (results.json)."""
    deferral = evaluation.deferral
    return {
        "cases": len(evaluation.cases),
        "reference": REFERENCE,
        "methods": [
            {"name": r.name, "description": r.description,
             "status": "ran" if r.ran else f"not run ({r.skipped})",
             "seconds": round(r.seconds, 3)}
            for r in evaluation.runs
        ],
        "scores": {name: _score_json(report) for name, report in evaluation.scores.items()},
        "mcnemar": {
            name: {**asdict(result), "versus": REFERENCE}
            for name, result in evaluation.mcnemar.items()
        },
        "deferral_analysis": None if deferral is None else {
            "reference": deferral.reference,
            "deferred": list(deferral.deferred_ids),
            "labels": deferral.labels,
            "methods": {
                row.method: {"overall": asdict(row.overall),
                             "by_label": {k: asdict(v) for k, v in row.by_label.items()}}
                for row in deferral.rows
            },
        },
    }


def decision_records(evaluation: Evaluation) -> list[dict[str, Any]]:
    """One record per case: its labels and every method's decision and reason."""
    ran = [r for r in evaluation.runs if r.ran]
    records: list[dict[str, Any]] = []
    for index, case in enumerate(evaluation.cases):
        records.append({
            "id": case.id, "label": case.label, "domain": case.domain,
            "complexity": case.complexity, "category": case.category,
            "reasoning": case.reasoning, "command": case.request.command,
            "decisions": {
                r.name: {"decision": r.verdicts[index].decision,
                         "reason": r.verdicts[index].reason}
                for r in ran
            },
        })
    return records
