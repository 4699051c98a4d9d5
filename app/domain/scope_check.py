"""Checking plan steps against the task's scope (Stages 5 and 6).

In: a `TaskScope` and parsed actions with the state each runs in. Out: `Departure`s: a step that
leaves the task, with the rule it breaks, a description quoting the command's words it departs
from, and a pseudo-formula `scope(action, object, target)` (not the condition language).
Rules, in the order they are told apart:
An entity matches the one the scope names when it is that entity, controls it or is controlled
by it (a stove's knob and its burner), or, for an entity Stage 1 made up, is of its kind.
- `scope.target`: the task does this action with this object, but to someone or something
  else (`HandOver mug_1` to mum when the command said dad);
- `scope.action`: the object is part of the task, this action on it is not (`ThrowObject`);
- `scope.object`: the task does nothing of the kind with this object (`HandOver knife_1`);
- `scope.aside`: something outside the task was picked up and then not simply put down again
  in the same room (used, carried elsewhere, or still held at the end). Stage 5 sees the
  whole plan and reports it at the pickup; the monitor, which cannot see ahead, allows the
  pickup and halts at the step that uses or moves it (`AsideTracker`).
Fails: never.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from app.domain.scope import PICKUP, ScopeStep, TaskScope
from app.domain.world import Action, WorldState
from app.domain.world.object_types import normalize_type


@dataclass(frozen=True, slots=True)
class Departure:
    """A step outside the task's scope."""

    step: int
    action: Action
    rule: str
    description: str
    quote: str

    @property
    def condition_id(self) -> str:
        return f"scope.{self.rule}"

    @property
    def formula(self) -> str:
        return f"scope({self.action.name}, {self.action.object}, {self.action.target})"


def _matches(expected: str | None, kind: str | None, actual: str | None,
             state: WorldState) -> bool:
    if expected is None or expected == actual:
        return True
    if actual is None:
        return False
    if kind is None:
        # A stove's knob stands for its burner, and the other way round.
        return ((actual, "controls", expected) in state.relations
                or (expected, "controls", actual) in state.relations)
    if kind in ("person", "room"):
        return state.entity_type(actual) == kind
    if kind.startswith("person:"):
        person = state.people.get(actual)
        return person is not None and kind[7:] in {
            normalize_type(n) for n in (person.role, person.name) if n}
    obj = state.objects.get(actual)
    return obj is not None and normalize_type(obj.kind.name) == kind


class ScopeMatcher:
    """A scope indexed for checking; immutable, shared by sessions of one contract."""

    __slots__ = ("_by_action", "_enabling", "scope")

    def __init__(self, scope: TaskScope) -> None:
        self.scope = scope
        self._enabling = frozenset(scope.enabling)
        by_action: dict[str, list[ScopeStep]] = {}
        for step in scope.steps:
            by_action.setdefault(step.action, []).append(step)
        self._by_action = {name: tuple(steps) for name, steps in by_action.items()}

    def authorized(self, action: Action, state: WorldState) -> bool:
        """Whether the command itself asks for this step (enabling moves aside)."""
        return any(_matches(s.object, s.object_kind, action.object, state)
                   and _matches(s.target, s.target_kind, action.target, state)
                   for s in self._by_action.get(action.name, ()))

    def departure(self, action: Action, state: WorldState, step: int) -> Departure | None:
        """The step's departure from the scope, judged on the step alone (a pickup of
        something outside the task is allowed here; see `AsideTracker`)."""
        if action.name in self._enabling or self.authorized(action, state):
            return None
        if action.name == PICKUP and self.scope.move_aside:
            return None
        return self.explain(action, state, step)

    def explain(self, action: Action, state: WorldState, step: int) -> Departure:
        """Why a step the scope does not authorize leaves the task (which rule, which words)."""
        name, obj, target = action.name, action.object, action.target
        same = self._by_action.get(name, ())
        with_object = [s for s in same if _matches(s.object, s.object_kind, obj, state)]
        about_object = [s for s in self.scope.steps if obj is not None and s.object is not None
                        and _matches(s.object, s.object_kind, obj, state)]
        shown = _show(action)
        if with_object:
            targets = sorted({s.target for s in with_object if s.target})
            words = with_object[0].words
            return Departure(step, action, "target", (
                f'{shown} departs from the task: "{words}" has {name} {obj} go to '
                f"{' or '.join(targets)} only."), words)
        if about_object:
            words = about_object[0].words
            allowed = sorted({s.action for s in about_object
                              if s.action not in self._enabling or s.kind == "literal"})
            asked = (", ".join(allowed[:-1]) + " or " + allowed[-1] if len(allowed) > 1
                     else allowed[0] if allowed else "no action beyond moving it")
            return Departure(step, action, "action", (
                f'{shown} departs from the task: "{words}" asks for {asked} with {obj}, '
                f"not {name}."), words)
        near = same or [s for s in self.scope.steps
                        if target is not None and s.target == target]
        words = near[0].words if near else self.scope.command
        others = sorted({s.object for s in same if s.object})
        then = f" ({name} is for {', '.join(others)})" if others else ""
        what = f"{name} of {obj}" if obj is not None else f"{name}"
        return Departure(step, action, "object", (
            f'{shown} departs from the task: "{words}" names no {what}{then}.'), words)


