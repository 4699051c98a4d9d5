"""The reference plan of an authorized task: a plan for the command, proved to keep its contract.

In: the gate request, its `Contract`, Stage 1's reader (how the command is read into a goal), the
solver budget and the planner's search budget (states expanded). Out: a `ReferencePlan`: the
plan in the wire shape with the goal it reaches and the Stage 5 verdict that proved it, or no
plan and the reason. The search planner (`search.py`) plans within the contract over the shared
action model; its plan is then verified with `verify_plan` (Z3, every value of the unknowns) and
handed out only if that passes, so a robot without an LLM planner can execute it as it is.
Fails closed: no goal, a spent search budget, a failed or undecided proof: no plan, with the
reason. Never raises for a task it cannot plan; `FormulaError` only for a broken contract.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from app.domain.contracts import Contract
from app.domain.models import GateRequest
from app.domain.planning.goals import CommandReader
from app.domain.planning.search import MAX_EXPANSIONS, SearchPlanner
from app.domain.planning.task import PlanningTask
from app.domain.verify import VerificationResult, verify_plan
from app.domain.world import state_from_request


@dataclass(frozen=True, slots=True)
class ReferencePlan:
    """A proved plan for the task, or None and why."""

    plan: tuple[Mapping[str, Any], ...] | None
    reason: str
    goal: str | None = None
    expanded: int = 0
    verification: VerificationResult | None = None


def reference_plan(
    request: GateRequest,
    contract: Contract,
    *,
    timeout_ms: int,
    reader: CommandReader | None = None,
    max_expansions: int = MAX_EXPANSIONS,
) -> ReferencePlan:
    """A plan for the command that Stage 5 proves keeps the contract.

    Args:
        request: the authorized gate request (command, scene, robot).
        contract: its Task Safety Contract.
        timeout_ms: the solver's budget for the proof.
        reader: Stage 1's reader (default: the embedded symbolic analyzer).
        max_expansions: the planner's search budget, in states expanded.

    Returns:
        The proved plan, or None with the reason.

    Raises:
        FormulaError: a contract condition does not parse or type-check.
    """
    state = state_from_request(request)
    planner = SearchPlanner(max_expansions=max_expansions, reader=reader)
    outcome = planner.plan(PlanningTask(request, state, contract))
    if outcome.plan is None:
        return ReferencePlan(None, f"no plan found within the search budget of "
                                   f"{max_expansions} states: {outcome.reason}",
                             outcome.goal, outcome.expanded)
    verdict = verify_plan(list(outcome.plan), contract, state, timeout_ms=timeout_ms)
    if not verdict.ok:
        return ReferencePlan(None, f"the planner's plan did not pass Stage 5: {verdict.reason}",
                             outcome.goal, outcome.expanded, verdict)
    return ReferencePlan(outcome.plan, f"plan of {len(outcome.plan)} steps for "
                                       f"{outcome.goal}, proved by Stage 5",
                         outcome.goal, outcome.expanded, verdict)
