"""Planning in the domain: from an authorized command to a plan that keeps its contract.

In: a gate request, its `WorldState`, the contract. Out: plans in the wire shape:
`SearchPlanner` (a search over the action model within the contract), `reference_plan` (the
planner's plan, proved by Stage 5 before it is handed out) and `repair_plan` (the nearest plan
to a failing one that Stage 5 proves). Nothing here imports the simulator; the simulator plans
through this package with its own `Dynamics`.
"""

from app.domain.planning.goals import CommandReader, Goal, GoalError, GoalLiteral, goal_for
from app.domain.planning.reference import ReferencePlan, reference_plan
from app.domain.planning.repair import Edit, Repair, RepairBudget, repair_plan
from app.domain.planning.search import CAUTIOUS_SPEED, MAX_EXPANSIONS, SearchPlanner, search
from app.domain.planning.task import (
    ActionModel,
    Dynamics,
    Planner,
    PlanningTask,
    PlanOutcome,
)

__all__ = [
    "CAUTIOUS_SPEED",
    "MAX_EXPANSIONS",
    "ActionModel",
    "CommandReader",
    "Dynamics",
    "Edit",
    "Goal",
    "GoalError",
    "GoalLiteral",
    "PlanOutcome",
    "Planner",
    "PlanningTask",
    "ReferencePlan",
    "Repair",
    "RepairBudget",
    "SearchPlanner",
    "goal_for",
    "reference_plan",
    "repair_plan",
    "search",
]
