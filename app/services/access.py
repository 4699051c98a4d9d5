"""API keys: issue, list and revoke them; look a presented key up.

In: a role and a name (issue), a key id (revoke), or the secret a client presented (find). Out:
`ApiKeyRecord` values; `issue_api_key` also returns the secret, which is shown once and never
stored (only its SHA-256 is). Fails: `NotFound` for an unknown key id, `Unavailable` for
database errors.
"""

from __future__ import annotations

import secrets
from collections.abc import Collection

from app.store.records import ApiKeyRecord, ApiKeyRole
from app.store.repository import hash_api_key
from app.store.repository.access import AccessQueries

KEY_PREFIX = "sg_"


def issue_api_key(repository: AccessQueries, role: ApiKeyRole,
                  name: str) -> tuple[ApiKeyRecord, str]:
    """Create a key with a fresh random secret.

    Args:
        repository: where the key's hash is stored.
        role: robot, curator or admin.
        name: who or what holds the key.

    Returns:
        The stored record and the secret (to be shown once).
    """
    secret = KEY_PREFIX + secrets.token_urlsafe(32)
    record = repository.create_api_key(key_hash=hash_api_key(secret), role=role, name=name)
    return record, secret


def find_key(repository: AccessQueries, secret: str) -> ApiKeyRecord | None:
    """The active key a client presented, or None when it is unknown or revoked."""
    if not secret:
        return None
    return repository.find_active_api_key(hash_api_key(secret))


class KeyService:
    """API keys for the API: issue, list, revoke, and look up the key a caller presented."""

    def __init__(self, access: AccessQueries) -> None:
        self._access = access

    def issue(self, role: ApiKeyRole, name: str) -> tuple[ApiKeyRecord, str]:
        """A new key and its secret (see `issue_api_key`)."""
        return issue_api_key(self._access, role, name)

    def find(self, secret: str) -> ApiKeyRecord | None:
        """The active key with this secret, or None."""
        return find_key(self._access, secret)

    def list(self) -> list[ApiKeyRecord]:
        """Every key, revoked ones included."""
        return self._access.list_api_keys()

    def revoke(self, key_id: str) -> ApiKeyRecord:
        """Revoke a key for good.

        Raises:
            NotFound: no such key.
        """
        return self._access.revoke_api_key(key_id)

    def revoked(self, key_ids: Collection[str]) -> set[str]:
        """Which of these key ids are revoked."""
        return self._access.revoked_api_key_ids(key_ids)
