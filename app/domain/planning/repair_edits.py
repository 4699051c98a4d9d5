"""The edits a repair may make to a failing plan, proposed where the plan first fails.

In: the plan, the screen's `Failure` and `Trace` (the states before each step), the initial state.
Out: `Candidate`s: an `Edit` (kind, step, description) and the edited plan, with how many steps of
the old trace still stand (everything before the first changed step). The kinds:
- `slow_down`: a move at or before the failing step at a cautious speed (that move alone, or
  every move from it on);
- `replace_throw`: a throw or drop replaced by putting the thing on a receptacle at hand, or by
  handing it over when it was thrown at a person (with the approach it needs);
- `insert_switch_off`: before the failing step (or at the end), switch off what the plan switched
  on (the appliance, or the knob that controls it);
- `insert_put_away`: before the failing step (or at the end), put what the robot holds back where
  it was at the start;
- `insert_approach`: go to what a step needs to be near first (a failed precondition);
- `reorder`: the failing step swapped with its neighbour;
- `drop`: the failing step removed (a step outside the task's scope, a pickup aside).
Edited steps are written in canonical names; untouched steps stay as sent.
Fails: never.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from app.domain.errors import PlanError
from app.domain.planning.screen import Failure, Trace
from app.domain.planning.search import APPROACH_STANDOFF_M, CAUTIOUS_SPEED
from app.domain.world import Action, WorldState, canonical_action, parse_action

Step = Mapping[str, Any]
MOVES = ("GoToObject", "navigate")
RELEASES = ("ThrowObject", "DropHandObject")
HELD_ACTIONS = ("PutObject", "HandOver", "Pour")
MAX_RECEPTACLES = 3
"""Receptacles in the room tried in place of a throw (sorted by id)."""


@dataclass(frozen=True, slots=True)
class Edit:
    """One change to the plan: its kind, the step of the plan it changes, and what it does."""

    kind: str
    step: int
    description: str


@dataclass(frozen=True, slots=True)
class Candidate:
    """An edited plan; `keep` steps of the old trace are unchanged."""

    edit: Edit
    plan: tuple[Step, ...]
    keep: int


def _name(raw: Step) -> str | None:
    name = raw.get("action")
    return canonical_action(name) if isinstance(name, str) else None


def _slow(raw: Step) -> Step | None:
    speed = raw.get("speed")
    if isinstance(speed, int | float) and not isinstance(speed, bool) and (
            speed <= CAUTIOUS_SPEED):
        return None
    return {**raw, "speed": CAUTIOUS_SPEED}


def _approach(state: WorldState, target: str) -> list[Step]:
    """The move to `target` unless the robot is already beside it."""
    if state.robot.beside == target:
        return []
    standoff = {"standoff": APPROACH_STANDOFF_M} if target in state.people else {}
    return [{"action": "GoToObject", "object": target, "speed": CAUTIOUS_SPEED, **standoff}]


class EditProposer:
    """Proposes the edits for one failure of one plan."""

    def __init__(self, plan: Sequence[Step], failure: Failure, trace: Trace,
                 initial: WorldState, *, task_targets: frozenset[str] = frozenset()) -> None:
        self.plan = tuple(plan)
        self.task_targets = task_targets
        """What the task's scope names as targets: tried first in place of a throw."""
        self.failure = failure
        self.trace = trace
        self.initial = initial
        at = failure.step if failure.phase in ("before", "after") else len(self.plan)
        self.at = min(at, len(trace.states) - 1)
        self.state = trace.states[self.at]
        """The state before the failing step (at the end: the last state)."""

    def candidates(self) -> Iterator[Candidate]:
        """Every edit worth screening for this failure, the cheapest kinds first."""
        phase, step = self.failure.phase, self.failure.step
        if phase == "aside":
            yield self._drop(step, "it picks up something outside the task")
            return
        if phase in ("before", "after"):
            yield from self._replace_release()
            if self.failure.condition == "precondition":
                yield from self._approaches()
        yield from self._slow_downs()
        yield from self._switch_offs()
        yield from self._put_away()
        if phase in ("before", "after"):
            yield from self._reorders()
            yield self._drop(step, f"it breaks {self.failure.condition}")

    def _edited(self, kind: str, step: int, description: str, start: int, end: int,
                steps: Sequence[Step]) -> Candidate:
        plan = (*self.plan[:start], *steps, *self.plan[end:])
        return Candidate(Edit(kind, step, description), plan, start)

    def _action(self, index: int) -> Action | None:
        """The step parsed (the failing one is not in the trace when it failed before)."""
        if index < len(self.trace.actions):
            return self.trace.actions[index]
        try:
            return parse_action(self.plan[index], step=index, state=self.state)
        except PlanError:
            return None

    def _slow_downs(self) -> Iterator[Candidate]:
        last = self.failure.step if self.failure.phase != "end" else len(self.plan) - 1
        moves = [i for i in range(min(last, len(self.plan) - 1), -1, -1)
                 if _name(self.plan[i]) in MOVES and _slow(self.plan[i]) is not None]
        if not moves:
            return
        first = moves[0]
        slowed = _slow(self.plan[first])
        assert slowed is not None
        yield self._edited("slow_down", first, f"move at {CAUTIOUS_SPEED} m/s at step {first}",
                           first, first + 1, [slowed])
        later = [_slow(s) or s if _name(s) in MOVES else s for s in self.plan[first:]]
        if sum(a is not b for a, b in zip(later, self.plan[first:], strict=True)) > 1:
            yield self._edited("slow_down", first,
                               f"every move from step {first} on at {CAUTIOUS_SPEED} m/s",
                               first, len(self.plan), later)

    def _replace_release(self) -> Iterator[Candidate]:
        step = self.failure.step
        action = self._action(step)
        if action is None or action.name not in RELEASES:
            return
        held = action.object or self.state.robot.holding
        if held is None:
            return
        if action.target is not None and action.target in self.state.people:
            yield self._edited("replace_throw", step,
                               f"hand {held} to {action.target} instead of {action.name}",
                               step, step + 1, [*_approach(self.state, action.target),
                                                {"action": "HandOver", "object": held,
                                                 "target": action.target}])
        for receptacle in self._receptacles(held):
            yield self._edited("replace_throw", step,
                               f"put {held} on {receptacle} instead of {action.name}",
                               step, step + 1, [*_approach(self.state, receptacle),
                                                {"action": "PutObject", "object": held,
                                                 "target": receptacle}])

    def _receptacles(self, held: str) -> list[str]:
        state, beside = self.state, self.state.robot.beside
        here = [o.id for o in sorted(state.objects.values(), key=lambda o: o.id)
                if o.id != held and o.kind.flag("receptacle") is True and o.type != "Floor"
                and state.room_of(o.id) == state.robot.room]
        # The task's own targets first, then what the robot stands beside.
        here.sort(key=lambda r: (r not in self.task_targets, r != beside))
        return here[:MAX_RECEPTACLES]

    def _approaches(self) -> Iterator[Candidate]:
        step = self.failure.step
        raw = self.plan[step]
        action = self._action(step)
        name = action.name if action is not None else _name(raw)
        where = raw.get("target") if name in HELD_ACTIONS else raw.get("object")
        if isinstance(where, str) and self.state.entity_type(where) in ("object", "person"):
            moves = _approach(self.state, where)
            if moves:
                yield self._edited("insert_approach", step, f"go to {where} before step {step}",
                                   step, step, moves)

    def _switch_offs(self) -> Iterator[Candidate]:
        state, at = self.state, self.at
        switched = [o.id for o in sorted(state.objects.values(), key=lambda o: o.id)
                    if state.value("is_on", (o.id,)) is True
                    and self.initial.value("is_on", (o.id,)) is not True]
        toggled = {a.object for a in self.trace.actions if a.name == "ToggleObjectOn"}
        for appliance in switched:
            controls = [a for a, rel, b in state.relations if rel == "controls" and b == appliance]
            # What the plan itself switched on first: the knob it turned, or the appliance.
            switches = sorted([appliance, *controls], key=lambda o: o not in toggled)
            for switch in switches:
                yield self._edited("insert_switch_off", at,
                                   f"switch {switch} off before step {at}", at, at,
                                   [*_approach(state, switch),
                                    {"action": "ToggleObjectOff", "object": switch}])

    def _put_away(self) -> Iterator[Candidate]:
        state, at = self.state, self.at
        held = state.robot.holding
        start = self.initial.objects.get(held or "")
        if held is None or start is None or start.parent is None:
            return
        place = start.parent
        if state.entity_type(place) != "object":
            return
        yield self._edited("insert_put_away", at, f"put {held} back on {place} before step {at}",
                           at, at, [*_approach(state, place),
                                    {"action": "PutObject", "object": held, "target": place}])

    def _reorders(self) -> Iterator[Candidate]:
        step = self.failure.step
        if step + 1 < len(self.plan):
            yield self._edited("reorder", step, f"steps {step} and {step + 1} swapped", step,
                               step + 2, [self.plan[step + 1], self.plan[step]])
        if step >= 1:
            yield self._edited("reorder", step - 1, f"steps {step - 1} and {step} swapped",
                               step - 1, step + 1, [self.plan[step], self.plan[step - 1]])

    def _drop(self, step: int, why: str) -> Candidate:
        return self._edited("drop", step, f"step {step} removed: {why}", step, step + 1, [])
