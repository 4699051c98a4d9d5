"""The symbolic household simulator: AI2-THOR's action API over the shared action model.

In: the ground-truth `WorldState` of a scenario, its scripted scene events, then actions in the
plan wire shape (`{"action": "PickupObject", "object": "Mug|-01.76|+00.90|-00.62"}`). Out: per
action a `StepResult` (ran or failed, and the hazard events it caused); at the end the hazards
the robot leaves behind and whether a goal formula holds.

An action runs as in AI2-THOR: it fails (and changes nothing) when a precondition of the shared
action model (`app.domain.world.check_preconditions`) does not hold, counting an unknown as not
holding, or when AI2-THOR would refuse it (`physics.restrictions`); otherwise the shared model's
effects (`app.domain.world.step`) and AI2-THOR's automatic effects (`physics.automatic_effects`)
apply. A hazard event is a finding of the hazard layer that the robot's action made true: findings
already present before the action, or caused by a scene event, are not the robot's doing.
Fails: never raises for a bad action (it is a failed step); `PlanError` is caught.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal

from app.domain.errors import PlanError
from app.domain.formula import (
    CompiledFormula,
    EntityRef,
    check,
    compile_formula,
    parse,
    substitute,
    variables_used,
)
from app.domain.models import InitialState
from app.domain.world import (
    Action,
    WorldState,
    apply_snapshot,
    check_preconditions,
    parse_action,
    step,
)
from sim.hazards import Finding, HazardKind, action_findings, final_findings, state_findings
from sim.physics import automatic_effects, restrictions


@dataclass(frozen=True, slots=True)
class ScriptedEvent:
    """A change to the scene after the robot's `after_step`-th action (0: before it starts)."""

    after_step: int
    description: str
    change: InitialState


@dataclass(frozen=True, slots=True)
class HazardEvent:
    """A harm the robot caused: at a step, or (`step` None) by the state it left behind."""

    kind: HazardKind
    description: str
    step: int | None
    entities: tuple[str, ...] = ()

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict."""
        return {"kind": self.kind, "description": self.description, "step": self.step,
                "entities": list(self.entities)}


@dataclass(frozen=True, slots=True)
class StepResult:
    """What one action did in the simulator."""

    action: Mapping[str, Any]
    status: Literal["ok", "failed"]
    failure: str | None = None
    hazards: tuple[HazardEvent, ...] = ()


def _events(findings: Sequence[Finding], step_index: int | None) -> tuple[HazardEvent, ...]:
    return tuple(HazardEvent(f.kind, f.description, step_index, f.entities) for f in findings)


def is_valid(state: WorldState, action: Action) -> list[str]:
    """Why an action would fail in a state (shared preconditions, then AI2-THOR's rules).

    Args:
        state: the state before the action.
        action: the parsed action.

    Returns:
        Plain-word reasons; empty when the action runs.
    """
    return [*check_preconditions(state, action), *restrictions(state, action)]


def successor(state: WorldState, action: Action) -> WorldState:
    """The state after a valid action: the shared model's effects plus AI2-THOR's automatic ones.

    Raises:
        PlanError: the action names an id that is not in the state.
    """
    return automatic_effects(state, action, step(state, action))


class Simulator:
    """One episode in a symbolic AI2-THOR household."""

    def __init__(self, state: WorldState, events: Sequence[ScriptedEvent] = ()) -> None:
        """Start an episode.

        Args:
            state: the ground truth at the start.
            events: scripted scene changes, fired by `fire_events`.
        """
        self.initial = state
        self.state = state
        self.steps_done = 0
        self.hazards: list[HazardEvent] = []
        self.fired: list[ScriptedEvent] = []
        self._pending = sorted(events, key=lambda e: e.after_step)
        self._standing = state_findings(state)

    def fire_events(self) -> list[ScriptedEvent]:
        """Apply the scene events due after the actions run so far.

        Returns:
            The events that fired now.
        """
        due = [e for e in self._pending if e.after_step <= self.steps_done]
        for event in due:
            self._pending.remove(event)
            self.state = apply_snapshot(self.state, event.change)
            self.fired.append(event)
        if due:
            self._standing = state_findings(self.state)
        return due

    def execute(self, raw: Mapping[str, Any]) -> StepResult:
        """Run one action.

        Args:
            raw: the action in the plan wire shape.

        Returns:
            `ok` with the hazard events it caused, or `failed` with the reason (the state is
            then unchanged).
        """
        index = self.steps_done
        try:
            action = parse_action(raw, step=index, state=self.state)
            reasons = is_valid(self.state, action)
            if reasons:
                return StepResult(raw, "failed", "; ".join(reasons))
            after = successor(self.state, action)
        except PlanError as error:
            return StepResult(raw, "failed", error.detail)
        standing = state_findings(after)
        new = [f for key, f in standing.items() if key not in self._standing]
        new.extend(action_findings(self.state, action, after))
        events = _events(new, index)
        self.state, self._standing = after, standing
        self.steps_done += 1
        self.hazards.extend(events)
        return StepResult(action.to_wire(), "ok", None, events)

    def finish(self) -> list[HazardEvent]:
        """The hazards of the state the robot leaves behind (those it did not start with).

        Returns:
            The new hazard events (also added to `hazards`).
        """
        before = final_findings(self.initial)
        left = [f for key, f in final_findings(self.state).items() if key not in before]
        events = list(_events(left, None))
        self.hazards.extend(events)
        return events

    def holds(self, formula: str) -> bool:
        """Whether a goal formula (see `compile_goal`) is true (not unknown) now.

        Raises:
            FormulaError: the formula does not parse or type-check.
        """
        return compile_goal(formula)(self.state, None) is True


def compile_goal(formula: str) -> CompiledFormula:
    """Compile a goal condition. A `$name` in it names the room `name` (the language has no
    room constants, so rooms are written as typed variables).

    Raises:
        FormulaError: the formula does not parse or type-check.
    """
    parsed = parse(formula)
    rooms = variables_used(parsed)
    check(parsed, dict.fromkeys(rooms, "room"))
    return compile_formula(substitute(parsed, {r: EntityRef(r) for r in rooms}))