def _show(action: Action) -> str:
    parts = [action.name, *(p for p in (action.object,) if p)]
    return " ".join(parts) + (f" -> {action.target}" if action.target else "")


@dataclass
class AsideTracker:
    """Things outside the task picked up to be moved aside: object -> (pickup step, action,
    room it was picked up in)."""

    matcher: ScopeMatcher
    held: dict[str, tuple[int, Action, str | None]] = field(default_factory=dict)

    def observe(self, action: Action, before: WorldState, step: int) -> Departure | None:
        """Note a step; a departure (dated at the pickup) when it breaks the aside rule."""
        obj = action.object
        if action.name == PICKUP and obj is not None:
            if not self.matcher.authorized(action, before):
                self.held[obj] = (step, action, before.room_of(obj))
            return None
        if obj is None or obj not in self.held:
            return None
        if action.name == "PutObject":
            picked, pickup, room = self.held.pop(obj)
            here = before.robot.room
            if room is None or here is None or here == room:
                return None
            return self._aside(picked, pickup, f"puts it down in {here}, not {room}")
        if action.name in self.matcher.scope.enabling:
            return None  # going somewhere with it, opening a door: not yet a use
        picked, pickup, _ = self.held.pop(obj)
        use = self.matcher.explain(action, before, step)
        return self._aside(picked, pickup, f"goes on to {_show(action)} at step {step}",
                           use.quote)

    def unfinished(self) -> list[Departure]:
        """Things picked up aside that the plan never put down."""
        return [self._aside(picked, pickup, "never puts it down")
                for picked, pickup, _ in self.held.values()]

    def _aside(self, step: int, pickup: Action, what: str, words: str | None = None
               ) -> Departure:
        words = words or self.matcher.scope.command
        return Departure(step, pickup, "aside", (
            f'{_show(pickup)} departs from the task: "{words}" does not name '
            f"{pickup.object}, so it may only be moved aside and put down in the same room; "
            f"the plan {what}."), words)


def plan_departures(matcher: ScopeMatcher, trace: Sequence[tuple[int, Action, WorldState]],
                    *, complete: bool) -> list[Departure]:
    """Every departure of a plan from the scope, each dated at the step that leaves the task.

    Args:
        matcher: the scope.
        trace: (step index, parsed action, state before it) for every step that ran.
        complete: whether the trace reached the end of the plan (only then is something
            still held aside a departure).

    Returns:
        The departures, by step.
    """
    tracker = AsideTracker(matcher)
    found: list[Departure] = []
    for index, action, before in trace:
        departure = matcher.departure(action, before, index)
        if departure is not None:
            found.append(departure)
        aside = tracker.observe(action, before, index)
        if aside is not None:
            found.append(aside)
    if complete:
        found.extend(tracker.unfinished())
    return sorted(found, key=lambda d: d.step)
