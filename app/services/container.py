"""The service container: everything a running gate needs, built once per app in the lifespan.

In: settings. Out: `Services` (engine, repository, template cache, analyzer, policy).
Fails: any start-up failure (database unreachable, migration or seed error) propagates, so the
app never serves with a half-built gate.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

from sqlalchemy.engine import Engine

from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.gate import GatePolicy
from app.domain.pipeline import Analyzer
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
class Services:
    """Everything the routes need."""

    settings: Settings
    engine: Engine
    repository: Repository
    templates: TemplateCache
    analyzer: Analyzer
    policy: GatePolicy

    def close(self) -> None:
        self.engine.dispose()


def build_analyzer(settings: Settings) -> Analyzer:
    """The Stage 1 analyzer the settings ask for (only the symbolic one ships offline)."""
    return SymbolicAnalyzer()


def build_services(settings: Settings) -> Services:
    """Connect, migrate, seed and load."""
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
