"""The `safegate` command line: serve the API, score and evaluate benchmarks, manage keys.

In: arguments and `SAFEGATE_*` environment variables. Out: a running server, or tables on stdout.
Fails: a non-zero exit code with a one-line reason.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from app.store.records import ApiKeyRole

if TYPE_CHECKING:
    from app.store import Repository

cli = typer.Typer(help="SafeGate: a pre-execution safety gate for LLM-controlled robots.",
                  no_args_is_help=True)
bench_cli = typer.Typer(help="Evaluate SafeGate on benchmark files.", no_args_is_help=True)
cli.add_typer(bench_cli, name="bench")
keys_cli = typer.Typer(help="Manage API keys (stored hashed; a key is printed once).",
                       no_args_is_help=True)
cli.add_typer(keys_cli, name="keys")


@cli.command()
def serve(
    host: Annotated[str, typer.Option(help="Address to bind.")] = "127.0.0.1",
    port: Annotated[int, typer.Option(help="Port to bind.")] = 8000,
    workers: Annotated[int, typer.Option(help="Worker processes.")] = 1,
) -> None:
    """Serve the SafeGate API (embedded default: SQLite file, symbolic analyzer, no network)."""
    import uvicorn

    from app.api.observability import configure_logging
    from app.config import Settings

    log_level = Settings().log_level
    configure_logging(log_level)
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


def _repository() -> Repository:
    from app.config import Settings
    from app.store import Repository, create_engine_for, migrate

    settings = Settings()
    engine = create_engine_for(settings.database_url)
    migrate(engine)
    return Repository(engine)


@keys_cli.command("create")
def keys_create(
    role: Annotated[ApiKeyRole, typer.Option(help="What the key may do.")],
    name: Annotated[str, typer.Option(help="Who or what holds the key.")] = "",
) -> None:
    """Create a key and print it once (only its hash is stored)."""
    from app.services.access import issue_api_key

    record, secret = issue_api_key(_repository(), role, name or f"{role.value} key")
    typer.echo(secret)
    typer.echo(f"created {record.role.value} key {record.id} ({record.name}); "
               "store it now, it cannot be shown again", err=True)


@keys_cli.command("list")
def keys_list() -> None:
    """List keys (id, role, name, created, revoked); never their secrets."""
    for key in _repository().list_api_keys():
        state = "revoked" if key.revoked else "active"
        typer.echo(f"{key.id}\t{key.role.value}\t{state}\t{key.created_at:%Y-%m-%d %H:%M}"
                   f"\t{key.name}")


@keys_cli.command("revoke")
def keys_revoke(
    key_id: Annotated[str, typer.Argument(help="The key's id (see `keys list`).")],
) -> None:
    """Revoke a key for good."""
    from app.domain.errors import NotFound

    try:
        key = _repository().revoke_api_key(key_id)
    except NotFound as error:
        typer.echo(error.detail, err=True)
        raise typer.Exit(code=1) from error
    typer.echo(f"revoked {key.role.value} key {key.id} ({key.name})")


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
