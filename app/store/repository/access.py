"""Queries on API keys and on the LLM analysis cache.

In: key hashes (never secrets: `hash_api_key` turns a secret into what is stored), roles, and
JSON analysis results keyed by the caller's hash of the analyzer's inputs, model and prompt
version. Out: `ApiKeyRecord` values and cached JSON. A revoked key is never returned as active.
Fails: `Conflict` for a key hash already stored, `NotFound` for an unknown key id,
`Unavailable` for database errors.
"""

from __future__ import annotations

import hashlib
from collections.abc import Collection
from typing import Any

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError

from app.domain.errors import Conflict, NotFound, Unavailable
from app.store.records import ApiKeyRecord, ApiKeyRole
from app.store.repository._base import RepositoryBase
from app.store.tables import ApiKeyRow, LlmCacheRow, new_id, utc_now


def hash_api_key(secret: str) -> str:
    """The stored form of an API key: SHA-256 hex of the secret.

    A plain digest suffices because keys are long random tokens, not guessable passwords.

    Args:
        secret: the key as the client sends it.

    Returns:
        64 hex characters.
    """
    return hashlib.sha256(secret.encode()).hexdigest()


def _to_key(row: ApiKeyRow) -> ApiKeyRecord:
    return ApiKeyRecord(
        id=row.id,
        key_hash=row.key_hash,
        role=ApiKeyRole(row.role),
        name=row.name,
        created_at=row.created_at,
        revoked=row.revoked,
    )


class AccessQueries(RepositoryBase):
    """API keys and the LLM cache."""

    def create_api_key(self, *, key_hash: str, role: ApiKeyRole, name: str) -> ApiKeyRecord:
        """Store a new API key by its hash.

        Raises:
            Conflict: a key with this hash exists already.
        """
        with self._transaction("creating an API key") as session:
            row = ApiKeyRow(
                id=new_id(),
                key_hash=key_hash,
                role=role.value,
                name=name,
                created_at=utc_now(),
                revoked=False,
            )
            session.add(row)
            try:
                session.flush()
            except IntegrityError as error:
                raise Conflict("an API key with this hash already exists") from error
            return _to_key(row)

    def find_active_api_key(self, key_hash: str) -> ApiKeyRecord | None:
        """The unrevoked key with this hash, or None (unknown and revoked keys look the same)."""
        with self._transaction("looking up an API key") as session:
            row = session.scalar(
                select(ApiKeyRow)
                .where(ApiKeyRow.key_hash == key_hash)
                .where(ApiKeyRow.revoked.is_(False))
            )
            return _to_key(row) if row is not None else None

    def list_api_keys(self) -> list[ApiKeyRecord]:
        """Every key, revoked ones included, oldest first."""
        with self._transaction("listing API keys") as session:
            rows = session.scalars(select(ApiKeyRow).order_by(ApiKeyRow.created_at, ApiKeyRow.id))
            return [_to_key(row) for row in rows.all()]

    def revoke_api_key(self, key_id: str) -> ApiKeyRecord:
        """Revoke a key for good.

        Raises:
            NotFound: no such key.
        """
        with self._transaction("revoking an API key") as session:
            row = session.get(ApiKeyRow, key_id)
            if row is None:
                raise NotFound(f"no API key {key_id!r}")
            row.revoked = True
            return _to_key(row)

    def revoked_api_key_ids(self, key_ids: Collection[str]) -> set[str]:
        """Which of these key ids are revoked (unknown ids are not reported)."""
        if not key_ids:
            return set()
        with self._transaction("checking API keys for revocation") as session:
            rows = session.scalars(
                select(ApiKeyRow.id)
                .where(ApiKeyRow.id.in_(list(key_ids)))
                .where(ApiKeyRow.revoked.is_(True))
            )
            return set(rows.all())

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
