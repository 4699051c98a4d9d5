"""Load benchmark JSONL files, score a gate's decisions on them and render the report.

In: JSONL paths (one `BenchmarkCase` a line, blank lines skipped) and, per case, a decision
"authorize" | "defer" | "reject" (given, or produced by a `decide` callable). Out: a
`ScoreReport` of the paper's metrics and a Rich renderable of it.
Fails: `BenchmarkError` naming the file and line of a malformed or invalid line or a repeated
case id, and on decisions that do not match the cases. An exception raised by `decide`
propagates: a case the gate could not decide is a failure to look at, not a silent score.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from pydantic import ValidationError
from rich.console import Group
from rich.table import Table

from app.domain.models import GateRequest
from bench.case import BenchmarkCase, BenchmarkError, Label
from bench.metrics import (
    ConfusionMatrix,
    DecisionCounts,
    GroupKey,
    GroupMetrics,
    McNemarResult,
    Rates,
    ScoredCase,
    breakdown,
    confusion,
    counts_by_label,
    rates,
)

GROUP_KEYS: tuple[GroupKey, ...] = ("domain", "complexity", "category", "reasoning")


def load_cases(path: Path) -> list[BenchmarkCase]:
    """Read one JSONL benchmark file.

    Args:
        path: the file; blank lines are skipped.

    Returns:
        The cases in file order.

    Raises:
        BenchmarkError: a line is not JSON, does not fit the case shape, or repeats an id.
    """
    cases: list[BenchmarkCase] = []
    seen: set[str] = set()
    with path.open(encoding="utf-8") as lines:
        for number, line in enumerate(lines, start=1):
            if not line.strip():
                continue
            where = f"{path}:{number}"
            try:
                case = BenchmarkCase.model_validate(json.loads(line))
            except json.JSONDecodeError as exc:
                raise BenchmarkError(f"{where}: not valid JSON ({exc.msg})") from exc
            except ValidationError as exc:
                raise BenchmarkError(f"{where}: not a benchmark case: {exc}") from exc
            if case.id in seen:
                raise BenchmarkError(f"{where}: case id {case.id!r} repeats an earlier line")
            seen.add(case.id)
            cases.append(case)
    return cases


@dataclass(frozen=True)
class ScoreReport:
    """Every metric of one scored run."""

    n: int
    label_counts: dict[Label, DecisionCounts]
    rates: Rates
    confusion: ConfusionMatrix
    ambiguous: DecisionCounts
    breakdowns: dict[GroupKey, list[GroupMetrics]]
    unsafe_authorized: tuple[str, ...]
    safe_blocked: tuple[str, ...]
    scored: tuple[ScoredCase, ...]


def score(
    cases: Sequence[BenchmarkCase], decisions: Sequence[str] | Mapping[str, str]
) -> ScoreReport:
    """Score decisions against the cases' labels.

    Args:
        cases: the benchmark cases.
        decisions: one decision per case, in the same order, or a mapping case id -> decision.

    Returns:
        The report.

    Raises:
        BenchmarkError: a decision is missing, extra or not one of the three allowed.
    """
    if isinstance(decisions, Mapping):
        missing = [c.id for c in cases if c.id not in decisions]
        if missing or len(decisions) != len(cases):
            raise BenchmarkError(f"decisions do not match the cases (missing e.g. {missing[:5]})")
        ordered = [decisions[c.id] for c in cases]
    else:
        if len(decisions) != len(cases):
            raise BenchmarkError(f"{len(decisions)} decisions for {len(cases)} cases")
        ordered = list(decisions)
    scored: tuple[ScoredCase, ...] = tuple(zip(cases, ordered, strict=True))
    by_label = counts_by_label(scored)
    return ScoreReport(
        n=len(scored),
        label_counts=dict(by_label),
        rates=rates(scored),
        confusion=confusion(scored),
        ambiguous=by_label["ambiguous"],
        breakdowns={key: breakdown(scored, key) for key in GROUP_KEYS},
        unsafe_authorized=tuple(
            c.id for c, d in scored if c.label == "unsafe" and d == "authorize"
        ),
        safe_blocked=tuple(c.id for c, d in scored if c.label == "safe" and d != "authorize"),
        scored=scored,
    )


def score_files(paths: list[Path], decide: Callable[[GateRequest], str]) -> ScoreReport:
    """Run every case of the files through `decide` and score the decisions.

    Args:
        paths: JSONL benchmark files; their case ids must not collide.
        decide: the gate, returning "authorize" | "defer" | "reject" for a request.

    Returns:
        The report over all files' cases together.

    Raises:
        BenchmarkError: a malformed file, a case id repeated across files, or a bad decision.
    """
    cases = load_files(paths)
    return score(cases, [decide(case.request) for case in cases])


def load_files(paths: Sequence[Path]) -> list[BenchmarkCase]:
    """Read several JSONL benchmark files into one list, in order.

    Raises:
        BenchmarkError: a malformed file, or a case id repeated across files.
    """
    cases: list[BenchmarkCase] = []
    seen: set[str] = set()
    for path in paths:
        for case in load_cases(path):
            if case.id in seen:
                raise BenchmarkError(f"{path}: case id {case.id!r} already loaded from a file")
            seen.add(case.id)
            cases.append(case)
    return cases


def _pct(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.1f}"


def _frac(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.3f}"


def _summary_table(report: ScoreReport) -> Table:
    table = Table(title=f"SafeGate benchmark ({report.n} cases)")
    for column in ("AR-S%", "AR-U%", "DR%", "DR-S%", "DR-U%", "DR-A%"):
        table.add_column(column, justify="right")
    r = report.rates
    table.add_row(*(_pct(v) for v in (r.ar_s, r.ar_u, r.dr, r.dr_s, r.dr_u, r.dr_a)))
    return table


def _decision_table(report: ScoreReport) -> Table:
    table = Table(title="Decisions by label (unsafe = positive; defer counts as blocked)")
    for column in ("label", "n", "authorized", "deferred", "rejected", "% deferred"):
        table.add_column(column, justify="right")
    for label, counts in report.label_counts.items():
        table.add_row(
            label,
            str(counts.total),
            str(counts.authorized),
            str(counts.deferred),
            str(counts.rejected),
            _pct(counts.pct_deferred),
        )
    m = report.confusion
    table.caption = (
        f"TP {m.tp}  FN {m.fn}  FP {m.fp}  TN {m.tn}   precision {_frac(m.precision)}  "
        f"recall {_frac(m.recall)}  F1 {_frac(m.f1)}"
    )
    return table


def _breakdown_table(key: GroupKey, groups: list[GroupMetrics]) -> Table:
    table = Table(title=f"By {key}")
    for column in ("value", "n", "AR-S%", "AR-U%", "DR-A%", "precision", "recall", "F1"):
        table.add_column(column, justify="right")
    for g in groups:
        table.add_row(
            g.value,
            str(g.rates.n),
            _pct(g.rates.ar_s),
            _pct(g.rates.ar_u),
            _pct(g.rates.dr_a),
            _frac(g.confusion.precision),
            _frac(g.confusion.recall),
            _frac(g.confusion.f1),
        )
    return table


def render_report(report: ScoreReport) -> Group:
    """A Rich renderable of the report: summary, decisions by label, breakdowns, failures.

    Args:
        report: from `score` or `score_files`.

    Returns:
        A `rich.console.Group` to print with a Rich console.
    """
    parts: list[Table | str] = [_summary_table(report), _decision_table(report)]
    parts.extend(_breakdown_table(k, groups) for k, groups in report.breakdowns.items())
    unsafe = ", ".join(report.unsafe_authorized) or "none"
    parts.append(f"Unsafe cases authorized: {unsafe}")
    return Group(*parts)


def render_mcnemar(name_a: str, name_b: str, result: McNemarResult) -> str:
    """One line describing a McNemar comparison of two methods."""
    return (
        f"McNemar {name_a} vs {name_b} on {result.n} cases: b={result.b} (only {name_a} "
        f"authorized), c={result.c} (only {name_b} authorized), chi2={result.statistic:.3f}, "
        f"p={result.p_value:.4f}"
    )
