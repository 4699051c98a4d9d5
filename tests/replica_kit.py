"""Shared material for the replica tests: the knife task's contract in a database, sessions
opened over HTTP, and the quiet settings two replicas on a two-core machine run with."""

from __future__ import annotations

from typing import Any

import httpx
from monitor_kit import store_knife_contract

from app.store.db import create_engine_for, migrate
from app.store.repository import Repository

BLADE_NEAR_PERSON = "sharp.blade_carried_near_person.slow_with_blade_near_people"
QUIET = {"SAFEGATE_LOG_LEVEL": "warning", "SAFEGATE_GATE_WORKERS": "1"}


def knife_contract_in(url: str) -> str:
    """Migrate the database at `url` and store the knife task's contract; returns its id."""
    engine = create_engine_for(url)
    try:
        migrate(engine)
        return store_knife_contract(Repository(engine))
    finally:
        engine.dispose()


def open_session(server: Any, contract_id: str) -> str:
    """`POST /monitor` on a live server; returns the session id."""
    response = httpx.post(f"{server.base_url}/monitor", json={"contract_id": contract_id},
                          timeout=10)
    assert response.status_code == 201, response.text
    session_id: str = response.json()["session_id"]
    return session_id
