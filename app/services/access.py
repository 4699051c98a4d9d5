"""API keys: issue, list and revoke them; look a presented key up.

In: a role and a name (issue), a key id (revoke), or the secret a client presented (find). Out:
`ApiKeyRecord` values; `issue_api_key` also returns the secret, which is shown once and never
stored (only its SHA-256 is). Fails: `NotFound` for an unknown key id, `Unavailable` for
database errors.
"""

from __future__ import annotations

import secrets

from app.store import Repository, hash_api_key
from app.store.records import ApiKeyRecord, ApiKeyRole

KEY_PREFIX = "sg_"


def issue_api_key(repository: Repository, role: ApiKeyRole, name: str) -> tuple[ApiKeyRecord, str]:
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


def find_key(repository: Repository, secret: str) -> ApiKeyRecord | None:
    """The active key a client presented, or None when it is unknown or revoked."""
    if not secret:
        return None
    return repository.find_active_api_key(hash_api_key(secret))
