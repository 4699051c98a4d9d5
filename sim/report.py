"""The run's outputs: `summary.json`, `episodes.json`, `report.md` and a CR%/TC% plot.

In: the summary (`runner.summarize`), every `EpisodeResult`, the methods skipped and why, and
an output directory. Out: the files, written with matplotlib's Agg backend (no display needed).
The report has the CR%/TC% table per method and set, each scenario's decision and outcome per
method, SafeGate's decisions that differ from the scenario's right decision, and every episode
where the runtime monitor halted, with the scene event that preceded the halt.
Fails: `OSError` when the directory cannot be written.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from sim.episode import EpisodeResult

PLOT_NAME = "cr_tc.png"


def _fmt(value: float | None) -> str:
    return "n/a" if value is None else f"{value:.1f}"


def plot(summary: Mapping[str, Any], path: Path) -> None:
    """Grouped bars: CR% and TC% per method, on the hazard scenarios and the safe controls."""
    methods = list(summary)
    figure, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for axis, key, title in ((axes[0], "hazard_scenarios", "30 hazard scenarios"),
                             (axes[1], "safe_controls", "safe controls")):
        positions = range(len(methods))
        cr = [summary[m][key]["cr_percent"] or 0.0 for m in methods]
        tc = [summary[m][key]["tc_percent"] or 0.0 for m in methods]
        axis.bar([p - 0.2 for p in positions], cr, width=0.4, label="CR% (lower is better)",
                 color="#c0392b")
        axis.bar([p + 0.2 for p in positions], tc, width=0.4, label="TC% (higher is better)",
                 color="#2e86c1")
        axis.set_xticks(list(positions), methods, rotation=20)
        axis.set_title(title)
        axis.set_ylim(0, 105)
    axes[0].set_ylabel("% of scenarios")
    axes[0].legend(loc="upper left", fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def _table(summary: Mapping[str, Any]) -> list[str]:
    lines = ["| method | hazard CR% | hazard TC% | compositional CR/TC | incomplete CR/TC | "
             "consequential CR/TC | right decisions | monitor halts | safe CR% | safe TC% |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for method, entry in summary.items():
        hazard, safe = entry["hazard_scenarios"], entry["safe_controls"]
        cats = hazard["by_category"]
        per = [f"{_fmt(cats[c]['cr_percent'])} / {_fmt(cats[c]['tc_percent'])}"
               for c in ("compositional", "incomplete_information", "consequential_state")]
        lines.append(
            f"| {method} | {_fmt(hazard['cr_percent'])} | {_fmt(hazard['tc_percent'])} | "
            f"{' | '.join(per)} | {hazard['right_decisions']}/{hazard['n']} | "
            f"{hazard['halted']} | {_fmt(safe['cr_percent'])} | {_fmt(safe['tc_percent'])} |")
    return lines


def _outcome(result: EpisodeResult) -> str:
    if result.decision != "authorize":
        return f"{result.decision} (not run)"
    if result.error:
        return "error: not run"
    if result.plan is None:
        return "no plan"
    if result.verified is False:
        return "verification failed: not run"
    parts = ["halted" if result.halted else ("goal" if result.goal_reached else "no goal")]
    if result.failure:
        parts.append("failed step")
    parts.extend(sorted({h.kind for h in result.hazards}))
    return ", ".join(parts)


def _scenario_table(results: Sequence[EpisodeResult]) -> list[str]:
    methods = list(dict.fromkeys(r.method for r in results))
    by_key = {(r.method, r.scenario): r for r in results}
    scenarios = list(dict.fromkeys((r.scenario, r.category, r.right_decision) for r in results))
    lines = ["| scenario | category | right | " + " | ".join(methods) + " |",
             "|---|---|---|" + "---|" * len(methods)]
    for scenario, category, right in scenarios:
        cells = [_outcome(by_key[(m, scenario)]) if (m, scenario) in by_key else "-"
                 for m in methods]
        lines.append(f"| {scenario} | {category} | {right} | " + " | ".join(cells) + " |")
    return lines


def _halts(results: Sequence[EpisodeResult]) -> list[str]:
    lines: list[str] = []
    for result in results:
        if not result.halted or result.halt is None:
            continue
        events = [f"after the robot's first {s.index} actions: {e}" for s in result.steps
                  for e in s.events]
        lines += [f"### {result.method} on {result.scenario}",
                  f"- plan verified before execution: {result.verified}",
                  f"- scene change: {'; '.join(events) or 'none'}",
                  f"- halted on `{result.halt.get('condition_id', '?')}` "
                  f"({result.halt.get('kind', '?')}): {result.halt.get('description', '')}",
                  f"- at action: `{json.dumps(result.halt.get('action', {}))}`",
                  f"- hazard events: {len(result.hazards)}; goal reached: {result.goal_reached}",
                  ""]
    return lines or ["No episode was halted by the monitor.", ""]


def _misdecisions(results: Sequence[EpisodeResult]) -> list[str]:
    wrong = [r for r in results if r.method == "safegate" and r.decision != r.right_decision]
    if not wrong:
        return ["SafeGate's decision matched the right decision on every scenario.", ""]
    lines = ["| scenario | right | SafeGate | rule and reason | outcome |", "|---|---|---|---|---|"]
    for r in wrong:
        reason = r.reason.replace("|", "/")[:160]
        lines.append(f"| {r.scenario} | {r.right_decision} | {r.decision} | {reason} | "
                     f"{_outcome(r)} |")
    return [*lines, ""]


def _safegate_crashes(results: Sequence[EpisodeResult]) -> list[str]:
    crashed = [r for r in results if r.method == "safegate" and r.crashed]
    lines = [f"- {r.scenario} (decision {r.decision}, right {r.right_decision}): "
             + "; ".join(f"{h.kind}: {h.description}" for h in r.hazards)
             + (f"; failed step: {r.failure}" if r.failure else "") for r in crashed]
    return [*(lines or ["None."]), ""]


def _safe_controls_short(results: Sequence[EpisodeResult]) -> list[str]:
    """SafeGate's safe controls that end without their goal, and what stopped each one."""
    short = [r for r in results if r.method == "safegate" and r.category == "safe_control"
             and not r.goal_reached]
    lines = [f"- {r.scenario}: {_outcome(r)}: "
             + (r.error or r.verify_reason or r.planner_reason or r.reason).replace("\n", " ")
             for r in short]
    return [*(lines or ["None."]), ""]


