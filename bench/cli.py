"""`python -m bench`: SafeGate's evaluation on the command line, kept outside the service.

In: benchmark JSONL files and options (`run`: methods, run name, reports root, analyzer;
`score`: files only). Out: `run` writes report.md, results.json, decisions.jsonl and the plots
under `<out>/<name>/` and prints the summary table; `score` prints the paper's metrics of
SafeGate alone as Rich tables. Needs the `bench` extra (scipy, matplotlib) and a source checkout:
the `safegate` wheel ships the service (`app`) only.
Fails: exit code 2 with a one-line reason on a bad case file or an unknown method name.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console

bench_cli = typer.Typer(help="Evaluate SafeGate on benchmark files.", no_args_is_help=True)

CaseFiles = Annotated[list[Path], typer.Argument(help="Benchmark JSONL files.", exists=True)]


@bench_cli.command("score")
def score(files: CaseFiles) -> None:
    """Run every case through the gate (embedded analyzer) and print the paper's metrics."""
    from bench.gate_runner import embedded_decider
    from bench.score import render_report, score_files

    with embedded_decider() as decide:
        report = score_files(list(files), decide)
    Console().print(render_report(report))


@bench_cli.command("run")
def run(
    files: CaseFiles,
    method: Annotated[
        list[str] | None,
        typer.Option(help="safegate | llm-classifier | selp-style | roboguard-style "
                          "(repeatable; default: all)."),
    ] = None,
    name: Annotated[str | None, typer.Option(help="Run name (default: first file's stem).")]
    = None,
    out: Annotated[Path, typer.Option(help="Reports root.")] = Path("bench/reports"),
    analyzer: Annotated[str, typer.Option(help="SafeGate's analyzer setting.")] = "symbolic",
) -> None:
    """Run the methods on the files and write report.md, results.json and plots."""
    # Imported here so that `--help` answers without loading the app, scipy and matplotlib.
    from bench.case import BenchmarkError
    from bench.methods import METHOD_NAMES
    from bench.report_md import summary_table
    from bench.run import run_all, write_run

    try:
        evaluation = run_all(list(files), method or list(METHOD_NAMES), safegate_analyzer=analyzer)
    except BenchmarkError as exc:
        typer.echo(f"error: {exc}", err=True)
        raise typer.Exit(code=2) from exc
    directory = out / (name or files[0].stem)
    written = write_run(evaluation, directory, [str(f) for f in files])
    typer.echo("\n".join(summary_table(evaluation)))
    Console().print(f"Wrote {', '.join(str(p) for p in written)}")


def main() -> None:
    """Entry point of `python -m bench`."""
    bench_cli(prog_name="python -m bench")
