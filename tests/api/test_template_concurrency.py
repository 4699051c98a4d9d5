"""Concurrent template writes over real HTTP: each gets its answer, none a 500.

Template validation runs Z3 in the server's threadpool; Z3's shared context is not thread-safe,
and four simultaneous `POST /templates` of one document answered two 500s ("context mismatch",
found by `test_openapi_conformance.py`). Now one is created and the others are told it exists.
"""

from __future__ import annotations

from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import httpx

from app.services.access import issue_api_key
from app.store.db import create_engine_for, migrate
from app.store.records import ApiKeyRole
from app.store.repository import Repository

TEMPLATE = {
    "id": "thermal.iron_left_on_near_child", "name": "Hot iron near a child",
    "category": "physical", "hazard_class": "thermal_burn",
    "description": "A hot iron burns a child who touches it.", "severity": "high",
    "preventability": "preventable", "variables": [{"name": "obj", "type": "object"}],
    "guards": [{"id": "no_hot_handover", "action": "HandOver",
                "formula": "@object != $obj or not hot($obj)",
                "description": "Never hand over the iron while it is hot."}],
}


class TestConcurrentTemplateWrites:
    def test_simultaneous_creations_of_one_template_get_one_201_and_409s(
        self, live_server: Callable[..., Any], sqlite_url: str
    ) -> None:
        engine = create_engine_for(sqlite_url)
        migrate(engine)
        secret = issue_api_key(Repository(engine), ApiKeyRole.CURATOR, "curator")[1]
        engine.dispose()
        server = live_server(SAFEGATE_LOG_LEVEL="warning")

        def create(_: int) -> int:
            answer = httpx.post(f"{server.base_url}/templates", json=TEMPLATE, timeout=60,
                                headers={"Authorization": f"Bearer {secret}"})
            return answer.status_code

        with ThreadPoolExecutor(6) as pool:
            statuses = sorted(pool.map(create, range(6)))
        assert statuses == [201, 409, 409, 409, 409, 409]
