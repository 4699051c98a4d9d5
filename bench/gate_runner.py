"""Run benchmark cases through the gate the way a caller does: POST /gate over the ASGI app.

In: gate requests. Out: the decision string for each ("authorize" | "defer" | "reject").
A temporary SQLite database holds the audit trail for the run; nothing else is touched.
Fails: an HTTP error from the gate is raised, never counted as a decision.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from fastapi.testclient import TestClient

from app.config import Settings
from app.domain.models import GateRequest
from app.main import create_app

Decider = Callable[[GateRequest], str]


@contextmanager
def embedded_client(**overrides: object) -> Iterator[TestClient]:
    """A client of a fresh SafeGate app on a throwaway SQLite file."""
    with tempfile.TemporaryDirectory(prefix="safegate-bench-") as tmp:
        settings = Settings(database_url=f"sqlite:///{Path(tmp) / 'bench.db'}", **overrides)  # type: ignore[arg-type]
        with TestClient(create_app(settings)) as client:
            yield client


@contextmanager
def embedded_decider(**overrides: object) -> Iterator[Decider]:
    """A function deciding one request through POST /gate of an embedded app."""
    with embedded_client(**overrides) as client:

        def decide(request: GateRequest) -> str:
            response = client.post(
                "/gate", json=request.model_dump(mode="json", by_alias=True, exclude_none=True)
            )
            response.raise_for_status()
            decision: str = response.json()["decision"]
            return decision

        yield decide
