"""The repositories: every SQL query SafeGate makes, one class per concern.

In: an `Engine` (or a `sessionmaker`) and domain values. Out: domain values and the records of
`app.store.records`; no ORM object ever leaves. Each method is one transaction.
One repository per concern, each in its own module: `TemplateRepository` (the library, its
versions and imports), `AuditRepository` (gate records and how they chain; a decision's
contract is written with it), `ContractRepository` (contracts and their verification budget),
`MonitorRepository` (monitoring sessions and events), `AccessRepository` (API keys) and
`AnalysisCacheRepository` (the LLM analysis cache). `Repositories.on(engine)` builds them all
on one session factory; the app's services each take only the ones they need. `Repository`
combines every family in one object for the command line, seeding and tests.
Every database failure surfaces as `app.domain.errors.Unavailable`, so a caller can never
read a broken database as "no hazard template", "no key" or "attempts left".
"""

from __future__ import annotations

from dataclasses import dataclass

from sqlalchemy import Engine

from app.store.db import make_session_factory
from app.store.repository.access import AccessQueries, hash_api_key
from app.store.repository.analysis_cache import AnalysisCacheQueries
from app.store.repository.audit import AuditQueries
from app.store.repository.contracts import ContractQueries
from app.store.repository.monitoring import MonitorLogWrite, MonitorQueries
from app.store.repository.template_documents import template_content_hash
from app.store.repository.template_imports import TemplateImportQueries


class TemplateRepository(TemplateImportQueries):
    """The Hazard Template Library: templates, their versions and statuses, imports."""


class AuditRepository(AuditQueries):
    """The audit trail: gate records (with a decision's contract) and how they chain."""


class ContractRepository(ContractQueries):
    """Task Safety Contracts, their verification attempts and budget."""


class MonitorRepository(MonitorQueries):
    """Runtime monitoring sessions and their event logs."""


class AccessRepository(AccessQueries):
    """API keys, stored by hash."""


class AnalysisCacheRepository(AnalysisCacheQueries):
    """The LLM analysis cache (an `app.adapters.llm.AnalysisCache`)."""


@dataclass(frozen=True)
class Repositories:
    """One repository per concern, sharing one session factory (built once per process)."""

    templates: TemplateRepository
    audit: AuditRepository
    contracts: ContractRepository
    monitoring: MonitorRepository
    access: AccessRepository
    analysis_cache: AnalysisCacheRepository

    @classmethod
    def on(cls, engine: Engine) -> Repositories:
        """Every repository on `engine`.

        Args:
            engine: the database; its session factory is made once and shared.
        """
        sessions = make_session_factory(engine)
        return cls(
            templates=TemplateRepository(sessions),
            audit=AuditRepository(sessions),
            contracts=ContractRepository(sessions),
            monitoring=MonitorRepository(sessions),
            access=AccessRepository(sessions),
            analysis_cache=AnalysisCacheRepository(sessions),
        )


class Repository(
    TemplateImportQueries, AuditQueries, ContractQueries, MonitorQueries, AccessQueries,
    AnalysisCacheQueries,
):
    """The whole store in one object, for the command line, seeding and tests."""


__all__ = [
    "AccessRepository",
    "AnalysisCacheRepository",
    "AuditRepository",
    "ContractRepository",
    "MonitorLogWrite",
    "MonitorRepository",
    "Repositories",
    "Repository",
    "TemplateRepository",
    "hash_api_key",
    "template_content_hash",
]
