"""Contract and verification attempt queries on SQLite and PostgreSQL."""

from __future__ import annotations

from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor

import pytest
from sqlalchemy import Engine

from app.domain.errors import AttemptsExhausted, Conflict, NotFound
from app.store.records import (
    ContractRecord,
    ContractStatus,
    GateRecord,
    VerificationAttemptRecord,
)
from app.store.repository import Repository


class TestSaveContract:
    def test_a_saved_contract_reads_back_and_is_attached_to_its_request(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        assert saved_contract.id is not None
        assert repository.get_contract(saved_contract.id) == saved_contract
        gate = repository.get_gate_record(saved_contract.request_id)
        assert gate.contract_id == saved_contract.id
        assert saved_contract.attempts_left == 3

    def test_an_unknown_request_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.save_contract(
                ContractRecord(request_id="0" * 32, contract={}, max_attempts=3)
            )

    def test_a_reused_id_is_a_conflict(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        with pytest.raises(Conflict):
            repository.save_contract(saved_contract)

    def test_an_unknown_contract_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.get_contract("0" * 32)


class TestUseVerificationAttempt:
    def test_each_attempt_is_counted(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        assert saved_contract.id is not None
        counts = [repository.use_verification_attempt(saved_contract.id) for _ in range(3)]
        assert [c.attempts_used for c in counts] == [1, 2, 3]
        assert counts[-1].attempts_left == 0

    def test_no_attempt_beyond_the_maximum(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        assert saved_contract.id is not None
        for _ in range(3):
            repository.use_verification_attempt(saved_contract.id)
        with pytest.raises(AttemptsExhausted):
            repository.use_verification_attempt(saved_contract.id)
        assert repository.get_contract(saved_contract.id).attempts_used == 3

    def test_an_exhausted_contract_gives_no_attempt(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        assert saved_contract.id is not None
        repository.mark_contract_exhausted(saved_contract.id)
        with pytest.raises(AttemptsExhausted):
            repository.use_verification_attempt(saved_contract.id)

    def test_concurrent_callers_never_exceed_the_maximum(
        self,
        repository: Repository,
        migrated_engine: Engine,
        make_gate_record: Callable[..., GateRecord],
    ) -> None:
        gate = repository.save_gate_record(make_gate_record())
        assert gate.id is not None
        contract = repository.save_contract(
            ContractRecord(request_id=gate.id, contract={}, max_attempts=5)
        )
        assert contract.id is not None
        contract_id = contract.id

        def attempt(_: int) -> bool:
            try:
                Repository(migrated_engine).use_verification_attempt(contract_id)
            except AttemptsExhausted:
                return False
            return True

        with ThreadPoolExecutor(max_workers=4) as pool:
            granted = sum(pool.map(attempt, range(12)))
        assert granted == 5
        assert repository.get_contract(contract_id).attempts_used == 5

    def test_an_unknown_contract_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.use_verification_attempt("0" * 32)


class TestMarkContractExhausted:
    def test_the_status_becomes_exhausted(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        assert saved_contract.id is not None
        exhausted = repository.mark_contract_exhausted(saved_contract.id)
        assert exhausted.status is ContractStatus.EXHAUSTED
        assert repository.get_contract(saved_contract.id).attempts_left == 0

    def test_an_unknown_contract_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.mark_contract_exhausted("0" * 32)


class TestVerificationAttempts:
    def test_saved_attempts_are_listed_in_order(
        self, repository: Repository, saved_contract: ContractRecord
    ) -> None:
        assert saved_contract.id is not None
        failed = repository.save_verification_attempt(
            VerificationAttemptRecord(
                contract_id=saved_contract.id,
                plan=[{"action": "PickupObject", "object": "mug_1"}],
                ok=False,
                violations=[{"step": 0, "kind": "guard", "condition_id": "not_hot"}],
                duration_ms=12.5,
            )
        )
        passed = repository.save_verification_attempt(
            VerificationAttemptRecord(
                contract_id=saved_contract.id, plan=[], ok=True, duration_ms=3.0
            )
        )
        listed = repository.list_verification_attempts(saved_contract.id)
        assert listed == [failed, passed]
        assert listed[0].violations[0]["condition_id"] == "not_hot"

    def test_an_attempt_for_an_unknown_contract_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.save_verification_attempt(
                VerificationAttemptRecord(contract_id="0" * 32, plan=[], ok=True, duration_ms=1)
            )
