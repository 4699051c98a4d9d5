"""The Markdown report of an evaluation: the paper's tables for every method, side by side.

In: an `Evaluation`, the benchmark file names and the plot file names (relative to the report).
Out: Markdown text: methods and their status (with `SCRIPTED_NOTE` when a `(scripted)` method
ran: its model was a scripted server, not a real model), the main rates table, confusion and
ambiguous rows, decisions by label, McNemar's tests, the deferral analysis, breakdowns by domain,
complexity, category and reasoning kind, and the plots. Numbers come only from the evaluation.
Fails: never on a well-formed evaluation; a rate with no cases prints as "n/a".
"""

from __future__ import annotations

from collections.abc import Sequence

from bench.evaluation import REFERENCE, Evaluation
from bench.metrics import GroupMetrics
from bench.score import GROUP_KEYS

SCRIPTED_NOTE = (
    "The methods marked `(scripted)` ran SafeGate's LLM analyzer through litellm and real HTTP "
    "against a scripted OpenAI-compatible server on 127.0.0.1: the model was a scripted "
    "server, not a real model. It answers every prompt by a fixed rule from the prompt's words "
    "(the library class whose name shares most words with the command, rated moderate and "
    "preventable, tied to the objects and person the scene lists, no unknowns; "
    "`bench/scripted_analyst.py`) and never sees a label. Their rows check that the LLM path "
    "runs end to end on every case; they are not a score of any model."
)


def _pct(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.1f}"


def _frac(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.3f}"


def _table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return [*lines, ""]


def summary_table(evaluation: Evaluation) -> list[str]:
    """The main table: one row per method (the README shows this one)."""
    rows = []
    for run in evaluation.runs:
        if not run.ran:
            rows.append([f"`{run.name}`", *([f"not run ({run.skipped})"] + [""] * 8)])
            continue
        r = evaluation.scores[run.name].rates
        m = evaluation.scores[run.name].confusion
        rows.append([f"`{run.name}`", _pct(r.ar_s), _pct(r.ar_u), _pct(r.dr), _pct(r.dr_s),
                     _pct(r.dr_u), _pct(r.dr_a), _frac(m.precision), _frac(m.recall),
                     _frac(m.f1)])
    header = ["method", "AR-S % ↑", "AR-U % ↓", "DR %", "DR-S %", "DR-U %", "DR-A % ↑",
              "precision", "recall", "F1"]
    return _table(header, rows)


def _confusion(evaluation: Evaluation) -> list[str]:
    rows = []
    for name, report in evaluation.scores.items():
        m, a = report.confusion, report.ambiguous
        rows.append([f"`{name}`", str(m.tp), str(m.fn), str(m.fp), str(m.tn),
                     f"{a.authorized} / {a.deferred} / {a.rejected}"])
    return _table(["method", "TP", "FN", "FP", "TN", "ambiguous: auth / defer / reject"], rows)


def _by_label(evaluation: Evaluation) -> list[str]:
    rows = []
    for name, report in evaluation.scores.items():
        for label, c in report.label_counts.items():
            rows.append([f"`{name}`", label, str(c.total), str(c.authorized), str(c.deferred),
                         str(c.rejected)])
    return _table(["method", "label", "n", "authorized", "deferred", "rejected"], rows)


def _mcnemar(evaluation: Evaluation) -> list[str]:
    if not evaluation.mcnemar:
        return ["No SafeGate run, or no other method ran: nothing to compare.", ""]
    rows = [
        [f"`{REFERENCE}` vs `{name}`", str(t.n), str(t.b), str(t.c), f"{t.statistic:.3f}",
         f"{t.p_value:.4g}"]
        for name, t in evaluation.mcnemar.items()
    ]
    header = ["comparison", "n", "b (only SafeGate authorized)", "c (only the other authorized)",
              "χ² (continuity-corrected)", "p"]
    return _table(header, rows)


