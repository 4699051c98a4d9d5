"""What every sub-command shares: the settings, a migrated repository, Rich consoles, a clean exit.

In: `SAFEGATE_*` environment variables. Out: `Settings`, a `Repository` on a database migrated to
head, consoles for stdout and stderr, and `fail(message)`, which prints one line on stderr and
exits with code 1. Fails: `Unavailable` from the database, turned into `fail` by the callers.
"""

from __future__ import annotations

from typing import NoReturn

import typer
from rich.console import Console

from app.config import Settings
from app.store import Repository, create_engine_for, migrate


def settings() -> Settings:
    """The configuration from the environment."""
    return Settings()


def repository(configured: Settings | None = None) -> Repository:
    """A repository on the configured database, migrated to head first."""
    engine = create_engine_for((configured or settings()).database_url)
    migrate(engine)
    return Repository(engine)


def out() -> Console:
    """A console on stdout (Rich picks the terminal's width; COLUMNS overrides it)."""
    return Console(highlight=False)


def err() -> Console:
    """A console on stderr."""
    return Console(stderr=True, highlight=False)


def fail(message: str, code: int = 1) -> NoReturn:
    """Print `message` on stderr and exit with `code`."""
    err().print(message, markup=False)
    raise typer.Exit(code=code)
