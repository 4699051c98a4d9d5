"""Planning in the domain: from an authorized command to a plan that keeps its contract.

In: a gate request, its `WorldState`, the contract. Out: plans in the wire shape:
`SearchPlanner` (a search over the action model within the contract) and `reference_plan` (the
planner's plan, proved by Stage 5 before it is handed out). Nothing here imports the simulator;
the simulator plans through this package with its own `Dynamics`.
"""

from app.domain.planning.goals import CommandReader, Goal, GoalError, GoalLiteral, goal_for
from app.domain.planning.reference import ReferencePlan, reference_plan
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
    "Goal",
    "GoalError",
    "GoalLiteral",
    "PlanOutcome",
    "Planner",
    "PlanningTask",
    "ReferencePlan",
    "SearchPlanner",
    "goal_for",
    "reference_plan",
    "search",
]
