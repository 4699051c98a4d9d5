"""Fixtures for the command line's tests: Typer's CliRunner on a real SQLite file."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from typer.testing import CliRunner, Result

from app.cli import cli

LIBRARY = Path(__file__).parent.parent / "store" / "library"

Invoke = Callable[..., Result]


@pytest.fixture
def invoke(sqlite_url: str) -> Invoke:
    """Run `safegate ARGS...` on this test's SQLite file (wide enough for whole ids)."""

    def run(*args: str, url: str | None = None) -> Result:
        env = {"SAFEGATE_DATABASE_URL": url or sqlite_url, "COLUMNS": "200"}
        return CliRunner().invoke(cli, list(args), env=env)

    return run
