"""Monitoring session and event queries on SQLite and PostgreSQL."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import pytest
from sqlalchemy import Engine

from app.domain.errors import NotFound, Unavailable
from app.domain.models import InitialState
from app.store.records import ContractRecord, MonitorSessionRecord
from app.store.repository import MonitorLogWrite, Repository

INITIAL_STATE = InitialState.model_validate(
    {
        "scene": {
            "objects": [{"id": "mug_1", "type": "Mug", "properties": {"temperature": "hot"}}]
        },
        "robot": {"holding": None, "room": "kitchen"},
    }
)


@pytest.fixture
def monitor_session(repository: Repository, saved_contract: ContractRecord) -> MonitorSessionRecord:
    assert saved_contract.id is not None
    return repository.create_monitor_session(
        MonitorSessionRecord(
            contract_id=saved_contract.id,
            initial_state=INITIAL_STATE,
            counters={"actions": 0},
        )
    )


class TestCreateMonitorSession:
    def test_a_created_session_reads_back_equal(
        self, repository: Repository, monitor_session: MonitorSessionRecord
    ) -> None:
        assert monitor_session.id is not None
        stored = repository.get_monitor_session(monitor_session.id)
        assert stored == monitor_session
        assert stored.initial_state == INITIAL_STATE
        assert stored.halted is False

    def test_an_unknown_contract_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.create_monitor_session(
                MonitorSessionRecord(contract_id="0" * 32, initial_state=INITIAL_STATE)
            )

    def test_an_unknown_session_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.get_monitor_session("0" * 32)


class TestUpdateMonitorSession:
    def test_counters_are_replaced(
        self, repository: Repository, monitor_session: MonitorSessionRecord
    ) -> None:
        assert monitor_session.id is not None
        updated = repository.update_monitor_session(monitor_session.id, counters={"actions": 4})
        assert updated.counters == {"actions": 4}
        assert updated.halted is False
        assert updated.updated_at is not None and monitor_session.updated_at is not None
        assert updated.updated_at >= monitor_session.updated_at

    def test_a_violation_halts_the_session(
        self, repository: Repository, monitor_session: MonitorSessionRecord
    ) -> None:
        assert monitor_session.id is not None
        violation = {"kind": "guard", "condition_id": "handover_only_when_cool"}
        repository.update_monitor_session(monitor_session.id, halt_violation=violation)
        stored = repository.get_monitor_session(monitor_session.id)
        assert (stored.halted, stored.halt_violation) == (True, violation)

    def test_the_first_violation_is_the_one_kept(
        self, repository: Repository, monitor_session: MonitorSessionRecord
    ) -> None:
        assert monitor_session.id is not None
        repository.update_monitor_session(monitor_session.id, halt_violation={"condition_id": "a"})
        later = repository.update_monitor_session(
            monitor_session.id, halt_violation={"condition_id": "b"}, counters={"actions": 9}
        )
        assert later.halt_violation == {"condition_id": "a"}
        assert (later.halted, later.counters) == (True, {"actions": 9})

    def test_an_unknown_session_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.update_monitor_session("0" * 32, counters={})


class TestMonitorEvents:
    def test_events_are_numbered_from_one_in_order(
        self, repository: Repository, monitor_session: MonitorSessionRecord
    ) -> None:
        assert monitor_session.id is not None
        for kind in ("before", "allow", "after"):
            repository.append_monitor_event(monitor_session.id, kind, {"wire_seq": 7})
        events = repository.list_monitor_events(monitor_session.id)
        assert [(e.seq, e.type) for e in events] == [(1, "before"), (2, "allow"), (3, "after")]
        assert events[0].payload == {"wire_seq": 7}

    def test_listing_after_a_sequence_number_pages_through(
        self, repository: Repository, monitor_session: MonitorSessionRecord
    ) -> None:
        assert monitor_session.id is not None
        for index in range(5):
            repository.append_monitor_event(monitor_session.id, "allow", {"i": index})
        page = repository.list_monitor_events(monitor_session.id, after_seq=2, limit=2)
        assert [e.seq for e in page] == [3, 4]

    def test_concurrent_appends_get_distinct_numbers(
        self,
        migrated_engine: Engine,
        repository: Repository,
        monitor_session: MonitorSessionRecord,
    ) -> None:
        session_id = monitor_session.id
        assert session_id is not None

        def append(index: int) -> int:
            event = Repository(migrated_engine).append_monitor_event(
                session_id, "allow", {"i": index}
            )
            return event.seq

        with ThreadPoolExecutor(max_workers=3) as pool:
            numbers = sorted(pool.map(append, range(9)))
        assert numbers == list(range(1, 10))

    def test_an_event_for_an_unknown_session_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.append_monitor_event("0" * 32, "allow", {})


class TestGroupCommit:
    """`write_monitor_logs`: the monitor's group commit, numbered by its caller."""

    @pytest.fixture
    def two_sessions(self, repository: Repository,
                     saved_contract: ContractRecord) -> list[str]:
        assert saved_contract.id is not None
        ids = [repository.create_monitor_session(MonitorSessionRecord(
            contract_id=saved_contract.id, initial_state=INITIAL_STATE)).id for _ in range(2)]
        return [i for i in ids if i is not None]

    def test_several_sessions_steps_halt_and_counters_land_in_one_write(
        self, repository: Repository, two_sessions: list[str]
    ) -> None:
        first, second = two_sessions
        violation = {"condition_id": "skill.toggle", "kind": "guard"}
        repository.write_monitor_logs([
            MonitorLogWrite(first, 1, [{"in": {"seq": 1}, "out": "allow"}]),
            MonitorLogWrite(second, 1, [{"in": {"seq": 1}, "out": "violation"}],
                            counters={"messages": 1}, halt_violation=violation),
        ])
        assert [e.payload["messages"] for e in repository.list_monitor_events(first)] == [
            [{"in": {"seq": 1}, "out": "allow"}]]
        halted = repository.get_monitor_session(second)
        assert (halted.halted, halted.halt_violation, halted.counters) == (
            True, violation, {"messages": 1})
        assert repository.last_monitor_event_seq(first) == 1
        assert repository.last_monitor_event_seq(two_sessions[0] + "x") == 0

    def test_an_event_number_already_taken_fails_the_whole_write(
        self, repository: Repository, two_sessions: list[str]
    ) -> None:
        first, second = two_sessions
        repository.write_monitor_logs([MonitorLogWrite(first, 1, [{"in": {}, "out": "allow"}])])
        with pytest.raises(Unavailable):
            repository.write_monitor_logs([
                MonitorLogWrite(second, 1, [{"in": {}, "out": "allow"}]),
                MonitorLogWrite(first, 1, [{"in": {}, "out": "allow"}]),  # another writer's
            ])
        assert repository.list_monitor_events(second) == []
        assert len(repository.list_monitor_events(first)) == 1

    def test_the_first_halt_is_kept(
        self, repository: Repository, two_sessions: list[str]
    ) -> None:
        first = two_sessions[0]
        for n, condition in enumerate(("a", "b"), start=1):
            repository.write_monitor_logs([MonitorLogWrite(
                first, n, [], halt_violation={"condition_id": condition})])
        stored = repository.get_monitor_session(first)
        assert stored.halt_violation == {"condition_id": "a"}
        assert repository.list_monitor_events(first) == []
