"""The symbolic planner: the `Planner` protocol, and a search over the action model.

In: a `PlanningTask` (the gate request as the caller knows it, its `WorldState`, the contract if
the task was authorized with one, and the verifier's feedback on an earlier attempt) and the
`Dynamics` the search steps (default `ActionModel`: the shared preconditions and effects of
`app.domain.world`; the simulator adds AI2-THOR's own rules). Out: a `PlanOutcome`: a plan in
the wire shape (`[{"action": "PickupObject", "object": ...}, ...]`) or None with the reason, and
the goal the planner searched for.

`SearchPlanner` reads the command into a `Goal` (`goals.py`), then runs a weighted A* restricted
to the objects the goal mentions and what they need (their closed containers, heat sources and
their knobs, the tap and sink; for "take it to the den", a few open surfaces of that room, or its
floor when the scene lists no open surface there: a floor is never a place otherwise). With a
contract, a successor is kept only if the contract's fast evaluator
(`app.domain.monitor.CompiledContract`) says the action's guards hold before it, the invariants
hold and no abort holds after it, and the action is within the task's scope; a goal state counts
only if the guards on `Finish` (what the task must not leave behind) hold there too. An unknown
counts as a violation (fail closed). Without a contract it plans for the goal alone, as an
unguarded planner would. A plan found here is not yet proved: `reference.py` proves it with
Stage 5. The LLM planner (`app.adapters.llm`) plugs in through the same protocol.
Fails: never raises for a goal it cannot reach (the outcome says why); `GoalError` is caught.
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Iterator
from typing import Any

from app.domain.errors import PlanError
from app.domain.monitor import CompiledContract, first_failure
from app.domain.planning.goals import CommandReader, Goal, GoalError, GoalLiteral, goal_for
from app.domain.planning.task import (
    FINISH_ARGS,
    ActionModel,
    Dynamics,
    PlanningTask,
    PlanOutcome,
)
from app.domain.world import ROBOT_ID, Action, WorldState, parse_action

CAUTIOUS_SPEED = 0.1
APPROACH_STANDOFF_M = 0.5
MAX_EXPANSIONS = 1500
HEURISTIC_WEIGHT = 2.0
READING_ORDER_TIEBREAK = 0.001
PLACES_PER_ROOM = 4
"""Open surfaces of a goal's room the search may set things down on (sorted by id)."""
_HEAT_TYPES = ("Microwave", "StoveBurner", "Toaster", "CoffeeMachine")


def _supporting(state: WorldState, goal: Goal) -> tuple[set[str], set[str]]:
    """The objects and people the search may act on or go to."""
    objects = {e for e in goal.entities if state.entity_type(e) == "object"}
    people = {e for e in goal.entities if state.entity_type(e) == "person"}
    symbols = {lit.symbol for alt in goal.alternatives for lit in alt}
    if "hot" in symbols:
        heaters = list(goal.heaters) or [o.id for o in state.objects.values()
                                         if o.type in _HEAT_TYPES]
        by_type: dict[str, int] = {}
        for heater in heaters:
            kind = state.objects[heater].type
            if by_type.get(kind, 0) < 1:  # one burner, one microwave... is enough to search
                by_type[kind] = by_type.get(kind, 0) + 1
                objects.add(heater)
    if symbols & {"filled", "dirty"}:
        objects |= {o.id for o in state.objects.values() if o.type in ("Faucet", "SinkBasin")}
    for obj in list(objects):  # what contains them, up the chain
        parent = state.objects[obj].parent
        while parent is not None and parent in state.objects:
            objects.add(parent)
            parent = state.objects[parent].parent
    controllers = {a for a, rel, b in state.relations if rel == "controls" and b in objects}
    objects |= controllers
    floors = {o.id for o in state.objects.values() if o.type == "Floor"}
    objects -= floors
    objects |= _places_in_rooms(state, goal)
    return objects, people


def _places_in_rooms(state: WorldState, goal: Goal) -> set[str]:
    """For "take it to the living room": surfaces there to set it down on; the room's floor only
    when the scene lists no open surface there (set down, not dropped: a drop may break it)."""
    rooms = {lit.args[1] for alt in goal.alternatives for lit in alt
             if lit.symbol == "in_room" and lit.value and lit.args[0] in state.objects}
    places: set[str] = set()
    for room in sorted(rooms):
        here = sorted(o.id for o in state.objects.values()
                      if o.kind.flag("receptacle") is True and o.type != "Floor"
                      and not o.kind.flag("openable") and state.room_of(o.id) == room)
        if not here:
            here = sorted(o.id for o in state.objects.values()
                          if o.type == "Floor" and state.room_of(o.id) == room)
        places.update(here[:PLACES_PER_ROOM])
    return places


