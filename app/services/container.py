"""The composition root: every service of one app, built once per process.

In: settings. Out: `Components` (built in the app's lifespan by `build_components`: connect,
migrate, seed, load the templates, build the analyzer and every service) and `Deciders` (the
services Stages 1-5 run in, built again in each analysis worker by `build_deciders`). Each
service takes only what it uses, by name; `app/api/deps.py` hands each one to the routes through
its own `Annotated` alias, so no route or service ever sees this container.
The analyzer is symbolic, LLM (through `app.adapters.llm`, cached in the store) or their
ensemble, as `SAFEGATE_ANALYZER` says; the reader, which reads an authorized command into the
task's scope, is always the symbolic analyzer (the same instance when it is the analyzer).
Fails: any start-up failure (database unreachable, migration or seed error) propagates, so the
app never serves with a half-built gate.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

from sqlalchemy.engine import Engine

from app.adapters.llm import AnalysisCache, LitellmClient, LlmAnalyzer, LlmConfig
from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.ensemble import EnsembleAnalyzer
from app.domain.gate import GatePolicy
from app.domain.pipeline import Analyzer, Reader
from app.metrics import Metrics
from app.services.access import KeyService
from app.services.audit_trail import AuditTrail
from app.services.curation import CurationService
from app.services.extensions import ExtensionService
from app.services.gate import GateService
from app.services.input_limits import InputLimits
from app.services.monitoring import MonitorService
from app.services.readiness import ReadinessProbe
from app.services.template_cache import TemplateCache
from app.services.template_catalog import TemplateCatalog
from app.services.verification import VerificationService
from app.store import Repositories, create_engine_for, migrate, seed_templates
from app.store.db import startup_lock


@dataclass(frozen=True)
class Deciders:
    """The services the deciding routes run in the analysis pool (and `/extensions/pending`
    reads through in the app's process)."""

    gate: GateService
    extensions: ExtensionService
    verification: VerificationService


@dataclass(frozen=True)
class Components:
    """Everything one app serves with, built once in its lifespan."""

    settings: Settings
    engine: Engine
    repositories: Repositories
    templates: TemplateCache
    metrics: Metrics
    deciders: Deciders
    audit_trail: AuditTrail
    curation: CurationService
    catalog: TemplateCatalog
    keys: KeyService
    readiness: ReadinessProbe

    def monitor_service(self, origin: str | None) -> MonitorService:
        """The app's monitoring service (`monitoring_fanout.monitoring_for` calls this once)."""
        stores = self.repositories
        return MonitorService(monitoring=stores.monitoring, contracts=stores.contracts,
                              audit=stores.audit, metrics=self.metrics, origin=origin,
                              limits=InputLimits.from_settings(self.settings))

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


def build_deciders(settings: Settings, repositories: Repositories, templates: TemplateCache,
                   metrics: Metrics) -> Deciders:
    """The gate, extension and verification services on these repositories.

    Args:
        settings: the analyzer, policy, budgets and solver timeout.
        repositories: the store.
        templates: the active templates.
        metrics: where decisions and verifications are counted.

    Raises:
        ValueError: an LLM analyzer is asked for but no model is configured.
    """
    limits = InputLimits.from_settings(settings)
    analyzer = build_analyzer(settings, cache=repositories.analysis_cache)
    reader = analyzer if isinstance(analyzer, Reader) else SymbolicAnalyzer(
        reject_from=settings.theta)
    gate = GateService(
        audit=repositories.audit, templates=templates, analyzer=analyzer, reader=reader,
        policy=GatePolicy(theta=settings.theta), metrics=metrics,
        max_verify_attempts=settings.max_verify_attempts,
        solver_timeout_ms=settings.solver_timeout_ms, limits=limits)
    return Deciders(
        gate=gate,
        extensions=ExtensionService(audit=repositories.audit, templates=repositories.templates,
                                    cache=templates, gate=gate),
        verification=VerificationService(
            contracts=repositories.contracts, audit=repositories.audit, metrics=metrics,
            solver_timeout_ms=settings.solver_timeout_ms, limits=limits),
    )


def build_components(settings: Settings, *, metrics: Metrics | None = None) -> Components:
    """Connect, migrate, seed, load the templates and build every service."""
    engine = create_engine_for(settings.database_url)
    repositories = Repositories.on(engine)
    with startup_lock(engine):  # replicas starting together take turns
        if settings.migrate_on_startup:
            migrate(engine)
        if settings.seed_on_startup:
            seed_templates(repositories.templates, settings.templates_dir)
    counted = metrics or Metrics()
    templates = TemplateCache(repositories.templates)
    return Components(
        settings=settings,
        engine=engine,
        repositories=repositories,
        templates=templates,
        metrics=counted,
        deciders=build_deciders(settings, repositories, templates, counted),
        audit_trail=AuditTrail(audit=repositories.audit, contracts=repositories.contracts),
        curation=CurationService(templates=repositories.templates, cache=templates,
                                 solver_lock=threading.Lock(),
                                 solver_timeout_ms=settings.solver_timeout_ms),
        catalog=TemplateCatalog(repositories.templates),
        keys=KeyService(repositories.access),
        readiness=ReadinessProbe(repositories.audit, templates),
    )