def _deferral(evaluation: Evaluation) -> list[str]:
    d = evaluation.deferral
    if d is None:
        return ["No SafeGate run: no deferral analysis.", ""]
    labels = ", ".join(f"{n} {label}" for label, n in d.labels.items())
    lines = [f"SafeGate deferred {len(d.deferred_ids)} tasks ({labels}). On those tasks:", ""]
    rows = [
        [f"`{row.method}`", str(row.overall.authorized), str(row.overall.deferred),
         str(row.overall.rejected), str(row.authorized_unsafe), str(row.authorized_ambiguous)]
        for row in d.rows
    ]
    header = ["method", "authorized", "deferred", "rejected", "of which unsafe authorized",
              "of which ambiguous authorized"]
    return lines + _table(header, rows) + [
        "Deferred ids: " + (", ".join(d.deferred_ids) or "none"), ""]


def _breakdown(evaluation: Evaluation, key: str) -> list[str]:
    per_method: dict[str, dict[str, GroupMetrics]] = {
        name: {g.value: g for g in report.breakdowns[key]}  # type: ignore[index]
        for name, report in evaluation.scores.items()
    }
    values = sorted({v for groups in per_method.values() for v in groups})
    rows = []
    for value in values:
        for name, groups in per_method.items():
            g = groups.get(value)
            if g is None:
                continue
            rows.append([value, f"`{name}`", str(g.rates.n), _pct(g.rates.ar_s),
                         _pct(g.rates.ar_u), _pct(g.rates.dr_a), _frac(g.confusion.recall),
                         _frac(g.confusion.f1)])
    header = [key, "method", "n", "AR-S %", "AR-U %", "DR-A %", "recall", "F1"]
    return [f"### By {key}", "", *_table(header, rows)]


def render_markdown(evaluation: Evaluation, files: Sequence[str], plots: Sequence[str]) -> str:
    """The full report.

    Args:
        evaluation: from `bench.evaluation.evaluate`.
        files: the benchmark files, as given on the command line.
        plots: the plot file names, relative to the report's directory.

    Returns:
        Markdown text.
    """
    lines = [
        "# SafeGate evaluation", "",
        f"{len(evaluation.cases)} cases from {', '.join(f'`{f}`' for f in files)}. "
        "Produced by `python -m bench run` (`make bench`); every method sees every case "
        "and the same inputs (command, scene, user, robot).", "",
        "## Methods", "",
    ]
    for run in evaluation.runs:
        status = f"{len(run.verdicts)} cases in {run.seconds:.1f} s" if run.ran else \
            f"**not run ({run.skipped})**"
        lines.append(f"- `{run.name}` — {run.description} {status}.")
    if any(run.name.endswith("(scripted)") for run in evaluation.runs):
        lines += ["", SCRIPTED_NOTE]
    lines += [
        "", "The baselines are our re-implementations from the published descriptions, without "
        "an LLM, with their own rule sets under `bench/baselines/data/`; they do not use "
        "SafeGate's analyzer or template library. Their lexicons were written by an engineer "
        "who had read the benchmark's commands, so if anything they are optimistic for the "
        "baselines.", "",
        "## Main results", "",
        "AR-S: safe tasks authorized; AR-U: unsafe tasks authorized (must be 0); DR: tasks "
        "deferred (overall, and within safe, unsafe, ambiguous). Precision, recall and F1 "
        "treat unsafe as the positive class and count a deferral as blocked.", "",
        *summary_table(evaluation),
        "![Decisions per label](decisions.png)" if "decisions.png" in plots else "", "",
        "## Confusion matrices", "", *_confusion(evaluation),
        "![Confusion matrices](confusion.png)" if "confusion.png" in plots else "", "",
        "## Decisions by label", "", *_by_label(evaluation),
        "## McNemar's test (authorized vs not, paired by case)", "", *_mcnemar(evaluation),
        "## Deferral analysis", "", *_deferral(evaluation),
        "## Safety against usefulness", "",
        "![AR-S against AR-U](ar_scatter.png)" if "ar_scatter.png" in plots else "", "",
        "## Breakdowns", "",
    ]
    for key in GROUP_KEYS:
        lines += _breakdown(evaluation, key)
    lines += ["Per-case decisions and reasons: `decisions.jsonl`; all numbers: `results.json`.",
              ""]
    return "\n".join(lines)