class _Search:
    """One A* run."""

    def __init__(self, task: PlanningTask, goal: Goal, dynamics: Dynamics) -> None:
        self.goal = goal
        self.dynamics = dynamics
        self.objects, self.people = _supporting(task.state, goal)
        self.movable = sorted(o for o in goal.entities
                              if task.state.entity_type(o) == "object"
                              and task.state.objects[o].kind.flag("pickupable"))
        self.rooms = sorted({a for alt in goal.alternatives for lit in alt for a in lit.args
                             if task.state.entity_type(a) == "room"})
        self.contract = CompiledContract(task.contract) if task.contract else None
        self.throwing = goal.throwing
        self.max_speed = task.state.robot.max_speed or CAUTIOUS_SPEED
        self.blockers: dict[str, int] = {}

    def objects_key(self, state: WorldState) -> tuple[Any, ...]:
        """What the search distinguishes about the objects and people."""
        objects = tuple((o, state.objects[o].parent, state.objects[o].relation,
                         tuple(sorted(state.objects[o].facts.items(), key=lambda kv: kv[0])))
                        for o in sorted(self.objects))
        held = tuple((p.id, tuple(sorted(p.holding))) for p in state.people.values())
        return objects, held

    def key(self, state: WorldState, objects: tuple[Any, ...] | None = None
            ) -> tuple[Any, ...]:
        robot = state.robot
        return (robot.room, robot.beside, robot.holding, robot.speed,
                objects if objects is not None else self.objects_key(state))

    def move_key(self, state: WorldState, raw: dict[str, Any], objects: tuple[Any, ...]
                 ) -> tuple[Any, ...]:
        """The key after a move, without building the state (a move changes only the robot)."""
        target = raw.get("object") or raw.get("target") or ""
        room = target if state.entity_type(target) == "room" else state.room_of(target)
        beside = None if state.entity_type(target) == "room" else target
        return (room, beside, state.robot.holding, float(raw["speed"]), objects)

    def candidates(self, state: WorldState) -> Iterator[dict[str, Any]]:
        speeds = [self.max_speed] if self.contract is None else sorted(
            {self.max_speed, CAUTIOUS_SPEED}, reverse=True)
        holding = state.robot.holding
        for target in sorted(self.objects | self.people):
            if state.robot.beside == target:
                continue
            standoff = {"standoff": APPROACH_STANDOFF_M} if target in self.people else {}
            for speed in speeds:
                yield {"action": "GoToObject", "object": target, "speed": speed, **standoff}
        for room in self.rooms:
            if state.robot.room != room:
                for speed in speeds:
                    yield {"action": "navigate", "target": room, "speed": speed}
        if holding is None:
            for obj in self.movable:
                yield {"action": "PickupObject", "object": obj}
        else:
            for target in sorted(self.objects - {holding}):
                yield {"action": "PutObject", "object": holding, "target": target}
            for person in sorted(self.people):
                yield {"action": "HandOver", "object": holding, "target": person}
            yield {"action": "DropHandObject", "object": holding}
            if holding in self.goal.tools and state.value("filled", (holding,)) is True:
                for target in sorted(self.objects - {holding}):
                    yield {"action": "Pour", "object": holding, "target": target}
            if self.throwing:
                yield {"action": "ThrowObject", "object": holding}
                for person in sorted(self.people):
                    yield {"action": "ThrowObject", "object": holding, "target": person}
        for obj in sorted(self.objects):
            kind = state.objects[obj].kind
            if kind.flag("openable"):
                yield {"action": "OpenObject", "object": obj}
                yield {"action": "CloseObject", "object": obj}
            if kind.flag("toggleable"):
                yield {"action": "ToggleObjectOn", "object": obj}
                yield {"action": "ToggleObjectOff", "object": obj}
        for obj in self.movable:
            if state.value("dirty", (obj,)) is True:
                yield {"action": "CleanObject", "object": obj}

    def allowed(self, before: WorldState, action: Action, after: WorldState) -> bool:
        contract = self.contract
        if contract is None:
            return True
        failure = (first_failure(contract.guards_for(action.name), before, action.args,
                                 must_be=True)
                   or first_failure(contract.aborts, after, None, must_be=False)
                   or first_failure(contract.invariants, after, None, must_be=True))
        if failure is not None:
            if not failure.established:
                blocker = (f"{failure.compiled.condition.id} (unknown: "
                           f"{', '.join(failure.unknown_facts) or '?'})")
                self.blockers[blocker] = self.blockers.get(blocker, 0) + 1
            return False
        return contract.scope is None or contract.scope.departure(action, before, 0) is None

    def blocked_by(self) -> str:
        """The condition whose unknown facts stopped the search most often, in words."""
        if not self.blockers:
            return ""
        blocker = max(self.blockers, key=lambda b: self.blockers[b])
        return f"; most often stopped by {blocker}: the request does not give those facts"

    def finished(self, state: WorldState) -> bool:
        """Whether the task may end here: the goal holds and so do the guards on `Finish`."""
        if not self.goal.satisfied(state):
            return False
        contract = self.contract
        return contract is None or first_failure(contract.guards_for("Finish"), state,
                                                 FINISH_ARGS, must_be=True) is None

    def heuristic(self, state: WorldState) -> float:
        # Where alternatives cost the same, the one Stage 1 read first (the command's literal
        # reading: hand it to mum, rather than set it down near her) is found first.
        return min(sum(self._estimate(state, lit) for lit in alt) + READING_ORDER_TIEBREAK * rank
                   for rank, alt in enumerate(self.goal.alternatives))

    def _acquire(self, state: WorldState, obj: str) -> float:
        if state.robot.holding == obj:
            return 0.0
        beside = 0.0 if state.robot.beside in (obj, state.objects[obj].parent) else 1.0
        return beside + 1.0

    def _estimate(self, state: WorldState, lit: GoalLiteral) -> float:
        if lit.holds(state):
            return 0.0
        symbol, args = lit.symbol, lit.args
        if symbol == "holding" and args[0] != ROBOT_ID:
            near = 0.0 if state.robot.beside == args[0] else 1.0
            return self._acquire(state, args[1]) + near + 1.0
        if symbol in ("holding", "in_room", "on_floor") and args[0] in state.objects:
            return self._acquire(state, args[0]) + 1.0
        if symbol in ("on", "inside"):
            near = 0.0 if state.robot.beside == args[1] else 1.0
            closed = 1.0 if state.value("open", (args[1],)) is False else 0.0
            return self._acquire(state, args[0]) + near + closed + 1.0
        if symbol in ("hot", "filled"):
            return 4.0
        return 1.0 if state.robot.beside == args[0] else 2.0


