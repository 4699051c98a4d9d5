"""API models of POST /verify (`shared/spec/plans-and-monitoring.md`) and the mapping to them.

In: the request body; out: the response built from `services.verification.Verified`. Plan steps
are taken as any JSON value so a malformed step is reported by the domain with its index
(`plan[3]`, `plan[3].object`) rather than as a generic shape error. Fields are only added
(`repair` and `repair_reason` for a failed plan, issue 17).
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.api.examples import VERIFY_EXAMPLE
from app.config import PLAN_STEPS_CAP
from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, InitialState
from app.domain.verify import Undecided, Violation
from app.services.verification import Verified

MAX_PLAN_STEPS = PLAN_STEPS_CAP
MAX_INLINE_CONDITIONS = 500


class InlineCondition(BaseModel):
    """A condition of an inline contract: its formula over entity constants (`#mug_1`)."""

    model_config = ConfigDict(extra="forbid")

    id: str = Field(min_length=1, max_length=200)
    formula: str = Field(min_length=1, max_length=4000)
    description: str = ""
    action: str | None = None


class InlineContract(BaseModel):
    """A contract given in the request instead of by id (no attempt budget, no audit trail)."""

    model_config = ConfigDict(extra="forbid")

    invariants: list[InlineCondition] = Field(default_factory=list,
                                              max_length=MAX_INLINE_CONDITIONS)
    guards: list[InlineCondition] = Field(default_factory=list, max_length=MAX_INLINE_CONDITIONS)
    aborts: list[InlineCondition] = Field(default_factory=list, max_length=MAX_INLINE_CONDITIONS)

    def to_domain(self) -> Contract:
        """The domain contract, each condition marked as coming from this request."""
        def conditions(items: list[InlineCondition], kind: ConditionKind
                       ) -> tuple[ContractCondition, ...]:
            return tuple(ContractCondition(
                id=c.id, kind=kind, formula=c.formula, description=c.description or c.id,
                action=c.action, template_id="inline", template_version=1, bindings={})
                for c in items)

        return Contract(invariants=conditions(self.invariants, ConditionKind.INVARIANT),
                        guards=conditions(self.guards, ConditionKind.GUARD),
                        aborts=conditions(self.aborts, ConditionKind.ABORT))


# Exactly one of `contract_id` and `contract` (the service says so with a 422 naming `body`).
_ONE_CONTRACT: dict[str, Any] = {"oneOf": [
    {"required": ["contract_id"],
     "properties": {"contract_id": {"type": "string"}, "contract": {"type": "null"}}},
    {"required": ["contract"],
     "properties": {"contract": {"type": "object"}, "contract_id": {"type": "null"}}},
]}
_PLAN_STEP: dict[str, Any] = {
    "type": "object", "required": ["action"], "additionalProperties": True,
    "description": "An action of the action model (`GET /vocabulary`); `object`, `target` and "
                   "the rest depend on the action.",
    "properties": {"action": {"type": "string", "examples": ["PickupObject", "navigate"]},
                   "object": {"type": "string"}, "target": {"type": "string"}},
}


class VerifyRequest(BaseModel):
    """What a planner POSTs to /verify: a plan and the contract it must keep (by id, or inline).
    """

    model_config = ConfigDict(json_schema_extra={**_ONE_CONTRACT, "examples": [VERIFY_EXAMPLE]})

    contract_id: str | None = Field(default=None, min_length=1, max_length=200)
    contract: InlineContract | None = None
    plan: list[Any] = Field(max_length=MAX_PLAN_STEPS, json_schema_extra={"items": _PLAN_STEP})
    initial_state: InitialState | None = Field(
        default=None, description="The scene and robot before the first step; default: the "
                                  "gate request's.")


class ViolationOut(BaseModel):
    """One violation (or, with `detail`, an instance the solver could not decide)."""

    step: int = Field(description="The plan step (from 0) where it happens.")
    state: int
    action: dict[str, Any] | None
    kind: Literal["invariant", "guard", "abort", "precondition", "scope"]
    condition_id: str
    formula: str
    description: str
    counterexample: dict[str, Any] = Field(default_factory=dict)
    free: list[str] = Field(default_factory=list)
    detail: str | None = None
    quote: str | None = None
    """For kind `scope`: the words of the command the step departs from."""


class RepairEditOut(BaseModel):
    """One edit of a repair: its kind, the step of the sent plan it changes, what it does."""

    kind: str
    step: int
    description: str


class RepairOut(BaseModel):
    """The nearest plan that passes, proved by Stage 5 before it is answered."""

    plan: list[dict[str, Any]]
    edits: list[RepairEditOut]
    reason: str
    candidates_screened: int
    proofs: int
    duration_ms: float = 0.0


class VerifyResponse(BaseModel):
    """The verdict: 200 whether or not the plan passes."""

    ok: bool
    violations: list[ViolationOut]
    undecided: list[ViolationOut] = Field(default_factory=list)
    reason: str | None = None
    attempts: int
    attempts_left: int | None
    decision: Literal["authorize", "reject"] | None = Field(
        description="The gate decision as it stands after this verification (`reject` once "
                    "the attempts are used up).")
    downgraded: bool = False
    contract_id: str | None = None
    states_checked: int = 0
    duration_ms: float = 0.0
    repair: RepairOut | None = None
    """A failed plan's nearest plan that passes (fewest edits), proved by Stage 5; else null."""
    repair_reason: str | None = None
    """Why `repair` is null for a failed plan (the search budget, a rejected task...)."""


def _out(item: Violation | Undecided) -> ViolationOut:
    return ViolationOut(
        step=item.step, state=item.state,
        action=None if item.action is None else dict(item.action),
        kind=item.kind.value, condition_id=item.condition_id, formula=item.formula,
        description=item.description,
        counterexample=dict(item.counterexample) if isinstance(item, Violation) else {},
        free=list(item.free) if isinstance(item, Violation) else [],
        detail=item.detail if isinstance(item, Undecided) else None,
        quote=item.quote if isinstance(item, Violation) else None,
    )


def _repair(verified: Verified) -> tuple[RepairOut | None, str | None]:
    repair = verified.repair
    if repair is None:
        return None, None
    if repair.plan is None:
        return None, repair.reason
    return RepairOut(
        plan=[dict(step) for step in repair.plan],
        edits=[RepairEditOut(kind=e.kind, step=e.step, description=e.description)
               for e in repair.edits],
        reason=repair.reason, candidates_screened=repair.screened, proofs=repair.proofs,
        duration_ms=verified.repair_ms), None


def verify_response(verified: Verified) -> VerifyResponse:
    """The response for a verification."""
    result = verified.result
    repair, repair_reason = _repair(verified)
    return VerifyResponse(
        ok=result.ok,
        violations=[_out(v) for v in result.violations],
        undecided=[_out(u) for u in result.undecided],
        reason=result.reason,
        attempts=verified.attempts,
        attempts_left=verified.attempts_left,
        decision=None if verified.decision is None else verified.decision.value,
        downgraded=verified.downgraded,
        contract_id=verified.contract_id,
        states_checked=result.states_checked,
        duration_ms=verified.duration_ms,
        repair=repair,
        repair_reason=repair_reason,
    )
