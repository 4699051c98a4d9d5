"""Gate record queries (the audit trail) on SQLite and PostgreSQL."""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime, timedelta

import pytest

from app.domain.errors import Conflict, NotFound
from app.domain.models import HazardProposal, HazardReport, UnknownFact
from app.store.records import GateRecord
from app.store.repository import Repository

RecordFactory = Callable[..., GateRecord]


def _saved_id(repository: Repository, record: GateRecord) -> str:
    saved = repository.save_gate_record(record)
    assert saved.id is not None
    return saved.id


class TestSaveGateRecord:
    def test_a_saved_record_reads_back_equal(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        report = HazardReport(
            proposals=(
                HazardProposal(
                    level="user",
                    category="physical",
                    hazard_class="scald_hot_liquid",
                    mechanism="hot coffee near a child",
                    entities={"obj": "mug_1"},
                    severity="high",
                    preventability="preventable",
                    confidence="certain",
                ),
            ),
            unknowns=(
                UnknownFact(attribute="age", description="exact age", critical=False, why="x"),
            ),
        )
        saved = repository.save_gate_record(
            make_gate_record(hazard_report=report, decision="defer", question="How old?")
        )
        assert saved.id is not None
        assert repository.get_gate_record(saved.id) == saved
        assert saved.hazard_report == report

    def test_id_and_creation_time_are_filled_in_as_utc(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        before = datetime.now(UTC)
        saved = repository.save_gate_record(make_gate_record())
        assert saved.id is not None and len(saved.id) == 32
        assert saved.created_at is not None and saved.created_at >= before - timedelta(seconds=1)
        assert repository.get_gate_record(saved.id).created_at == saved.created_at

    def test_the_reference_plan_handed_out_reads_back(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        reference = {"plan": [{"action": "PickupObject", "object": "mug_1"},
                              {"action": "GoToObject", "object": "dad", "speed": 0.1}],
                     "goal": 'holding(#"dad", #"mug_1")', "reason": "plan of 2 steps"}
        asked = _saved_id(repository, make_gate_record(reference_plan=reference))
        assert repository.get_gate_record(asked).reference_plan == reference
        not_asked = _saved_id(repository, make_gate_record())
        assert repository.get_gate_record(not_asked).reference_plan is None

    def test_the_request_keeps_its_aliased_fields(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        request_id = _saved_id(repository, make_gate_record())
        request = repository.get_gate_record(request_id).request
        assert request.scene is not None and request.scene.objects[0].inside == "cupboard_1"

    def test_a_reused_id_is_a_conflict(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        repository.save_gate_record(make_gate_record(id="a" * 32))
        with pytest.raises(Conflict):
            repository.save_gate_record(make_gate_record(id="a" * 32))

    def test_an_unknown_parent_is_not_found(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        with pytest.raises(NotFound):
            repository.save_gate_record(make_gate_record(parent_request_id="f" * 32))

    def test_an_unknown_id_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.get_gate_record("0" * 32)


class TestListPendingLibraryExtensions:
    def test_only_unanswered_extend_library_deferrals_are_pending(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        start = datetime.now(UTC)

        def deferral(offset: int) -> GateRecord:
            return make_gate_record(
                decision="defer",
                rule="R2",
                defer_kind="extend_library",
                created_at=start + timedelta(seconds=offset),
            )

        answered = _saved_id(repository, deferral(0))
        newer = _saved_id(repository, deferral(2))
        older = _saved_id(repository, deferral(1))
        _saved_id(repository, make_gate_record(decision="defer", rule="R3", defer_kind="clarify"))
        _saved_id(repository, make_gate_record(parent_request_id=answered))
        pending = repository.list_pending_library_extensions()
        assert [record.id for record in pending] == [older, newer]

    def test_the_limit_is_respected(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        for _ in range(3):
            _saved_id(repository, make_gate_record(decision="defer", defer_kind="extend_library"))
        assert len(repository.list_pending_library_extensions(limit=2)) == 2


class TestLinkChildRecord:
    def test_a_linked_child_answers_its_parent(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        parent = _saved_id(repository, make_gate_record(decision="defer", defer_kind="clarify"))
        child = _saved_id(repository, make_gate_record())
        linked = repository.link_child_record(parent, child)
        assert linked.parent_request_id == parent
        assert [r.id for r in repository.list_child_records(parent)] == [child]

    def test_a_child_linked_elsewhere_is_a_conflict(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        first = _saved_id(repository, make_gate_record())
        second = _saved_id(repository, make_gate_record())
        child = _saved_id(repository, make_gate_record(parent_request_id=first))
        with pytest.raises(Conflict):
            repository.link_child_record(second, child)

    def test_a_loop_is_a_conflict(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        root = _saved_id(repository, make_gate_record())
        child = _saved_id(repository, make_gate_record(parent_request_id=root))
        with pytest.raises(Conflict):
            repository.link_child_record(child, root)

    def test_a_record_cannot_be_its_own_parent(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        record = _saved_id(repository, make_gate_record())
        with pytest.raises(Conflict):
            repository.link_child_record(record, record)

    def test_an_unknown_record_is_not_found(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        record = _saved_id(repository, make_gate_record())
        with pytest.raises(NotFound):
            repository.link_child_record(record, "0" * 32)


class TestMarkGateRecordDowngraded:
    def test_the_flag_and_reason_are_stored(
        self, repository: Repository, make_gate_record: RecordFactory
    ) -> None:
        record = _saved_id(repository, make_gate_record())
        repository.mark_gate_record_downgraded(record, "verification attempts exhausted")
        stored = repository.get_gate_record(record)
        assert (stored.downgraded, stored.downgrade_reason) == (
            True,
            "verification attempts exhausted",
        )

    def test_an_unknown_record_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.mark_gate_record_downgraded("0" * 32, "why")