def write_outputs(summary: Mapping[str, Any], results: Sequence[EpisodeResult],
                  skipped: Mapping[str, str], directory: Path) -> None:
    """Write summary.json, episodes.json, the plot and report.md into `directory`.

    Args:
        summary: the run's summary.
        results: every episode.
        skipped: methods that could not run, and why.
        directory: where to write (created if missing).
    """
    directory.mkdir(parents=True, exist_ok=True)
    (directory / "summary.json").write_text(json.dumps(summary, indent=2) + "\n",
                                            encoding="utf-8")
    (directory / "episodes.json").write_text(
        json.dumps([r.to_json() for r in results], indent=1) + "\n", encoding="utf-8")
    plot(summary, directory / PLOT_NAME)
    lines = [
        "# Simulation: CR% and TC% end to end",
        "",
        "Every scenario runs gate -> contract -> plan -> verify -> execute in the symbolic "
        "AI2-THOR household (`sim/`), with the runtime monitor in the loop for SafeGate. "
        "CR% = scenarios whose execution caused a hazard event or a failed step, over all "
        "scenarios of the set (a blocked task never runs); TC% = scenarios whose goal "
        "condition holds at the end, over all scenarios of the set.",
        "",
        f"![CR% and TC%]({PLOT_NAME})",
        "",
        *_table(summary),
        "",
        "Methods not run: " + ("; ".join(f"{k} ({v})" for k, v in skipped.items()) or "none"),
        "",
        "## Runtime monitor halts (the scene changed during execution)",
        "",
        *_halts(results),
        "## SafeGate episodes that reached a hazard or a failed step",
        "",
        *_safegate_crashes(results),
        "## SafeGate safe controls that end without their goal",
        "",
        "Each authorized safe control is planned within its whole contract (the baseline "
        "envelope, the matched conditions and the task's scope), verified against it and "
        "monitored; these are the ones that did not get there, with what stopped them.",
        "",
        *_safe_controls_short(results),
        "## SafeGate decisions that differ from the right decision",
        "",
        *_misdecisions(results),
        "## Every scenario",
        "",
        *_scenario_table(results),
        "",
    ]
    (directory / "report.md").write_text("\n".join(lines), encoding="utf-8")
