"""Readiness: whether this process can decide requests now.

In: the store (any repository: they share the database) and the template cache. Out: the number
of active templates loaded. Fails: `Unavailable` (503) when the database does not answer.
"""

from __future__ import annotations

from app.services.template_cache import TemplateCache
from app.store.repository._base import RepositoryBase


class ReadinessProbe:
    """The database answers and the template library is loaded."""

    def __init__(self, store: RepositoryBase, cache: TemplateCache) -> None:
        self._store = store
        self._cache = cache

    def check(self) -> int:
        """The number of active templates loaded.

        Raises:
            Unavailable: the database cannot be reached.
        """
        self._store.ping()
        return len(self._cache.index())