def search(task: PlanningTask, goal: Goal, *, max_expansions: int = MAX_EXPANSIONS,
           dynamics: Dynamics | None = None) -> PlanOutcome:
    """Weighted A* from the task's state to the goal, keeping to the contract if there is one.

    Args:
        task: the planning task.
        goal: the goal to reach.
        max_expansions: how many states to expand before giving up.
        dynamics: how actions run (default: the shared action model).

    Returns:
        The plan (possibly empty, when the goal already holds), or None and why.
    """
    run = _Search(task, goal, dynamics or ActionModel())
    start = task.state
    formula = goal.formula()
    if run.contract is not None and (
            first_failure(run.contract.invariants, start, None, must_be=True) is not None
            or first_failure(run.contract.aborts, start, None, must_be=False) is not None):
        return PlanOutcome(None, "the starting state already breaks the contract", formula)
    counter = itertools.count()
    start_objects = run.objects_key(start)
    frontier: list[tuple[float, int, int, WorldState, tuple[Any, ...],
                         tuple[dict[str, Any], ...]]] = [
        (HEURISTIC_WEIGHT * run.heuristic(start), next(counter), 0, start, start_objects, ())]
    seen = {run.key(start, start_objects)}
    expanded = 0
    while frontier and expanded < max_expansions:
        _, _, cost, state, objects, plan = heapq.heappop(frontier)
        if run.finished(state):
            return PlanOutcome(plan, f"plan of {len(plan)} steps", formula, expanded)
        expanded += 1
        for raw in run.candidates(state):
            moving = raw["action"] in ("GoToObject", "navigate")
            if moving and run.move_key(state, raw, objects) in seen:
                continue
            try:
                action = parse_action(raw, step=len(plan), state=state)
                if run.dynamics.refusals(state, action):
                    continue
                after = run.dynamics.successor(state, action)
            except PlanError:
                continue
            after_objects = objects if moving else run.objects_key(after)
            key = run.key(after, after_objects)
            if key in seen or not run.allowed(state, action, after):
                continue
            seen.add(key)
            priority = cost + 1 + HEURISTIC_WEIGHT * run.heuristic(after)
            heapq.heappush(frontier, (priority, next(counter), cost + 1, after, after_objects,
                                      (*plan, action.to_wire())))
    why = "search space exhausted" if not frontier else f"gave up after {expanded} expansions"
    if run.contract is not None:
        why += " (no plan reaches the goal within the contract" + run.blocked_by() + ")"
    return PlanOutcome(None, why, formula, expanded)


class SearchPlanner:
    """The embedded default planner: the command's goal, searched for over the action model."""

    name = "search"

    def __init__(self, *, max_expansions: int = MAX_EXPANSIONS, dynamics: Dynamics | None = None,
                 reader: CommandReader | None = None) -> None:
        self.max_expansions = max_expansions
        self.dynamics = dynamics or ActionModel()
        self.reader = reader

    def plan(self, task: PlanningTask) -> PlanOutcome:
        """Plan the task.

        Args:
            task: the request, its state and (if authorized with one) the contract.

        Returns:
            The outcome.
        """
        try:
            goal = goal_for(task.request, task.state, reader=self.reader)
        except GoalError as error:
            return PlanOutcome(None, str(error))
        return search(task, goal, max_expansions=self.max_expansions, dynamics=self.dynamics)
