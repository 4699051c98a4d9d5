"""The `safegate` command line: serve the API, score benchmarks, manage keys.

In: arguments and `SAFEGATE_*` environment variables. Out: a running server, or tables on stdout.
Fails: a non-zero exit code with a one-line reason.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

cli = typer.Typer(help="SafeGate: a pre-execution safety gate for LLM-controlled robots.",
                  no_args_is_help=True)
bench_cli = typer.Typer(help="Evaluate SafeGate on benchmark files.", no_args_is_help=True)
cli.add_typer(bench_cli, name="bench")


@cli.command()
def serve(
    host: Annotated[str, typer.Option(help="Address to bind.")] = "127.0.0.1",
    port: Annotated[int, typer.Option(help="Port to bind.")] = 8000,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
) -> None:
    """Serve the SafeGate API (embedded default: SQLite file, symbolic analyzer, no network)."""
    import uvicorn

    uvicorn.run(
        "app.main:create_app",
        factory=True,
        host=host,
        port=port,
        workers=workers,
        log_level="info",
        access_log=False,
    )


@bench_cli.command("score")
def bench_score(
    files: Annotated[list[Path], typer.Argument(help="Benchmark JSONL files.", exists=True)],
) -> None:
    """Run every case through the gate (embedded analyzer) and print the paper's metrics."""
    from rich.console import Console

    from bench.gate_runner import embedded_decider
    from bench.score import render_report, score_files

    with embedded_decider() as decide:
        report = score_files(list(files), decide)
    Console().print(render_report(report))


def main() -> None:
    """Entry point of the `safegate` console script."""
    cli()


if __name__ == "__main__":
    main()
