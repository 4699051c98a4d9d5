"""One evaluation run end to end: load, run every method with a progress bar, write the report.

In: benchmark JSONL paths, method names, a run name and an output root. Out: the directory
`<root>/<run-name>/`, emptied first and then holding `report.md`, `results.json`,
`decisions.jsonl` (one line per case with every method's decision and reason) and the PNG plots;
the `Evaluation` is returned too.
Fails: `BenchmarkError` on a bad file or unknown method name; a method's exception while
deciding propagates and nothing is written.
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Sequence
from pathlib import Path

from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TaskID,
    TextColumn,
    TimeElapsedColumn,
)

from bench.evaluation import (
    Evaluation,
    MethodRun,
    decision_records,
    evaluate,
    evaluation_json,
    run_method,
)
from bench.methods import build_method
from bench.plots import draw_all
from bench.report_md import render_markdown
from bench.score import load_files


def run_all(
    paths: Sequence[Path],
    method_names: Sequence[str],
    *,
    safegate_analyzer: str = "symbolic",
    console: Console | None = None,
) -> Evaluation:
    """Run the methods over the cases of the files and evaluate them.

    Args:
        paths: benchmark JSONL files.
        method_names: names from `bench.methods.METHOD_NAMES`, in report order.
        safegate_analyzer: the analyzer SafeGate's embedded app runs with.
        console: where the progress bar goes (stderr-like; None for a default console).

    Returns:
        The evaluation.
    """
    cases = load_files(paths)
    methods = [build_method(n, safegate_analyzer=safegate_analyzer) for n in method_names]
    runs: list[MethodRun] = []
    columns = (TextColumn("{task.description:<16}"), BarColumn(), MofNCompleteColumn(),
               TimeElapsedColumn())
    with Progress(*columns, console=console or Console(stderr=True)) as progress:
        for method in methods:
            task = progress.add_task(method.name, total=len(cases))

            def advance(_case_id: str, task: TaskID = task) -> None:
                progress.advance(task)

            run = run_method(method, cases, tick=advance)
            if not run.ran:
                progress.update(task, description=f"{method.name} (not run)")
            runs.append(run)
    return evaluate(cases, runs)


def write_run(evaluation: Evaluation, directory: Path, files: Sequence[str]) -> list[Path]:
    """Write the report, the JSON results, the per-case decisions and the plots.

    Args:
        evaluation: from `run_all` or `bench.evaluation.evaluate`.
        directory: the run's directory; removed first, so nothing stale survives.
        files: the benchmark file names to cite in the report.

    Returns:
        The paths written.
    """
    if directory.exists():
        shutil.rmtree(directory)
    directory.mkdir(parents=True)
    plots = draw_all(evaluation, directory) if evaluation.scores else []
    report = directory / "report.md"
    report.write_text(render_markdown(evaluation, files, [p.name for p in plots]),
                      encoding="utf-8")
    results = directory / "results.json"
    results.write_text(json.dumps(evaluation_json(evaluation), indent=2) + "\n",
                       encoding="utf-8")
    decisions = directory / "decisions.jsonl"
    decisions.write_text(
        "".join(json.dumps(r, ensure_ascii=False) + "\n" for r in decision_records(evaluation)),
        encoding="utf-8",
    )
    return [report, results, decisions, *plots]
