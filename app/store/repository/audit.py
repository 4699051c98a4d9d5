"""Queries on the audit trail: every gate request with its decision, and how records chain.

In: `GateRecord` values. Out: `GateRecord` values with their id and creation time. A record is
never rewritten except to link it to its parent, attach its contract or mark it downgraded.
A "pending" library extension is a record deferred with `extend_library` that no later record
(an answer or a re-evaluation) has yet been linked to.
Fails: `NotFound` for unknown ids, `Conflict` for a link that would break the chain,
`Unavailable` for database errors.
"""

from __future__ import annotations

from typing import Any

from sqlalchemy import Connection, Table, exists, insert, select
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session, aliased

from app.domain.errors import Conflict, NotFound
from app.domain.gate import Decision, DeferKind, Rule
from app.domain.models import GateRequest, HazardReport
from app.store.records import ContractRecord, GateRecord
from app.store.repository._base import RepositoryBase
from app.store.tables import ContractRow, GateRecordRow, new_id, utc_now

_GATE_TABLE: Table = GateRecordRow.__table__  # type: ignore[assignment]
_CONTRACT_TABLE: Table = ContractRow.__table__  # type: ignore[assignment]
# Built once: a statement object memoises its compiled-cache key, a fresh one per call would not.
_INSERT_GATE = insert(_GATE_TABLE)
_INSERT_CONTRACT = insert(_CONTRACT_TABLE)


def _to_record(row: GateRecordRow) -> GateRecord:
    return GateRecord(
        id=row.id,
        created_at=row.created_at,
        request=GateRequest.model_validate(row.request),
        hazard_report=(
            HazardReport.model_validate(row.hazard_report)
            if row.hazard_report is not None
            else None
        ),
        decision=Decision(row.decision),
        rule=Rule(row.rule),
        defer_kind=None if row.defer_kind is None else DeferKind(row.defer_kind),
        question=row.question,
        triggers=list(row.triggers),
        timings=dict(row.timings),
        analyzer=row.analyzer,
        template_versions={str(k): int(v) for k, v in row.template_versions.items()},
        contract_id=row.contract_id,
        parent_request_id=row.parent_request_id,
        downgraded=row.downgraded,
        downgrade_reason=row.downgrade_reason,
        reference_plan=None if row.reference_plan is None else dict(row.reference_plan),
    )


def _gate_values(record: GateRecord) -> dict[str, Any]:
    """The gate_records row of a record whose id and creation time are set."""
    return {
        "id": record.id,
        "created_at": record.created_at,
        # Models go to the JSON encoder as they are (see `db._json_text`): no dict in between.
        "request": record.request,
        "hazard_report": record.hazard_report,
        # The columns hold the enums' values (a string column, readable by any SQL client).
        "decision": record.decision.value,
        "rule": record.rule.value,
        "defer_kind": None if record.defer_kind is None else record.defer_kind.value,
        "question": record.question,
        "triggers": list(record.triggers),
        "timings": dict(record.timings),
        "analyzer": record.analyzer,
        "template_versions": dict(record.template_versions),
        "contract_id": record.contract_id,
        "parent_request_id": record.parent_request_id,
        "downgraded": record.downgraded,
        "downgrade_reason": record.downgrade_reason,
        "reference_plan": record.reference_plan,
    }


def _contract_values(contract: ContractRecord) -> dict[str, Any]:
    """The contracts row of a contract whose id and creation time are set."""
    return {
        "id": contract.id,
        "request_id": contract.request_id,
        "contract": dict(contract.contract),
        "template_versions": dict(contract.template_versions),
        "created_at": contract.created_at,
        "attempts_used": contract.attempts_used,
        "max_attempts": contract.max_attempts,
        "status": contract.status.value,
    }


def _exists(connection: Connection, table: Table, row_id: str) -> bool:
    return connection.execute(
        select(table.c.id).where(table.c.id == row_id)).first() is not None


def _gate_row(session: Session, request_id: str) -> GateRecordRow:
    row = session.get(GateRecordRow, request_id)
    if row is None:
        raise NotFound(f"no gate request {request_id!r}")
    return row


def _insert_gate_record(session: Session, record: GateRecord) -> GateRecordRow:
    """Add a gate record in an open transaction."""
    if record.parent_request_id is not None:
        _gate_row(session, record.parent_request_id)
    if record.id is not None and session.get(GateRecordRow, record.id) is not None:
        raise Conflict(f"gate request {record.id!r} already exists")
    row = GateRecordRow(**_gate_values(record.model_copy(update={
        "id": record.id or new_id(), "created_at": record.created_at or utc_now()})))
    session.add(row)
    session.flush()
    return row


