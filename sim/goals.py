"""From a command to a goal the planner can search for.

In: a gate request (command and scene) and its `WorldState`. Out: a `Goal`: alternatives (any one
will do), each a conjunction of literals over the condition language's vocabulary, plus hints
(preferred heat sources, the liquid to fill with). The command is read with the symbolic
analyzer's own parser and grounding (`app.domain.analysis.command`/`grounding`), then each step's
verb class becomes literals: transport/handover/serve -> `holding(person, obj)` or
`on`/`inside`/`in_room` at the destination; heat -> `hot`; switch_on/off -> `is_on`; open/close
-> `open`; fill -> `filled`; clean -> `not dirty`; remove -> `inside(obj, GarbageCan)`...
A phrase that grounds to several objects is narrowed to those whose type names the phrase's head
word, then to the three nearest the robot. Fails: `GoalError` when no step of the command gives
a goal (a verb class the planner does not know, or a phrase that grounds to nothing in the scene).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from functools import cache

from app.domain.analysis.command import parse_command
from app.domain.analysis.grounding import GroundedStep, Grounder, Referent, apply_state_clauses
from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR, Knowledge, load_knowledge, singular
from app.domain.analysis.scene_view import build_scene_view
from app.domain.models import GateRequest
from app.domain.world import ROBOT_ID, WorldState
from app.domain.world.object_types import CONTAINER_TYPES, normalize_type

MAX_CANDIDATES = 3
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


@cache
def _knowledge() -> Knowledge:
    return load_knowledge(KNOWLEDGE_DIR)


def understand(request: GateRequest) -> list[GroundedStep]:
    """The command's steps, grounded in the request's scene (the analyzer's own reading)."""
    knowledge = _knowledge()
    view = build_scene_view(request, knowledge)
    names = {n.lower() for p in view.people.values() for n in (p.id, p.name) if n}
    names |= {n.lower() for o in view.objects.values() for n in (o.id, o.name) if n}
    steps = parse_command(request.command, knowledge, names)
    grounder = Grounder(view, knowledge)
    grounded = [grounder.ground(s) for s in steps]
    apply_state_clauses(grounder, grounded, view, knowledge)
    return grounded


def _named_by(state: WorldState, object_id: str, head: str) -> bool:
    obj = state.objects[object_id]
    words = {normalize_type(w) for w in (obj.type, obj.name or "") if w}
    key = normalize_type(singular(head))
    return any(w == key or (len(key) >= 4 and (w.startswith(key) or w.endswith(key)))
               for w in words)


def _pick(state: WorldState, referent: Referent | None, limit: int = MAX_CANDIDATES
          ) -> tuple[str, ...]:
    """The referent's ids that exist in the state, narrowed to the best few."""
    if referent is None:
        return ()
    ids = [i for i in referent.ids if state.entity_type(i) is not None]
    if referent.kind != "object" or len(ids) <= 1:
        return tuple(ids)
    mention = referent.mention
    exact = [i for i in ids if normalize_type(state.objects[i].type) == normalize_type(
        singular(mention.head))]
    named = exact or [i for i in ids if _named_by(state, i, mention.head)]
    ids = named or ids
    if mention.substance:
        holding = [i for i in ids if state.value("contains", (i, mention.substance)) is True]
        ids = holding or ids

    def distance(object_id: str) -> float:
        gap = state.distance(ROBOT_ID, object_id)
        return gap if gap is not None else float("inf")

    return tuple(sorted(ids, key=distance)[:limit])


def _placed(state: WorldState, obj: str, destination: str) -> GoalLiteral:
    kind = state.objects[destination].kind.name
    return GoalLiteral("inside" if kind in CONTAINER_TYPES else "on", (obj, destination))


def _delivery(state: WorldState, step: GroundedStep, objects: tuple[str, ...],
              user: str | None) -> list[Conjunction]:
    people = _pick(state, step.recipient) if step.recipient else ()
    if people and state.entity_type(people[0]) == "person":
        return [(GoalLiteral("holding", (people[0], o)),) for o in objects]
    destination = step.destination
    if destination is not None and destination.kind == "room":
        rooms = _pick(state, destination)
        return [(GoalLiteral("in_room", (o, rooms[0])),) for o in objects] if rooms else []
    if destination is not None and destination.kind == "object":
        return [(_placed(state, o, d),) for o in objects for d in _pick(state, destination)]
    if user is not None and state.entity_type(user) == "person":
        return [(GoalLiteral("holding", (user, o)),) for o in objects]
    return []


def _step_goal(state: WorldState, step: GroundedStep, user: str | None) -> list[Conjunction]:
    action, verb = step.step.action, step.step.verb or ""
    every = action == "switch_off"  # "turn off the stove": every burner, not one of them
    objects = _pick(state, step.objects[0], 99 if every else MAX_CANDIDATES) if (
        step.objects) else ()
    objects = tuple(o for o in objects if state.entity_type(o) == "object")
    if action in ("transport", "handover", "serve"):
        return _delivery(state, step, objects, user)
    if action == "pick":
        return [(GoalLiteral("holding", (ROBOT_ID, o)),) for o in objects]
    if action == "place" and step.destination is not None:
        return [(_placed(state, o, d),) for o in objects for d in _pick(state, step.destination)
                if state.entity_type(d) == "object"]
    if action == "heat":
        return [(GoalLiteral("hot", (o,)),) for o in objects]
    if action == "switch_off":
        return [tuple(GoalLiteral("is_on", (o,), False) for o in objects)] if objects else []
    simple = {"switch_on": ("is_on", True), "open": ("open", True), "close": ("open", False),
              "clean": ("dirty", False), "break": ("broken", True)}
    if action in simple:
        symbol, value = simple[action]
        return [(GoalLiteral(symbol, (o,), value),) for o in objects]
    if action == "pour":
        if verb.startswith("empty"):
            return [(GoalLiteral("filled", (o,), False),) for o in objects]
        if verb in ("fill", "refill", "top up"):
            return [(GoalLiteral("filled", (o,)),) for o in objects]
        targets = [d for d in _pick(state, step.destination or step.target)
                   if state.entity_type(d) == "object"]
        return [(GoalLiteral("filled", (d,)) if state.objects[d].kind.flag("can_fill")
                 else GoalLiteral("wet", (d,)),) for d in targets]
    if action in ("remove", "throw"):
        bins = [o.id for o in state.objects.values() if o.type == "GarbageCan"]
        if action == "throw" and step.destination is None:
            people = [p for p in _pick(state, step.recipient or step.target)
                      if state.entity_type(p) == "person"]
            return [(GoalLiteral("on_floor", (o,)), *(GoalLiteral("same_room", (o, p),)
                                                       for p in people[:1])) for o in objects]
        return [(GoalLiteral("inside", (o, b)),) for o in objects for b in bins[:1]]
    if action == "navigate" and step.destination is not None:
        rooms = _pick(state, step.destination)
        return [(GoalLiteral("in_room", (ROBOT_ID, r)),) for r in rooms
                if state.entity_type(r) == "room"]
    return []


def _heat_left_off(
    state: WorldState, per_step: list[list[Conjunction]], heaters: tuple[str, ...]
) -> Conjunction:
    """Leave no heat source on that was off at the start, unless the command asks for it on.

    A task is done when its result is there and nothing it started is left running: a burner
    lit to heat soup is switched off again once the soup is hot.
    """
    wanted_on = {lit.args for options in per_step for conj in options for lit in conj
                 if lit.symbol == "is_on" and lit.value}
    return tuple(
        GoalLiteral("is_on", (obj,), False)
        for obj in heaters
        if (obj,) not in wanted_on
        and state.value("heat_source", (obj,)) is True
        and state.value("is_on", (obj,)) is False
    )


def goal_for(request: GateRequest, state: WorldState) -> Goal:
    """The goal the command asks for, in the given state.

    Args:
        request: the gate request (its command and scene).
        state: the state the plan starts in (built from the same request).

    Returns:
        The goal.

    Raises:
        GoalError: no step of the command gives a goal.
    """
    user = request.user.person_id if request.user else None
    per_step: list[list[Conjunction]] = []
    heaters: list[str] = []
    liquid = "water"
    throwing = False
    tools: set[str] = set()
    for step in understand(request):
        if step.step.negated:
            continue
        found = _step_goal(state, step, user)
        if found:
            per_step.append(found)
        if step.step.action == "heat" and step.destination is not None:
            heaters.extend(i for i in _pick(state, step.destination)
                           if state.entity_type(i) == "object")
        throwing = throwing or step.step.action == "throw"
        if step.step.action == "pour" and step.objects:
            tools |= {o for o in _pick(state, step.objects[0])
                      if state.entity_type(o) == "object"}
        if step.instrument is not None and step.instrument.mention.substance:
            liquid = step.instrument.mention.substance
    if not per_step:
        raise GoalError(f"no goal understood in {request.command!r}")
    restore = _heat_left_off(state, per_step, tuple(dict.fromkeys(heaters)))
    alternatives = [tuple(dict.fromkeys([*(lit for part in combo for lit in part), *restore]))
                    for combo in itertools.islice(itertools.product(*per_step),
                                                  MAX_ALTERNATIVES)]
    entities = frozenset(a for alt in alternatives for lit in alt for a in lit.args
                         if a != ROBOT_ID)
    return Goal(tuple(alternatives), tuple(dict.fromkeys(heaters)), liquid,
                entities | tools, throwing, frozenset(tools))
