"""Fixtures for the fault suite: the shared monitoring kit on the path, and the `live_server`
factory and the in-process `client` of `tests/api/conftest.py`."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

_TESTS = Path(__file__).resolve().parents[1]
if str(_TESTS) not in sys.path:
    sys.path.insert(0, str(_TESTS))

_spec = importlib.util.spec_from_file_location("safegate_fault_fixtures",
                                               _TESTS / "api" / "conftest.py")
assert _spec is not None and _spec.loader is not None
_api_fixtures = importlib.util.module_from_spec(_spec)
sys.modules[_spec.name] = _api_fixtures
_spec.loader.exec_module(_api_fixtures)
live_server = _api_fixtures.live_server
client = _api_fixtures.client
LiveServer = _api_fixtures.LiveServer
