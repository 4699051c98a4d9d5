"""Queries on API keys.

In: key hashes (never secrets: `hash_api_key` turns a secret into what is stored) and roles.
Out: `ApiKeyRecord` values. A revoked key is never returned as active.
Fails: `Conflict` for a key hash already stored, `NotFound` for an unknown key id,
`Unavailable` for database errors.
"""

from __future__ import annotations

import hashlib
from collections.abc import Collection

from sqlalchemy import select
from sqlalchemy.exc import IntegrityError

from app.domain.errors import Conflict, NotFound
from app.store.records import ApiKeyRecord, ApiKeyRole
from app.store.repository._base import RepositoryBase
from app.store.tables import ApiKeyRow, new_id, utc_now


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
    """API keys: issued, looked up by hash, listed, revoked."""

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
