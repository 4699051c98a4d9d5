"""The `safegate` command line: serve the API, migrate its database, try the gate, manage keys
and the template library. (The evaluation is `python -m bench`, outside the service package.)

In: arguments and `SAFEGATE_*` environment variables. Out: a running server, or Rich tables on
stdout (`app/commands/` holds the key, template and gate commands).
Fails: a non-zero exit code with a one-line reason on stderr.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version
from typing import Annotated

import typer

from app.commands.gate import gate_command
from app.commands.keys import keys_cli
from app.commands.templates import templates_cli

cli = typer.Typer(help="SafeGate: a pre-execution safety gate for LLM-controlled robots.",
                  no_args_is_help=True)
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


@cli.command(hidden=True, context_settings={"allow_extra_args": True,
                                           "ignore_unknown_options": True})
def bench() -> None:
    """Moved: the evaluation is `python -m bench` in a source checkout, outside the service."""
    typer.echo("`safegate bench` moved out of the service: run `python -m bench run|score ...` "
               "from a SafeGate source checkout (pip install -e '.[bench]').", err=True)
    raise typer.Exit(code=2)


def main() -> None:
    """Entry point of the `safegate` console script."""
    cli()


if __name__ == "__main__":
    main()
