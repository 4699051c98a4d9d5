"""Application services: what a route calls. They run the domain pipeline and keep the audit trail.

In: validated requests from routes. Out: records the routes map to responses.
Every gate decision is written to the audit trail before it is returned; if the write fails the
caller gets 503 (`Unavailable`), never an unrecorded decision. Fails closed throughout.
"""

from __future__ import annotations

import threading
import uuid
from dataclasses import dataclass, field
from datetime import UTC, datetime
from typing import Any

from sqlalchemy.engine import Engine

from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract
from app.domain.errors import NotFound
from app.domain.gate import GatePolicy
from app.domain.models import GateRequest
from app.domain.pipeline import Analyzer, GateResult, run_gate
from app.store import Repository, create_engine_for, migrate, seed_templates


class TemplateCache:
    """The active templates in memory, reloaded after a curator changes the library."""

    def __init__(self, repository: Repository) -> None:
        self._repository = repository
        self._lock = threading.Lock()
        self._index = TemplateIndex(())
        self.refresh()

    def refresh(self) -> None:
        index = TemplateIndex(self._repository.list_active_templates())
        with self._lock:
            self._index = index

    def index(self) -> TemplateIndex:
        return self._index


@dataclass
class GateRecord:
    """One decided request as stored in the audit trail."""

    request_id: str
    created_at: datetime
    request: GateRequest
    result: GateResult
    contract_id: str | None
    parent_request_id: str | None = None
    extra: dict[str, Any] = field(default_factory=dict)


@dataclass
class Services:
    """Everything the routes need, built once per app in the lifespan."""

    settings: Settings
    engine: Engine
    repository: Repository
    templates: TemplateCache
    analyzer: Analyzer
    policy: GatePolicy

    def close(self) -> None:
        self.engine.dispose()

    def decide(self, request: GateRequest, *, parent_request_id: str | None = None) -> GateRecord:
        """Run Stages 1-4 on a request and record it in the audit trail."""
        result = run_gate(
            request, templates=self.templates.index(), analyzer=self.analyzer, policy=self.policy
        )
        record = GateRecord(
            request_id=uuid.uuid4().hex,
            created_at=datetime.now(UTC),
            request=request,
            result=result,
            contract_id=uuid.uuid4().hex if result.contract is not None else None,
            parent_request_id=parent_request_id,
        )
        self.repository.save_gate_record(record)
        return record

    def gate_record(self, request_id: str) -> dict[str, Any]:
        record = self.repository.get_gate_record(request_id)
        if record is None:
            raise NotFound(f"no gate request {request_id!r}", field="request_id")
        return record

    def contract(self, contract_id: str) -> tuple[Contract, dict[str, Any]]:
        found = self.repository.get_contract(contract_id)
        if found is None:
            raise NotFound(f"no contract {contract_id!r}", field="contract_id")
        return found


def build_analyzer(settings: Settings) -> Analyzer:
    """The Stage 1 analyzer the settings ask for (only the symbolic one ships offline)."""
    return SymbolicAnalyzer()


def build_services(settings: Settings) -> Services:
    """Connect, migrate, seed and load: everything a running gate needs."""
    engine = create_engine_for(settings.database_url)
    if settings.migrate_on_startup:
        migrate(engine)
    repository = Repository(engine)
    if settings.seed_on_startup:
        seed_templates(repository, settings.templates_dir)
    return Services(
        settings=settings,
        engine=engine,
        repository=repository,
        templates=TemplateCache(repository),
        analyzer=build_analyzer(settings),
        policy=GatePolicy(theta=settings.theta),
    )
