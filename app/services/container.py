"""The service container: everything a running gate needs, built once per app in the lifespan.

In: settings. Out: `Services` (engine, repository, template cache, analyzer, reader, policy).
The analyzer is symbolic, LLM (through `app.adapters.llm`, cached in the repository) or their
ensemble, as `SAFEGATE_ANALYZER` says; the reader, which reads an authorized command into the
task's scope, is always the symbolic analyzer (the same instance when it is the analyzer).
Fails: any start-up failure (database unreachable, migration or seed error) propagates, so the
app never serves with a half-built gate.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field

from sqlalchemy.engine import Engine

from app.adapters.llm import AnalysisCache, LitellmClient, LlmAnalyzer, LlmConfig
from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.ensemble import EnsembleAnalyzer
from app.domain.gate import GatePolicy
from app.domain.pipeline import Analyzer, Reader
from app.metrics import Metrics
from app.store import Repository, create_engine_for, migrate, seed_templates
from app.store.db import startup_lock


class TemplateCache:
    """The active templates in memory, reloaded after a curator changes the library.

    `version` counts the reloads; the analysis workers reload theirs when a job carries a
    version they have not seen.
    """

    def __init__(self, repository: Repository) -> None:
        self._repository = repository
        self._lock = threading.Lock()
        self._index = TemplateIndex(())
        self.version = 0
        self.refresh()

    def refresh(self) -> None:
        index = TemplateIndex(self._repository.list_active_templates())
        with self._lock:
            self._index = index
            self.version += 1

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
    metrics: Metrics = field(default_factory=Metrics)
    reader: Reader | None = None
    solver_lock: threading.Lock = field(default_factory=threading.Lock)
    """Held around every Z3 use in this process (template validation): Z3's shared context is
    not thread-safe, and concurrent template writes in the threadpool failed with a 500."""

    def close(self) -> None:
        self.engine.dispose()


def llm_config(settings: Settings) -> LlmConfig:
    """The LLM connection the settings describe.

    Args:
        settings: with `llm_model` (any litellm model string), `llm_api_base`, `llm_api_key`
            and `llm_timeout` (seconds).

    Returns:
        The config for `LitellmClient`.

    Raises:
        ValueError: no `SAFEGATE_LLM_MODEL` is set.
    """
    if not settings.llm_model:
        raise ValueError(
            f"SAFEGATE_ANALYZER={settings.analyzer} needs SAFEGATE_LLM_MODEL "
            "(a litellm model string such as openai/gpt-4o-mini or ollama/llama3)"
        )
    return LlmConfig(
        model=settings.llm_model,
        api_base=settings.llm_api_base,
        api_key=settings.llm_api_key,
        timeout=settings.llm_timeout,
    )


def build_analyzer(settings: Settings, cache: AnalysisCache | None = None) -> Analyzer:
    """The Stage 1 analyzer the settings ask for.

    `symbolic` is offline and needs nothing else; `llm` asks the configured LLM; `ensemble`
    runs both and reports the union of their hazards and unknowns.

    Args:
        settings: `analyzer` and, for `llm`/`ensemble`, the `llm_*` settings.
        cache: where LLM analyses are cached (the repository); None disables caching.

    Returns:
        The analyzer.

    Raises:
        ValueError: an LLM is asked for but no model is configured.
    """
    if settings.analyzer == "symbolic":
        return SymbolicAnalyzer(reject_from=settings.theta)
    client = LitellmClient(llm_config(settings))
    if settings.analyzer == "llm":
        return LlmAnalyzer(client, cache=cache, theta=settings.theta,
                           batch_levels=settings.llm_batch_levels)
    # The symbolic member reads the command (and fails closed when it cannot), so an LLM that
    # finds nothing adds nothing rather than holding every request back.
    llm = LlmAnalyzer(client, cache=cache, require_findings=False, theta=settings.theta,
                      batch_levels=settings.llm_batch_levels)
    return EnsembleAnalyzer([SymbolicAnalyzer(reject_from=settings.theta), llm])


def build_services(settings: Settings, *, metrics: Metrics | None = None) -> Services:
    """Connect, migrate, seed and load."""
    engine = create_engine_for(settings.database_url)
    repository = Repository(engine)
    with startup_lock(engine):  # replicas starting together take turns
        if settings.migrate_on_startup:
            migrate(engine)
        if settings.seed_on_startup:
            seed_templates(repository, settings.templates_dir)
    analyzer = build_analyzer(settings, cache=repository)
    return Services(
        settings=settings,
        engine=engine,
        repository=repository,
        templates=TemplateCache(repository),
        analyzer=analyzer,
        policy=GatePolicy(theta=settings.theta),
        metrics=metrics or Metrics(),
        reader=analyzer if isinstance(analyzer, Reader) else SymbolicAnalyzer(
            reject_from=settings.theta),
    )
