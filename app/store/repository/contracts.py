"""Queries on Task Safety Contracts and the verification attempts made against them.

In: `ContractRecord` and `VerificationAttemptRecord` values. Out: the same, as stored. Spending a
verification attempt is one conditional UPDATE, so two concurrent `/verify` calls can never both
take the last attempt.
Fails: `NotFound` for unknown ids, `AttemptsExhausted` when no attempt is left, `Conflict` for a
duplicate id, `Unavailable` for database errors.
"""

from __future__ import annotations

from sqlalchemy import select, update
from sqlalchemy.orm import Session

from app.domain.errors import AttemptsExhausted, Conflict, NotFound
from app.store.records import ContractRecord, ContractStatus, VerificationAttemptRecord
from app.store.repository._base import RepositoryBase
from app.store.tables import ContractRow, GateRecordRow, VerificationAttemptRow, new_id, utc_now


def to_contract_record(row: ContractRow) -> ContractRecord:
    return ContractRecord(
        id=row.id,
        request_id=row.request_id,
        contract=dict(row.contract),
        template_versions={str(k): int(v) for k, v in row.template_versions.items()},
        created_at=row.created_at,
        attempts_used=row.attempts_used,
        max_attempts=row.max_attempts,
        status=ContractStatus(row.status),
    )


def _to_attempt(row: VerificationAttemptRow) -> VerificationAttemptRecord:
    return VerificationAttemptRecord(
        id=row.id,
        contract_id=row.contract_id,
        plan=list(row.plan),
        ok=row.ok,
        violations=list(row.violations),
        created_at=row.created_at,
        duration_ms=row.duration_ms,
    )


def _contract_row(session: Session, contract_id: str) -> ContractRow:
    row = session.get(ContractRow, contract_id)
    if row is None:
        raise NotFound(f"no contract {contract_id!r}")
    return row


def insert_contract(session: Session, record: ContractRecord) -> ContractRow:
    """Add a contract in an open transaction and point its gate record at it."""
    gate = session.get(GateRecordRow, record.request_id)
    if gate is None:
        raise NotFound(f"no gate request {record.request_id!r}")
    if record.id is not None and session.get(ContractRow, record.id) is not None:
        raise Conflict(f"contract {record.id!r} already exists")
    row = ContractRow(
        id=record.id or new_id(),
        request_id=record.request_id,
        contract=dict(record.contract),
        template_versions=dict(record.template_versions),
        created_at=record.created_at or utc_now(),
        attempts_used=record.attempts_used,
        max_attempts=record.max_attempts,
        status=record.status.value,
    )
    session.add(row)
    session.flush()
    gate.contract_id = row.id
    return row


class ContractQueries(RepositoryBase):
    """Contracts, their attempt budget and their verification attempts."""

    def save_contract(self, record: ContractRecord) -> ContractRecord:
        """Store a contract and attach it to the gate record it was compiled for.

        Args:
            record: the contract; a missing id or created_at is filled in.

        Returns:
            The contract as stored.

        Raises:
            NotFound: the gate request does not exist.
            Conflict: a contract with this id already exists.
        """
        with self._transaction("saving a contract") as session:
            return to_contract_record(insert_contract(session, record))

    def get_contract(self, contract_id: str) -> ContractRecord:
        """One contract by id.

        Raises:
            NotFound: no such contract.
        """
        with self._transaction("reading a contract") as session:
            return to_contract_record(_contract_row(session, contract_id))

    def use_verification_attempt(self, contract_id: str) -> ContractRecord:
        """Spend one verification attempt, atomically.

        Returns:
            The contract with `attempts_used` already counting this attempt.

        Raises:
            NotFound: no such contract.
            AttemptsExhausted: the contract is exhausted or has no attempt left.
        """
        with self._transaction("using a verification attempt") as session:
            spent = session.execute(
                update(ContractRow)
                .where(ContractRow.id == contract_id)
                .where(ContractRow.status == ContractStatus.ACTIVE.value)
                .where(ContractRow.attempts_used < ContractRow.max_attempts)
                .values(attempts_used=ContractRow.attempts_used + 1)
                .execution_options(synchronize_session=False)
            )
            row = _contract_row(session, contract_id)
            if spent.rowcount != 1:  # type: ignore[attr-defined]
                raise AttemptsExhausted(
                    f"contract {contract_id!r} has used all {row.max_attempts} attempts",
                    attempts_used=row.attempts_used,
                    max_attempts=row.max_attempts,
                )
            session.refresh(row)
            return to_contract_record(row)

    def mark_contract_exhausted(self, contract_id: str) -> ContractRecord:
        """Close a contract to further verification.

        Raises:
            NotFound: no such contract.
        """
        with self._transaction("exhausting a contract") as session:
            row = _contract_row(session, contract_id)
            row.status = ContractStatus.EXHAUSTED.value
            return to_contract_record(row)

    def save_verification_attempt(
        self, record: VerificationAttemptRecord
    ) -> VerificationAttemptRecord:
        """Store the outcome of one verification.

        Raises:
            NotFound: the contract does not exist.
        """
        with self._transaction("saving a verification attempt") as session:
            _contract_row(session, record.contract_id)
            row = VerificationAttemptRow(
                id=record.id or new_id(),
                contract_id=record.contract_id,
                plan=list(record.plan),
                ok=record.ok,
                violations=list(record.violations),
                created_at=record.created_at or utc_now(),
                duration_ms=record.duration_ms,
            )
            session.add(row)
            session.flush()
            return _to_attempt(row)

    def list_verification_attempts(self, contract_id: str) -> list[VerificationAttemptRecord]:
        """A contract's verification attempts, oldest first (empty for an unknown contract)."""
        with self._transaction("listing verification attempts") as session:
            rows = session.scalars(
                select(VerificationAttemptRow)
                .where(VerificationAttemptRow.contract_id == contract_id)
                .order_by(VerificationAttemptRow.created_at, VerificationAttemptRow.id)
            ).all()
            return [_to_attempt(row) for row in rows]
