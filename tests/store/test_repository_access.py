"""API key and LLM cache queries, and the readiness ping, on SQLite and PostgreSQL."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.domain.errors import Conflict, NotFound, Unavailable
from app.store.db import create_engine_for
from app.store.records import ApiKeyRole
from app.store.repository import Repository, hash_api_key


class TestHashApiKey:
    def test_the_hash_is_stable_and_hides_the_secret(self) -> None:
        digest = hash_api_key("sg_live_secret")
        assert digest == hash_api_key("sg_live_secret")
        assert "secret" not in digest and len(digest) == 64

    def test_different_secrets_hash_differently(self) -> None:
        assert hash_api_key("a") != hash_api_key("b")


class TestApiKeys:
    def test_a_created_key_is_found_by_its_hash(self, repository: Repository) -> None:
        created = repository.create_api_key(
            key_hash=hash_api_key("s1"), role=ApiKeyRole.CURATOR, name="ann"
        )
        found = repository.find_active_api_key(hash_api_key("s1"))
        assert found == created
        assert found is not None and found.role is ApiKeyRole.CURATOR

    def test_an_unknown_hash_finds_nothing(self, repository: Repository) -> None:
        repository.create_api_key(key_hash=hash_api_key("s1"), role=ApiKeyRole.ROBOT, name="r")
        assert repository.find_active_api_key(hash_api_key("s2")) is None

    def test_a_revoked_key_is_no_longer_found(self, repository: Repository) -> None:
        created = repository.create_api_key(
            key_hash=hash_api_key("s1"), role=ApiKeyRole.ADMIN, name="root"
        )
        revoked = repository.revoke_api_key(created.id)
        assert revoked.revoked is True
        assert repository.find_active_api_key(hash_api_key("s1")) is None
        assert [key.revoked for key in repository.list_api_keys()] == [True]

    def test_a_duplicate_hash_is_a_conflict(self, repository: Repository) -> None:
        repository.create_api_key(key_hash=hash_api_key("s1"), role=ApiKeyRole.ROBOT, name="a")
        with pytest.raises(Conflict):
            repository.create_api_key(key_hash=hash_api_key("s1"), role=ApiKeyRole.ADMIN, name="b")

    def test_revoking_an_unknown_key_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.revoke_api_key("0" * 32)

    def test_keys_are_listed_oldest_first(self, repository: Repository) -> None:
        for name in ("first", "second", "third"):
            repository.create_api_key(key_hash=hash_api_key(name), role=ApiKeyRole.ROBOT, name=name)
        assert [key.name for key in repository.list_api_keys()] == ["first", "second", "third"]


class TestLlmCache:
    def test_a_stored_result_is_returned_for_the_same_key_model_and_prompt(
        self, repository: Repository
    ) -> None:
        result = {"proposals": [{"hazard_class": "scald_hot_liquid"}], "unknowns": []}
        repository.put_cached_analysis("k1", "gpt-x", "v3", result)
        assert repository.get_cached_analysis("k1", "gpt-x", "v3") == result

    def test_another_model_or_prompt_version_misses(self, repository: Repository) -> None:
        repository.put_cached_analysis("k1", "gpt-x", "v3", {"proposals": []})
        assert repository.get_cached_analysis("k1", "gpt-y", "v3") is None
        assert repository.get_cached_analysis("k1", "gpt-x", "v4") is None

    def test_putting_again_replaces_the_result(self, repository: Repository) -> None:
        repository.put_cached_analysis("k1", "gpt-x", "v3", {"n": 1})
        repository.put_cached_analysis("k1", "gpt-x", "v3", {"n": 2})
        assert repository.get_cached_analysis("k1", "gpt-x", "v3") == {"n": 2}


class TestPing:
    def test_a_reachable_database_answers(self, repository: Repository) -> None:
        assert repository.ping() is None  # and raises nothing

    def test_an_unreachable_database_is_unavailable(self, tmp_path: Path) -> None:
        missing = tmp_path / "no such directory" / "safegate.db"
        with pytest.raises(Unavailable):
            Repository(create_engine_for(f"sqlite:///{missing}")).ping()