class AuditQueries(RepositoryBase):
    """Gate records: the decision audit trail."""

    def save_gate_record(self, record: GateRecord) -> GateRecord:
        """Store a gate decision.

        Args:
            record: the decision; a missing id or created_at is filled in.

        Returns:
            The record as stored.

        Raises:
            NotFound: `parent_request_id` names no stored record.
            Conflict: a record with this id already exists.
        """
        with self._transaction("saving a gate record") as session:
            return _to_record(_insert_gate_record(session, record))

    def save_gate_decision(
        self, record: GateRecord, contract: ContractRecord | None = None
    ) -> tuple[GateRecord, ContractRecord | None]:
        """Store a decision and, for an authorization, its contract, in one transaction.

        Either both are in the audit trail or neither is, so no authorization is ever
        recorded without the contract it was given. This is the gate's hot path, so it writes
        with Core statements (two inserts at most) and returns the records it was given with
        their ids and times filled in, instead of reading the rows back.

        Args:
            record: the decision; its id must be set when a contract is given.
            contract: the compiled contract whose `request_id` is the record's id.

        Returns:
            The stored record (pointing at its contract) and the stored contract.

        Raises:
            NotFound: `parent_request_id` names no stored record, or the contract names another
                request than the record.
            Conflict: a record or contract with this id already exists.
        """
        record_id = record.id or new_id()
        created_at = record.created_at or utc_now()
        stored_contract = None
        if contract is not None:
            if contract.request_id != record_id:
                raise NotFound(f"no gate request {contract.request_id!r}")
            stored_contract = contract.model_copy(update={
                "id": contract.id or new_id(),
                "created_at": contract.created_at or utc_now(),
            })
        stored = record.model_copy(update={
            "id": record_id,
            "created_at": created_at,
            "contract_id": stored_contract.id if stored_contract else record.contract_id,
        })
        with self._core_transaction("saving a gate decision") as connection:
            if stored.parent_request_id is not None and not _exists(
                    connection, _GATE_TABLE, stored.parent_request_id):
                raise NotFound(f"no gate request {stored.parent_request_id!r}")
            # The primary keys decide uniqueness: probing for the ids first would cost a query
            # per table on every decision for ids that are fresh uuid4s.
            try:
                connection.execute(_INSERT_GATE, [_gate_values(stored)])
            except IntegrityError as error:
                raise Conflict(f"gate request {record_id!r} already exists") from error
            if stored_contract is not None:
                try:
                    connection.execute(
                        _INSERT_CONTRACT, [_contract_values(stored_contract)])
                except IntegrityError as error:
                    raise Conflict(
                        f"contract {stored_contract.id!r} already exists") from error
        return stored, stored_contract

    def get_gate_record(self, request_id: str) -> GateRecord:
        """One gate record by id.

        Raises:
            NotFound: no such record.
        """
        with self._transaction("reading a gate record") as session:
            return _to_record(_gate_row(session, request_id))

    def list_child_records(self, request_id: str) -> list[GateRecord]:
        """Records linked to `request_id` as its answers or re-evaluations, oldest first."""
        with self._transaction("listing child gate records") as session:
            rows = session.scalars(
                select(GateRecordRow)
                .where(GateRecordRow.parent_request_id == request_id)
                .order_by(GateRecordRow.created_at, GateRecordRow.id)
            ).all()
            return [_to_record(row) for row in rows]

    def list_pending_library_extensions(self, limit: int = 100) -> list[GateRecord]:
        """Records deferred for `extend_library` that no later record answers yet, oldest first.

        Args:
            limit: at most this many records.
        """
        child = aliased(GateRecordRow)
        query = (
            select(GateRecordRow)
            .where(GateRecordRow.decision == Decision.DEFER.value)
            .where(GateRecordRow.defer_kind == DeferKind.EXTEND_LIBRARY.value)
            .where(~exists().where(child.parent_request_id == GateRecordRow.id))
            .order_by(GateRecordRow.created_at, GateRecordRow.id)
            .limit(limit)
        )
        with self._transaction("listing pending library extensions") as session:
            return [_to_record(row) for row in session.scalars(query).all()]

    def link_child_record(self, parent_id: str, child_id: str) -> GateRecord:
        """Record that `child_id` answers or re-evaluates `parent_id`.

        Returns:
            The child record, now linked.

        Raises:
            NotFound: either record does not exist.
            Conflict: the child is the parent, is already linked elsewhere, or is an ancestor
                of the parent (the chain would loop).
        """
        if parent_id == child_id:
            raise Conflict("a gate record cannot be its own parent")
        with self._transaction("linking gate records") as session:
            parent = _gate_row(session, parent_id)
            child = _gate_row(session, child_id)
            if child.parent_request_id not in (None, parent_id):
                raise Conflict(f"gate request {child_id!r} is already linked to another request")
            ancestor = parent
            while ancestor.parent_request_id is not None:
                if ancestor.parent_request_id == child_id:
                    raise Conflict("linking these gate records would make a loop")
                ancestor = _gate_row(session, ancestor.parent_request_id)
            child.parent_request_id = parent_id
            return _to_record(child)

    def mark_gate_record_downgraded(self, request_id: str, reason: str) -> GateRecord:
        """Mark an authorized request downgraded (its contract's attempts ran out).

        Raises:
            NotFound: no such record.
        """
        with self._transaction("downgrading a gate record") as session:
            row = _gate_row(session, request_id)
            row.downgraded = True
            row.downgrade_reason = reason
            return _to_record(row)
