"""The repository: every SQL query SafeGate makes, behind typed methods on one class.

In: an `Engine` (or a `sessionmaker`) and domain values. Out: domain values and the records of
`app.store.records`; no ORM object ever leaves. Each method is one transaction. The queries are
split by family into the modules beside this one so each stays readable; `Repository` combines
them. Every database failure surfaces as `app.domain.errors.Unavailable`, so a caller can never
read a broken database as "no hazard template", "no key" or "attempts left".
"""

from app.store.repository.access import AccessQueries, hash_api_key
from app.store.repository.audit import AuditQueries
from app.store.repository.contracts import ContractQueries
from app.store.repository.monitoring import MonitorLogWrite, MonitorQueries
from app.store.repository.template_documents import template_content_hash
from app.store.repository.template_imports import TemplateImportQueries


class Repository(
    TemplateImportQueries, AuditQueries, ContractQueries, MonitorQueries, AccessQueries
):
    """All of SafeGate's persistence: templates, audit trail, contracts, monitoring, keys, cache."""


__all__ = ["MonitorLogWrite", "Repository", "hash_api_key", "template_content_hash"]
