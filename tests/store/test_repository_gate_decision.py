"""The gate's one-transaction write of a decision and its contract (the hot path)."""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime, timedelta

import pytest

from app.domain.errors import Conflict, NotFound
from app.store.records import ContractRecord, GateRecord
from app.store.repository import Repository

RecordFactory = Callable[..., GateRecord]


def _contract(request_id: str, **overrides: object) -> ContractRecord:
    fields: dict[str, object] = {
        "request_id": request_id,
        "contract": {"invariants": [{"id": "not_hot", "formula": "not hot(#mug_1)"}]},
        "template_versions": {"test.hot_mug": 1},
        "max_attempts": 3,
    }
    fields.update(overrides)
    return ContractRecord.model_validate(fields)


class TestSaveGateDecision:
    def test_a_decision_without_contract_reads_back_equal(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        before = datetime.now(UTC)
        saved, contract = repository.save_gate_decision(make_gate_record(decision="defer"))
        assert contract is None
        assert saved.id is not None and len(saved.id) == 32
        assert saved.created_at is not None and saved.created_at >= before - timedelta(seconds=1)
        assert repository.get_gate_record(saved.id) == saved

    def test_an_authorization_and_its_contract_are_linked_both_ways(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        record = make_gate_record(id="a" * 32)
        saved, contract = repository.save_gate_decision(record, _contract("a" * 32))
        assert contract is not None and contract.id is not None
        assert saved.contract_id == contract.id
        assert repository.get_gate_record(saved.id or "") == saved
        assert repository.get_contract(contract.id) == contract
        assert contract.attempts_left == 3

    def test_an_answer_links_to_its_parent(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        parent, _ = repository.save_gate_decision(make_gate_record())
        child, _ = repository.save_gate_decision(make_gate_record(parent_request_id=parent.id))
        assert [r.id for r in repository.list_child_records(parent.id or "")] == [child.id]

    def test_an_unknown_parent_is_refused_and_nothing_is_written(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        with pytest.raises(NotFound):
            repository.save_gate_decision(make_gate_record(id="b" * 32,
                                                           parent_request_id="c" * 32))
        with pytest.raises(NotFound):
            repository.get_gate_record("b" * 32)

    def test_a_duplicate_record_id_is_a_conflict(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        repository.save_gate_decision(make_gate_record(id="d" * 32))
        with pytest.raises(Conflict):
            repository.save_gate_decision(make_gate_record(id="d" * 32))

    def test_a_duplicate_contract_id_rolls_the_record_back(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        first = make_gate_record(id="e" * 32)
        repository.save_gate_decision(first, _contract("e" * 32, id="f" * 32))
        second = make_gate_record(id="0" * 32)
        with pytest.raises(Conflict):
            repository.save_gate_decision(second, _contract("0" * 32, id="f" * 32))
        with pytest.raises(NotFound):
            repository.get_gate_record("0" * 32)

    def test_a_contract_for_another_request_is_refused(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        with pytest.raises(NotFound):
            repository.save_gate_decision(make_gate_record(id="1" * 32), _contract("2" * 32))
