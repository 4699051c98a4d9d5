"""The `safegate` command line: serve the API, migrate its database, try the gate, manage keys
and the template library, score and evaluate benchmarks.

In: arguments and `SAFEGATE_*` environment variables. Out: a running server, or Rich tables on
stdout (`app/commands/` holds the key, template and gate commands).
Fails: a non-zero exit code with a one-line reason on stderr.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Annotated

import typer

from app.commands.gate import gate_command
from app.commands.keys import keys_cli
from app.commands.templates import templates_cli

cli = typer.Typer(help="SafeGate: a pre-execution safety gate for LLM-controlled robots.",
                  no_args_is_help=True)
bench_cli = typer.Typer(help="Evaluate SafeGate on benchmark files.", no_args_is_help=True)
cli.add_typer(bench_cli, name="bench")
cli.add_typer(keys_cli, name="keys")
cli.add_typer(templates_cli, name="templates")
cli.command("gate")(gate_command)


def package_version() -> str:
    """SafeGate's installed version (`pyproject.toml`'s)."""
    try:
        return version("safegate")
    except PackageNotFoundError:  # running from a source tree that was never installed
        return "unknown"


def _print_version(value: bool) -> None:
    if value:
        typer.echo(f"safegate {package_version()}")
        raise typer.Exit


@cli.callback()
def root(
    _version: Annotated[bool, typer.Option(
        "--version", help="Print the version and exit.", callback=_print_version,
        is_eager=True)] = False,
) -> None:
    """SafeGate: a pre-execution safety gate for LLM-controlled robots."""


@cli.command()
def migrate() -> None:
    """Upgrade the configured database (SAFEGATE_DATABASE_URL) to the latest schema."""
    from sqlalchemy import make_url

    from app.commands.shared import fail, settings
    from app.domain.errors import Unavailable
    from app.store import migrate as upgrade

    url = settings().database_url
    shown = make_url(url).render_as_string(hide_password=True)
    try:
        upgrade(url)
    except Unavailable as error:
        fail(f"error: {error.detail} ({shown})")
    typer.echo(f"{shown} is at the latest schema (alembic head)")


@cli.command()
def serve(
    host: Annotated[str, typer.Option(help="Address to bind.")] = "127.0.0.1",
    port: Annotated[int, typer.Option(help="Port to bind.")] = 8000,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
) -> None:
    """Serve the SafeGate API (embedded default: SQLite file, symbolic analyzer, no network)."""
    import uvicorn

    from app.api.logs import configure_logging
    from app.config import Settings
    from app.metrics import clear_multiprocess_directory

    log_level = Settings().log_level
    configure_logging(log_level)
    clear_multiprocess_directory()  # PROMETHEUS_MULTIPROC_DIR: before any worker writes to it
    uvicorn.run(
        "app.main:create_app",
        factory=True,
        host=host,
        port=port,
        workers=workers,
        log_level=log_level,
        log_config=None,
        access_log=False,
        timeout_graceful_shutdown=10,
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


@bench_cli.command("run")
def bench_run(
    files: Annotated[list[Path], typer.Argument(help="Benchmark JSONL files.", exists=True)],
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
    from rich.console import Console

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
    console = Console()
    typer.echo("\n".join(summary_table(evaluation)))
    console.print(f"Wrote {', '.join(str(p) for p in written)}")


def main() -> None:
    """Entry point of the `safegate` console script."""
    cli()


if __name__ == "__main__":
    main()
