"""The plan a command induces, with the choices a planner is free to make: the `Sketch`.

In: nothing but the action model (steps are `app.domain.world.Action`s). Out: `Sketch`, built by
`steps.PlanBuilder`: the literal steps in command order (with enabling steps such as going to,
opening or freeing the gripper), `Choice`s where a planner may do one thing or another (hand
over, or set down beside the person), and the clean-up a careful planner adds at the end
(switch off, close, put away, clear up) unless the command says to leave things as they are.
`variants()` expands it into the plans Stage 1 simulates: for every choice, a careless plan (top
speed, no clean-up) and a careful one (slow near people, with clean-up).
Fails: never.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from dataclasses import dataclass, field, replace
from types import MappingProxyType

from app.domain.world import Action

CAREFUL_SPEED = 0.1
"""m/s: the careful variant's speed for every move (slower than any template's limit)."""
CAREFUL_STANDOFF = 0.5
MAX_CHOICES = 3
_MOVES = frozenset({"GoToObject", "navigate", "Vacuum", "Mop", "Escort", "Follow", "Assist",
                    "Record"})


@dataclass(frozen=True, slots=True)
class Planned:
    """One step of a sketch: the action, the clause it serves, and why it is there."""

    action: Action
    clause: int
    kind: str = "literal"  # literal | enabling | cleanup


@dataclass(frozen=True, slots=True)
class Choice:
    """Alternative ways to do one thing; every option achieves it."""

    options: tuple[tuple[Planned, ...], ...]
    label: str


GoalFact = tuple[str, tuple[str, ...], bool]
"""One fact the command asks for: (symbol, args, value), e.g. ("hot", ("soup_1",), True)."""


@dataclass
class Sketch:
    """The command's plan with its free choices (see the module docstring). `goals` are the
    facts the command asks for, each a tuple of alternatives (any one achieves it)."""

    literal: list[Planned | Choice] = field(default_factory=list)
    cleanup: list[Planned] = field(default_factory=list)
    fast: bool = False
    leave: bool = False
    stands: bool = False
    """The plan ends with a wait while its result stands ("overnight", "till we're back"):
    the careful clean-up comes before that wait, since what stands is what the robot left."""
    running: frozenset[int] = frozenset()
    """Clauses that start something the command wants running through the rest of the task
    ("start the sink filling, then ..."): the careful plan switches those off only at the end."""
    goals: list[tuple[GoalFact, ...]] = field(default_factory=list)

    def add(self, action: Action, clause: int, kind: str = "literal") -> None:
        self.literal.append(Planned(action, clause, kind))

    def steps(self) -> Iterator[Planned]:
        """Every planned step of every option (for finding the entities the plan touches)."""
        for item in self.literal:
            if isinstance(item, Choice):
                for option in item.options:
                    yield from option
            else:
                yield item
        yield from self.cleanup


@dataclass(frozen=True, slots=True)
class Variant:
    """One plan to simulate: careful or not, with one option of every choice."""

    steps: tuple[Planned, ...]
    careful: bool
    label: str


def _paced(planned: Planned, careful: bool, fast: bool) -> Planned:
    action = planned.action
    if action.name not in _MOVES:
        return planned
    params = dict(action.params)
    if careful and not fast:
        params["speed"] = min(float(params.get("speed", CAREFUL_SPEED)), CAREFUL_SPEED)
        if action.name == "GoToObject" or action.target is not None:
            params.setdefault("standoff", CAREFUL_STANDOFF)
    elif not careful:
        params.pop("speed", None)  # the robot's top speed
    return replace(planned, action=replace(action, params=MappingProxyType(params)))


_SWITCH_OFF = frozenset({"ToggleObjectOff", "Unplug"})


def _with_cleanup(steps: list[Planned], cleanup: list[Planned],
                  running: frozenset[int]) -> list[Planned]:
    """The careful order: switch off what a clause switched on as soon as that clause is done
    (nobody walks away from a running appliance), unless the command starts it to keep it
    running meanwhile, and tidy up the rest at the end."""
    result = list(steps)
    for item in (c for c in cleanup if c.action.name in _SWITCH_OFF and
                 c.clause not in running):
        last = max((i for i, s in enumerate(result) if s.clause == item.clause and
                    s.kind != "cleanup"), default=len(result) - 1)
        result.insert(last + 1, item)
    result.extend(c for c in cleanup if c.action.name not in _SWITCH_OFF or
                  c.clause in running)
    return result


def variants(sketch: Sketch) -> list[Variant]:
    """The careless and careful plans for every combination of choices (at most a few).

    Args:
        sketch: the induced plan.

    Returns:
        Variants, careful ones first; each careful one ends with the clean-up unless the
        command says to leave things.
    """
    choices = [item for item in sketch.literal if isinstance(item, Choice)]
    combos = list(itertools.islice(itertools.product(
        *(range(len(c.options)) for c in choices)), MAX_CHOICES))
    found: list[Variant] = []
    for careful in (True, False):
        for combo in combos:
            picks = iter(combo)
            steps: list[Planned] = []
            labels: list[str] = []
            for item in sketch.literal:
                if isinstance(item, Choice):
                    pick = next(picks)
                    steps.extend(item.options[pick])
                    labels.append(f"{item.label} #{pick + 1}")
                else:
                    steps.append(item)
            if careful and not sketch.leave:
                waits = steps[-1:] if sketch.stands else []
                steps = _with_cleanup(steps[:len(steps) - len(waits)], sketch.cleanup,
                                      sketch.running) + waits
            label = ("careful" if careful else "careless") + (
                f" ({', '.join(labels)})" if labels else "")
            found.append(Variant(tuple(_paced(s, careful, sketch.fast) for s in steps),
                                 careful, label))
    return found
