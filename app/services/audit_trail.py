"""Reading the audit trail: a decision's record with what followed it, and a stored contract.

In: a gate request id or a contract id. Out: `AuditEntry` (the stored record and the ids of the
decisions that followed it: answers, re-evaluations) and contracts parsed back into the domain
model. Fails: `NotFound` (404) for an unknown id, `Unavailable` (503) for database errors.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.domain.contracts import Contract
from app.store.records import ContractRecord, GateRecord
from app.store.repository import AuditRepository, ContractRepository


@dataclass(frozen=True)
class AuditEntry:
    """A stored decision and the ids of the decisions that followed it, oldest first."""

    record: GateRecord
    followed_by: tuple[str, ...]


class AuditTrail:
    """Read access to decisions and contracts."""

    def __init__(self, *, audit: AuditRepository, contracts: ContractRepository) -> None:
        self._audit = audit
        self._contracts = contracts

    def entry(self, request_id: str) -> AuditEntry:
        """A stored decision with the decisions that followed it (answers, re-evaluations)."""
        record = self._audit.get_gate_record(request_id)
        children = self._audit.list_child_records(request_id)
        return AuditEntry(record, tuple(str(child.id) for child in children))

    def contract(self, contract_id: str) -> tuple[Contract, ContractRecord]:
        """A stored contract, parsed back into the domain model, with its record."""
        stored = self._contracts.get_contract(contract_id)
        return Contract.model_validate(stored.contract), stored
