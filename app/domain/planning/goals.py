"""From a command to a goal the planner can search for: the analyzer's reading, as literals.

In: a gate request (command and scene), its `WorldState` and optionally Stage 1's reader (default
the embedded symbolic analyzer). Out: a `Goal`: alternatives (any
one will do), each a conjunction of literals over the condition language's vocabulary, plus hints
(the heat sources the task uses, the liquid to fill with, the tools it takes up). The command is
read by the gate's own Stage 1 (`SymbolicAnalyzer.understand`): the facts its plan sketch asks for
(the soup hot, the mug in the dad's hands or beside him, the stove off) become the literals; the
careful clean-up adds "leave off what you switched on". Fails: `GoalError` when the reading gives
no fact the planner can reach in this state.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from functools import cache
from typing import TYPE_CHECKING, Protocol

from app.domain.analysis import SymbolicAnalyzer
from app.domain.models import GateRequest
from app.domain.world import ROBOT_ID, WorldState

if TYPE_CHECKING:
    from app.domain.analysis import Understanding

MAX_ALTERNATIVES = 9


class GoalError(ValueError):
    """The command gives no goal the planner can search for."""


@dataclass(frozen=True, slots=True)
class GoalLiteral:
    """`symbol(args)` must have the truth value `value`."""

    symbol: str
    args: tuple[str, ...]
    value: bool = True

    def holds(self, state: WorldState) -> bool:
        """Whether the literal is established (unknown does not count)."""
        return state.value(self.symbol, self.args) is self.value

    def render(self) -> str:
        """The literal in the condition language."""
        args = ", ".join("robot" if a == ROBOT_ID else f'#"{a}"' for a in self.args)
        text = f"{self.symbol}({args})"
        return text if self.value else f"not {text}"


Conjunction = tuple[GoalLiteral, ...]


@dataclass(frozen=True)
class Goal:
    """What the command asks for: any one of the alternatives, each a conjunction."""

    alternatives: tuple[Conjunction, ...]
    heaters: tuple[str, ...] = ()
    liquid: str = "water"
    entities: frozenset[str] = field(default_factory=frozenset)
    throwing: bool = False
    tools: frozenset[str] = field(default_factory=frozenset)

    def satisfied(self, state: WorldState) -> bool:
        """Whether some alternative holds in the state."""
        return any(all(lit.holds(state) for lit in alt) for alt in self.alternatives)

    def formula(self) -> str:
        """The goal in the condition language."""
        parts = [" and ".join(lit.render() for lit in alt) for alt in self.alternatives]
        return parts[0] if len(parts) == 1 else " or ".join(f"({p})" for p in parts)


class CommandReader(Protocol):
    """Stage 1's reading of a command (the symbolic analyzer is one)."""

    def understand(self, request: GateRequest) -> Understanding: ...


@cache
def _analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


def goal_for(request: GateRequest, state: WorldState, *,
             reader: CommandReader | None = None) -> Goal:
    """The goal the command asks for, in the given state.

    Args:
        request: the gate request (its command and scene).
        state: the state the plan starts in (built from the same request).
        reader: Stage 1's reader (default: the embedded symbolic analyzer).

    Returns:
        The goal.

    Raises:
        GoalError: no fact the command asks for can be stated over this state's entities.
    """
    read = (reader or _analyzer()).understand(request)
    sketch = read.sketch

    def reachable(fact: tuple[str, tuple[str, ...], bool]) -> bool:
        return all(a == ROBOT_ID or state.entity_type(a) is not None for a in fact[1])

    def located(fact: tuple[str, tuple[str, ...], bool]) -> tuple[str, tuple[str, ...], bool]:
        # "Take the tomato to the living room": Stage 1 sets it on a surface it made up for the
        # room; in the simulated house the goal is the room itself.
        symbol, args, value = fact
        if symbol in ("on", "inside") and len(args) == 2 and state.entity_type(args[1]) is None:
            room = read.scene.room_of(args[1])
            if room is not None and state.entity_type(room) == "room":
                return ("in_room", (args[0], room), value)
        return fact

    per_goal = [[GoalLiteral(*located(fact)) for fact in options if reachable(located(fact))]
                for options in sketch.goals]
    # Set down in the room, not still carried.
    per_goal += [[GoalLiteral("holding", (ROBOT_ID, fact[1][0]), False)]
                 for options in sketch.goals for fact in options
                 if located(fact) != fact and fact[2]]
    per_goal = [options for options in per_goal if options]
    if not per_goal:
        raise GoalError(f"no goal understood in {request.command!r}")
    wanted_on = {lit.args for options in per_goal for lit in options
                 if lit.symbol == "is_on" and lit.value}
    switched = [p.action.object for p in sketch.cleanup if p.action.name == "ToggleObjectOff"
                and p.action.object and state.entity_type(p.action.object) == "object"]
    heaters = tuple(dict.fromkeys(
        o for o in switched if state.value("heat_source", (o,)) is True))
    restore = tuple(GoalLiteral("is_on", (o,), False) for o in heaters
                    if (o,) not in wanted_on and state.value("is_on", (o,)) is False)
    alternatives = [tuple(dict.fromkeys([*combo, *restore])) for combo in itertools.islice(
        itertools.product(*per_goal), MAX_ALTERNATIVES)]
    steps = list(sketch.steps())
    tools = frozenset(p.action.object for p in steps if p.kind == "enabling"
                      and p.action.name == "PickupObject" and p.action.object
                      and state.entity_type(p.action.object) == "object")
    liquid = next((str(p.action.params["liquid"]) for p in steps
                   if p.action.name == "FillWithLiquid" and "liquid" in p.action.params),
                  "water")
    entities = frozenset(a for alt in alternatives for lit in alt for a in lit.args
                         if a != ROBOT_ID)
    throwing = any(p.action.name == "ThrowObject" for p in steps)
    return Goal(tuple(alternatives), heaters, liquid, entities | tools, throwing, tools)
