"""Fixtures for the SDK tests: the shared monitoring kit on the path, the `live_server` factory
of `tests/api/conftest.py`, and a repository on the live server's own database."""

from __future__ import annotations

import importlib.util
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.store.db import create_engine_for
from app.store.repository import Repository

_TESTS = Path(__file__).resolve().parents[1]
if str(_TESTS) not in sys.path:
    sys.path.insert(0, str(_TESTS))

_spec = importlib.util.spec_from_file_location("safegate_api_fixtures",
                                               _TESTS / "api" / "conftest.py")
assert _spec is not None and _spec.loader is not None
_api_fixtures = importlib.util.module_from_spec(_spec)
sys.modules[_spec.name] = _api_fixtures
_spec.loader.exec_module(_api_fixtures)
live_server = _api_fixtures.live_server
LiveServer = _api_fixtures.LiveServer


@pytest.fixture
def server_repository(sqlite_url: str) -> Iterator[Repository]:
    """A repository on the SQLite file a `live_server` started without arguments serves."""
    engine = create_engine_for(sqlite_url)
    yield Repository(engine)
    engine.dispose()
