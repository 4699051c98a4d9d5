"""API keys (app/services/access.py) on a real database: a key is stored by its hash only, found
by its secret while active, and not found once revoked."""

from __future__ import annotations

from app.services.access import KEY_PREFIX, find_key, issue_api_key
from app.store.records import ApiKeyRole
from app.store.repository import Repository, hash_api_key


class TestIssueApiKey:
    def test_the_secret_is_returned_once_and_only_its_hash_is_stored(
        self, repository: Repository
    ) -> None:
        record, secret = issue_api_key(repository, ApiKeyRole.ROBOT, "kitchen robot")
        assert secret.startswith(KEY_PREFIX) and len(secret) > 40
        assert record.key_hash == hash_api_key(secret) != secret
        (stored,) = repository.list_api_keys()
        assert (stored.id, stored.role, stored.name) == (record.id, ApiKeyRole.ROBOT,
                                                         "kitchen robot")
        assert secret not in stored.model_dump_json()

    def test_every_key_gets_its_own_secret(self, repository: Repository) -> None:
        secrets = {issue_api_key(repository, ApiKeyRole.CURATOR, "c")[1] for _ in range(3)}
        assert len(secrets) == 3


class TestFindKey:
    def test_an_active_key_is_found_by_its_secret(self, repository: Repository) -> None:
        record, secret = issue_api_key(repository, ApiKeyRole.ADMIN, "ops")
        found = find_key(repository, secret)
        assert found is not None and found.id == record.id

    def test_an_unknown_or_empty_secret_finds_nothing(self, repository: Repository) -> None:
        issue_api_key(repository, ApiKeyRole.ADMIN, "ops")
        assert find_key(repository, KEY_PREFIX + "not-a-key") is None
        assert find_key(repository, "") is None

    def test_a_revoked_key_is_no_longer_found(self, repository: Repository) -> None:
        record, secret = issue_api_key(repository, ApiKeyRole.ROBOT, "old robot")
        repository.revoke_api_key(record.id)
        assert find_key(repository, secret) is None
