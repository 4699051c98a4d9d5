"""PNG plots of an evaluation, drawn with matplotlib's Agg backend (no display needed).

In: an `Evaluation` and an output directory. Out: three PNG files, their paths returned:
`decisions.png` (per label, each method's authorize/defer/reject shares as stacked bars),
`confusion.png` (each method's confusion matrix, unsafe positive, defer counted as blocked, with
the ambiguous row beneath) and `ar_scatter.png` (AR-S against AR-U per method; the safe corner is
top left). Methods that did not run are left out of the pictures (the report lists them).
Fails: `OSError` when a file cannot be written.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
from matplotlib.figure import Figure

from bench.case import LABELS
from bench.evaluation import Evaluation

COLOURS = {"authorize": "#3a9d5d", "defer": "#f2a93b", "reject": "#c8453c"}
METHOD_COLOURS = ("#1f5fa8", "#8c564b", "#7a5195", "#2a9d8f", "#e76f51")


def _save(figure: Figure, path: Path) -> Path:
    figure.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(figure)
    return path


def decision_distribution(evaluation: Evaluation, path: Path) -> Path:
    """Stacked bars: within each label, the share of each decision per method."""
    names = list(evaluation.scores)
    figure, axes = plt.subplots(1, len(LABELS), figsize=(4.2 * len(LABELS), 4.2), sharey=True)
    for axis, label in zip(axes, LABELS, strict=True):
        bottoms = [0.0] * len(names)
        for decision, attribute in (("authorize", "authorized"), ("defer", "deferred"),
                                    ("reject", "rejected")):
            shares = []
            for name in names:
                counts = evaluation.scores[name].label_counts[label]
                part: int = getattr(counts, attribute)
                shares.append(100.0 * part / counts.total if counts.total else 0.0)
            axis.bar(names, shares, bottom=bottoms, color=COLOURS[decision], label=decision,
                     edgecolor="white", linewidth=0.6)
            for x, (share, bottom) in enumerate(zip(shares, bottoms, strict=True)):
                if share >= 8:
                    axis.text(x, bottom + share / 2, f"{share:.0f}", ha="center", va="center",
                              fontsize=8, color="white")
            bottoms = [b + s for b, s in zip(bottoms, shares, strict=True)]
        total = evaluation.scores[names[0]].label_counts[label].total if names else 0
        axis.set_title(f"{label} (n={total})")
        axis.tick_params(axis="x", rotation=30)
        axis.set_ylim(0, 100)
    axes[0].set_ylabel("% of the label's cases")
    axes[-1].legend(loc="upper left", bbox_to_anchor=(1.0, 1.0), frameon=False)
    figure.suptitle("Decisions per ground-truth label", y=1.03)
    return _save(figure, path)


def confusion_matrices(evaluation: Evaluation, path: Path) -> Path:
    """One confusion matrix per method, with the ambiguous cases as a third row."""
    names = list(evaluation.scores)
    figure, axes = plt.subplots(1, max(1, len(names)), figsize=(3.4 * max(1, len(names)), 3.8),
                                squeeze=False)
    for axis, name in zip(axes[0], names, strict=False):
        report = evaluation.scores[name]
        m, amb = report.confusion, report.ambiguous
        cells = [[m.tp, m.fn], [m.fp, m.tn], [amb.blocked, amb.authorized]]
        tags = [["TP", "FN"], ["FP", "TN"], ["", ""]]
        shares = [[v / max(1, sum(row)) for v in row] for row in cells]
        axis.imshow(shares, cmap="Blues", vmin=0, vmax=1)
        for r, row in enumerate(cells):
            for c, value in enumerate(row):
                axis.text(c, r, f"{tags[r][c]} {value}".strip(), ha="center", va="center",
                          fontsize=10, color="white" if shares[r][c] > 0.6 else "black")
        axis.set_xticks([0, 1], ["blocked", "authorized"])
        axis.set_yticks([0, 1, 2], ["unsafe", "safe", "ambiguous"])
        f1 = "n/a" if m.f1 is None else f"{m.f1:.2f}"
        axis.set_title(f"{name}\nF1 {f1}", fontsize=10)
    figure.subplots_adjust(wspace=0.45)
    figure.suptitle("Confusion (unsafe = positive; defer counts as blocked)", y=1.1)
    return _save(figure, path)


def authorization_scatter(evaluation: Evaluation, path: Path) -> Path:
    """AR-S (helpfulness) against AR-U (harm let through), one point per method."""
    figure, axis = plt.subplots(figsize=(5.6, 4.6))
    lowest = 100.0
    for index, (name, report) in enumerate(evaluation.scores.items()):
        ar_s, ar_u = report.rates.ar_s, report.rates.ar_u
        if ar_s is None or ar_u is None:
            continue
        colour = METHOD_COLOURS[index % len(METHOD_COLOURS)]
        axis.scatter([ar_u], [ar_s], s=90, color=colour, zorder=3,
                     label=f"{name} (AR-S {ar_s:.0f}, AR-U {ar_u:.0f})")
        lowest = min(lowest, ar_s)
    axis.scatter([0], [100], marker="*", s=180, color="#3a9d5d", zorder=2, label="ideal")
    axis.set_xlim(-3, 103)
    axis.set_ylim(max(-3.0, lowest - 15), 103)
    axis.legend(loc="lower left", fontsize=8, frameon=True)
    axis.set_xlabel("AR-U % (unsafe tasks authorized; lower is safer)")
    axis.set_ylabel("AR-S % (safe tasks authorized; higher is more useful)")
    axis.grid(True, alpha=0.3)
    axis.set_title("Safety against usefulness")
    return _save(figure, path)


def draw_all(evaluation: Evaluation, directory: Path) -> list[Path]:
    """Draw every plot into `directory` and return their paths."""
    return [
        decision_distribution(evaluation, directory / "decisions.png"),
        confusion_matrices(evaluation, directory / "confusion.png"),
        authorization_scatter(evaluation, directory / "ar_scatter.png"),
    ]
