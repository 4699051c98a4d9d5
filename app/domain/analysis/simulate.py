"""Simulation: every variant of the induced plan run on the request's world state.

In: the initial `WorldState` (the request's scene plus what the command named) and the
`Variant`s of the sketch. Out: one `Trace` per variant: the states s0..sN the action model's
effects lead to (unknown facts stay unknown), the steps between them, and a final `Finish`
(the end of the task, where what the plan leaves behind is judged). The same `world.step` that
`/verify` and the monitor use makes every transition. Fails: never; a step the action model
refuses in the state it is reached in (an id of the wrong kind) is skipped, and the trace says
which.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.domain.analysis.sketch import Planned, Variant
from app.domain.errors import PlanError
from app.domain.world import Action, WorldState, step

FINISH = Action("Finish")


@dataclass(frozen=True, slots=True)
class Trace:
    """One variant run: `states[i]` is before `steps[i]`, `states[i + 1]` after it."""

    variant: Variant
    states: tuple[WorldState, ...]
    steps: tuple[Planned, ...]
    skipped: tuple[str, ...] = ()

    @property
    def careful(self) -> bool:
        return self.variant.careful


def simulate(initial: WorldState, variants: list[Variant]) -> list[Trace]:
    """Run each variant from the initial state.

    Args:
        initial: the state the task starts in.
        variants: the plans to run.

    Returns:
        One trace per variant, each ending with a `Finish` step whose after-state is the last.
    """
    traces: list[Trace] = []
    for variant in variants:
        state = initial
        states = [initial]
        steps: list[Planned] = []
        skipped: list[str] = []
        for planned in variant.steps:
            try:
                state = step(state, planned.action)
            except PlanError as error:
                skipped.append(error.detail)
                continue
            states.append(state)
            steps.append(planned)
        clause = steps[-1].clause if steps else -1
        steps.append(Planned(FINISH, clause, "finish"))
        states.append(state)
        traces.append(Trace(variant, tuple(states), tuple(steps), tuple(skipped)))
    return traces
