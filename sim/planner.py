"""The simulator's planner: the domain's search planner (`app.domain.planning`) stepping
AI2-THOR's rules on top of the shared action model.

In: a `PlanningTask`. Out: a `PlanOutcome`. `Ai2ThorDynamics` refuses what AI2-THOR refuses
(`sim.physics.restrictions`, with the shared preconditions) and applies its automatic effects, so
a plan found here also runs in the simulator. Fails: never raises for a goal it cannot reach.
"""

from __future__ import annotations

from app.domain.planning import (
    MAX_EXPANSIONS,
    Planner,
    PlanningTask,
    PlanOutcome,
    SearchPlanner,
)
from app.domain.world import Action, WorldState
from sim.simulator import is_valid, successor

__all__ = ["Ai2ThorDynamics", "PlanOutcome", "Planner", "PlanningTask", "SimPlanner"]


class Ai2ThorDynamics:
    """The shared action model plus AI2-THOR's refusals and automatic effects."""

    def refusals(self, state: WorldState, action: Action) -> list[str]:
        """Why the simulator would refuse the action."""
        return is_valid(state, action)

    def successor(self, state: WorldState, action: Action) -> WorldState:
        """The state after the action, AI2-THOR's automatic effects included."""
        return successor(state, action)


class SimPlanner(SearchPlanner):
    """The domain's search planner over the simulator's dynamics."""

    def __init__(self, *, max_expansions: int = MAX_EXPANSIONS) -> None:
        super().__init__(max_expansions=max_expansions, dynamics=Ai2ThorDynamics())
