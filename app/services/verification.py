"""The verification use case: check a plan against a stored (or inline) contract, spend repair
attempts on failures, and downgrade the gate decision when they run out.

In: a plan, a contract id or an inline `Contract`, and optionally an initial state (default: the
state of the gate request the stored contract came from). Out: `Verified`: the domain verdict,
the attempts used and left, and the gate decision that now stands (`authorize`, or `reject` once
the k-th failure downgraded it; None for an inline contract, which has no gate request).
Each failed verification of a stored contract spends one attempt atomically before it is
answered; the k-th failure marks the contract exhausted and the gate record downgraded, with the
reason, in the audit trail. A passing plan spends nothing. Every verification is recorded.
A failed plan also gets a repair (`app.domain.planning.repair_plan`): the nearest plan Stage 5
proves, or None with the reason; none is searched for once the task has been rejected (the
attempt that downgraded it, or an initial state that already breaks the contract).
Fails: `NotFound` (no such contract), `AttemptsExhausted` (the contract is exhausted: 409),
`InvalidInput` (bad plan or formula, or an inline contract without an initial state),
`Unavailable` (database).
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, replace
from typing import Any

from app.adapters.tracing import stages
from app.domain.contracts import Contract
from app.domain.errors import AttemptsExhausted, InvalidInput
from app.domain.gate import Decision
from app.domain.models import GateRequest, InitialState
from app.domain.planning import Repair, repair_plan
from app.domain.verify import Undecided, VerificationResult, Violation, verify_plan
from app.metrics import Metrics
from app.services.input_limits import MODEL_CAPS, InputLimits
from app.store.records import ContractRecord, ContractStatus, VerificationAttemptRecord
from app.store.repository import AuditRepository, ContractRepository


@dataclass(frozen=True)
class Verified:
    """A verification's verdict and what it did to the contract's budget and the decision."""

    result: VerificationResult
    contract_id: str | None
    attempts: int
    attempts_left: int | None
    decision: Decision | None
    downgraded: bool
    duration_ms: float
    repair: Repair | None = None
    """For a failed plan: the nearest plan that passes, or why there is none."""
    repair_ms: float = 0.0


def _traced_verify(plan: Sequence[object], contract: Contract,
                   start: GateRequest | InitialState, timeout_ms: int,
                   contract_id: str | None) -> VerificationResult:
    """Stage 5, as one stage span when tracing is on."""
    with stages.stage("safegate.stage5.verify",
                      **{"safegate.contract_id": contract_id or "inline"}) as found:
        result = verify_plan(plan, contract, start, timeout_ms=timeout_ms)
        found["safegate.verified"] = result.ok
        found["safegate.violations"] = len(result.violations)
        found["safegate.undecided"] = len(result.undecided)
    stages.annotate_request(**{"safegate.verified": result.ok})
    return result


class VerificationService:
    """Stage 5 with the contracts' attempt budgets and the audit trail."""

    def __init__(self, *, contracts: ContractRepository, audit: AuditRepository,
                 metrics: Metrics, solver_timeout_ms: int,
                 limits: InputLimits = MODEL_CAPS) -> None:
        """Args:
            contracts: the stored contracts and their budgets.
            audit: the gate records a contract came from (its start state; downgrades).
            metrics: where verifications are counted.
            solver_timeout_ms: Z3's budget per check.
            limits: the most steps a plan, and the most items a scene list, may have.
        """
        self._limits = limits
        self._contracts = contracts
        self._audit = audit
        self._metrics = metrics
        self._timeout_ms = solver_timeout_ms

    def verify(
        self,
        plan: Sequence[object],
        *,
        contract_id: str | None = None,
        contract: Contract | None = None,
        initial_state: InitialState | None = None,
    ) -> Verified:
        """Verify a plan and keep the attempt budget and the audit trail.

        Args:
            plan: the steps as sent.
            contract_id: a stored contract (mutually exclusive with `contract`).
            contract: an inline contract, verified without budget or audit trail.
            initial_state: the starting state; default the stored contract's gate request.

        Returns:
            The verdict with attempts used/left and the standing decision.

        Raises:
            AttemptsExhausted: the stored contract has no attempt left.
            NotFound: no such contract.
            InvalidInput: neither or both of `contract_id` and `contract`; an inline contract
                without an initial state; a bad plan step or condition.
        """
        self._limits.check_plan(plan)
        self._limits.check_initial_state(initial_state)
        if (contract_id is None) == (contract is None):
            raise InvalidInput("give exactly one of contract_id and contract", field="body")
        timeout_ms = self._timeout_ms
        if contract is not None:
            if initial_state is None:
                raise InvalidInput("an inline contract needs an initial_state",
                                   field="body.initial_state")
            started = time.perf_counter()
            result = _traced_verify(plan, contract, initial_state, timeout_ms, None)
            duration_ms = _since(started)
            self._count(result)
            verified = Verified(result, None, 0, None, None, False, duration_ms)
            return _with_repair(verified, plan, contract, initial_state, timeout_ms)
        assert contract_id is not None
        stored = self._contracts.get_contract(contract_id)
        if stored.status is ContractStatus.EXHAUSTED or stored.attempts_left == 0:
            raise AttemptsExhausted(
                f"contract {contract_id!r} has used all {stored.max_attempts} verification "
                "attempts; the task was rejected",
                attempts_used=stored.attempts_used, max_attempts=stored.max_attempts)
        start: GateRequest | InitialState = (
            initial_state if initial_state is not None
            else self._audit.get_gate_record(stored.request_id).request)
        started = time.perf_counter()
        domain_contract = Contract.model_validate(stored.contract)
        result = _traced_verify(plan, domain_contract, start, timeout_ms, contract_id)
        duration_ms = _since(started)
        self._count(result)
        if not result.ok:
            stored = self._contracts.use_verification_attempt(contract_id)
        self._contracts.save_verification_attempt(VerificationAttemptRecord(
            contract_id=contract_id, plan=list(plan), ok=result.ok,
            violations=[*map(_violation_json, result.violations),
                        *map(_violation_json, result.undecided)],
            duration_ms=duration_ms))
        downgraded = False
        if not result.ok and stored.attempts_left == 0:
            self._downgrade(stored, result)
            downgraded = True
        verified = Verified(result, contract_id, stored.attempts_used, stored.attempts_left,
                            Decision.REJECT if downgraded else Decision.AUTHORIZE, downgraded,
                            duration_ms)
        return _with_repair(verified, plan, domain_contract, start, timeout_ms)

    def _downgrade(self, stored: ContractRecord, result: VerificationResult) -> None:
        assert stored.id is not None
        reason = (f"plan verification failed {stored.attempts_used} of {stored.max_attempts} "
                  f"allowed times (last: {result.reason}); decision downgraded to reject")
        self._contracts.mark_contract_exhausted(stored.id)
        self._audit.mark_gate_record_downgraded(stored.request_id, reason)

    def _count(self, result: VerificationResult) -> None:
        self._metrics.verifications.labels(outcome_of(result)).inc()


