"""Queries on the LLM analysis cache.

In: JSON analysis results keyed by the caller's hash of the analyzer's inputs, model and prompt
version. Out: the cached JSON, or None.
Fails: `Unavailable` for database errors (a concurrent writer of the same key is not one).
"""

from __future__ import annotations

from typing import Any

from sqlalchemy.exc import IntegrityError

from app.domain.errors import Unavailable
from app.store.repository._base import RepositoryBase
from app.store.tables import LlmCacheRow, utc_now


class AnalysisCacheQueries(RepositoryBase):
    def get_cached_analysis(
        self, cache_key: str, model: str, prompt_version: str
    ) -> dict[str, Any] | None:
        """A cached analysis result, or None when there is none for this key, model and prompt."""
        with self._transaction("reading the LLM cache") as session:
            row = session.get(LlmCacheRow, (cache_key, model, prompt_version))
            return dict(row.result) if row is not None else None

    def put_cached_analysis(
        self, cache_key: str, model: str, prompt_version: str, result: dict[str, Any]
    ) -> None:
        """Store (or replace) a cached analysis result."""
        identity = (cache_key, model, prompt_version)
        try:
            with self._transaction("writing the LLM cache") as session:
                row = session.get(LlmCacheRow, identity)
                if row is None:
                    session.add(
                        LlmCacheRow(
                            cache_key=cache_key,
                            model=model,
                            prompt_version=prompt_version,
                            result=dict(result),
                            created_at=utc_now(),
                        )
                    )
                else:
                    row.result = dict(result)
                    row.created_at = utc_now()
        except Unavailable as error:
            if not isinstance(error.__cause__, IntegrityError):
                raise
            # A concurrent writer stored the same key first; overwrite with ours.
            with self._transaction("writing the LLM cache") as session:
                existing = session.get(LlmCacheRow, identity)
                if existing is not None:
                    existing.result = dict(result)
                    existing.created_at = utc_now()
