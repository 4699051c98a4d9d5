"""What planning takes and gives: the task, the outcome, the planner and the dynamics it steps.

In: a gate request, its `WorldState` and (if authorized) the contract. Out: a plan in the wire
shape, or None with the reason. `Dynamics` says how actions run: `ActionModel` is the shared
action model that Stages 5 and 6 assume; the simulator brings AI2-THOR's own rules on top.
Fails: nothing here raises.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from app.domain.contracts import Contract
from app.domain.models import GateRequest
from app.domain.world import Action, WorldState, check_preconditions, step


@dataclass(frozen=True)
class PlanningTask:
    """What a planner is given."""

    request: GateRequest
    state: WorldState
    contract: Contract | None = None
    feedback: tuple[str, ...] = ()


@dataclass(frozen=True)
class PlanOutcome:
    """A plan, or None and why; `goal` is the goal the planner searched for, if it had one."""

    plan: tuple[Mapping[str, Any], ...] | None
    reason: str
    goal: str | None = None
    expanded: int = 0


class Dynamics(Protocol):
    """How actions run: why one would be refused in a state, and the state after it."""

    def refusals(self, state: WorldState, action: Action) -> list[str]:
        """Why the action would not run (empty when it runs)."""
        ...

    def successor(self, state: WorldState, action: Action) -> WorldState:
        """The state after an action that runs."""
        ...


class ActionModel:
    """The shared action model alone: the dynamics Stages 5 and 6 assume."""

    def refusals(self, state: WorldState, action: Action) -> list[str]:
        """The preconditions that do not hold (an unknown one counts as not holding)."""
        return check_preconditions(state, action)

    def successor(self, state: WorldState, action: Action) -> WorldState:
        """The shared model's effects."""
        return step(state, action)


FINISH_ARGS: dict[str, str | None] = {"object": None, "target": None}


class Planner(Protocol):
    """Anything that turns a task into a plan (the search planner, the LLM planner...)."""

    name: str

    def plan(self, task: PlanningTask) -> PlanOutcome:
        """Plan the task, or say why not."""
        ...