def _with_repair(verified: Verified, plan: Sequence[object], contract: Contract,
                 start: GateRequest | InitialState, timeout_ms: int) -> Verified:
    """A failed verification with its repair; a passed one, or a rejected task, as it is."""
    if verified.result.ok:
        return verified
    if verified.downgraded:
        repair = Repair(None, (), "no repair: the task was rejected (no attempts left)", 0, 0)
        return replace(verified, repair=repair)
    started = time.perf_counter()
    # verify_plan has already refused any step that is not an object.
    steps = [step for step in plan if isinstance(step, Mapping)]
    repair = repair_plan(steps, contract, start, timeout_ms=timeout_ms,
                         failed=verified.result)
    return replace(verified, repair=repair, repair_ms=_since(started))


def _violation_json(item: Violation | Undecided) -> dict[str, Any]:
    body: dict[str, Any] = asdict(item)
    body["kind"] = item.kind.value
    return body


def outcome_of(result: VerificationResult) -> str:
    """The verification's outcome as counted in metrics: `ok`, `violation` or `undecided`
    (failed only because the solver could not decide some check)."""
    if result.ok:
        return "ok"
    return "violation" if result.violations else "undecided"


def _since(started: float) -> float:
    return round((time.perf_counter() - started) * 1000, 3)
