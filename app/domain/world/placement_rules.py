"""Where things are: the meaning of the placement and proximity predicates in a world state.

In: a `WorldState` and the symbol's arguments (ids of the right type). Out: True/False/float or
`Unknown`. Rooms and positions are inherited: a held object is where its holder is, an object
without its own room or position is where its receptacle is (`WorldState.room_of`/`position_of`).
Fails: never.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from app.domain.formula.facts import FactValue, Unknown, fact_key
from app.domain.world.entities import AWAY, ROBOT_ID, ObjectState
from app.domain.world.object_rules import Rule, stated_value, unknown_of
from app.domain.world.object_types import normalize_type

if TYPE_CHECKING:
    from app.domain.world.state import WorldState

PLACEMENT_RULES: dict[str, Rule] = {}
NEAR_M = 1.0
ELEVATED_M = 1.5
# Surfaces at or below table height: what rests on them is not "high up".
_LOW_SURFACES = frozenset(normalize_type(t) for t in (
    "Floor", "CounterTop", "DiningTable", "CoffeeTable", "SideTable", "Desk", "Bed", "Sofa",
    "ArmChair", "Chair", "Stool", "Ottoman", "TVStand", "Dresser", "StoveBurner", "Sink",
    "SinkBasin", "Toilet", "Bathtub", "BathtubBasin", "GarbageCan", "Footstool", "DogBed",
    "Drawer", "Fridge", "Dishwasher", "WashingMachine", "Oven", "Bed", "CoffeeMachine",
))


def _rule(name: str) -> Callable[[Rule], Rule]:
    def register(func: Rule) -> Rule:
        PLACEMENT_RULES[name] = func
        return func
    return register


def _is_floor(obj: ObjectState | None) -> bool:
    return obj is not None and obj.kind.name.lower() == "floor"


def _names_exit(state: WorldState, entity_id: str) -> bool:
    target = state.objects.get(entity_id)
    words = normalize_type(target.kind.name if target else entity_id)
    return any(w in words for w in ("door", "exit", "stair", "hall", "gate", "landing",
                                    "corridor", "entrance", "entry", "foyer", "porch"))


def _names_ground(obj: ObjectState) -> bool:
    words = normalize_type(obj.kind.name)
    return any(w in words for w in ("floor", "stair", "step", "rug", "mat", "path", "walkway",
                                    "carpet", "ground", "doorway"))


def _placement(state: WorldState, obj: ObjectState, symbol: str) -> tuple[
        FactValue | None, ObjectState | None]:
    """A value decided by a statement or by being held (held things rest nowhere), and the
    receptacle the object rests on."""
    stated = stated_value(obj, symbol)
    if stated is not None:
        return stated, None
    if state.holder_of(obj.id) is not None:
        return False, None
    return None, state.objects.get(obj.parent) if obj.parent else None


@_rule("on_floor")
def _on_floor(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    decided, parent = _placement(state, obj, "on_floor")
    if decided is not None:
        return decided
    if obj.obstacle or parent is not None:
        return obj.obstacle or _is_floor(parent)
    if _is_floor(obj) or (obj.kind.flag("pickupable") is False
                          and obj.kind.flag("moveable") is False):
        return False  # fixtures and furniture stand on the floor; they do not lie on it
    return unknown_of("on_floor", obj)


def _walkway_rule(symbol: str, blocking: Callable[[WorldState, str], bool]) -> None:
    # Something resting on furniture is off the walkways; on the floor, or somewhere
    # unstated, only a `blocks` relation or a statement decides.
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        obj = state.objects[args[0]]
        decided, parent = _placement(state, obj, symbol)
        if decided is not None:
            return decided
        if parent is not None and not _is_floor(parent):
            return False
        if any(a == obj.id and rel == "blocks" and blocking(state, o)
               for a, rel, o in state.relations):
            return True
        if _is_floor(obj):
            return True if symbol == "in_path" else _names_exit(state, state.room_of(
                obj.id) or "")
        if parent is None and not obj.obstacle and obj.kind.flag("pickupable") is False and (
                obj.kind.flag("moveable") is False or obj.kind.flag("receptacle") is True):
            return False  # fixtures and furniture (counter, sink, sofa) stand off the walkways
        if not obj.obstacle and not _names_exit(state, obj.id) and not _names_ground(obj):
            room = state.room_of(obj.id)
            if symbol == "blocks_exit" and room is not None and not blocking(state, room):
                return False  # a way out is a door, hall or stair, or a stated `blocks`
            # Something nobody said lies on a floor (a breaker box, a bowl on a shelf) is not
            # itself in the walkway: a caller mentions what is lying about.
            return False
        return unknown_of(symbol, obj)
    PLACEMENT_RULES[symbol] = rule


_walkway_rule("in_path", lambda state, blocked: True)
_walkway_rule("blocks_exit", _names_exit)


@_rule("exit_way")
def _exit_way(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # A door, gate, stair, hall or exit: what is set against or in front of it is in the way
    # out, whatever the reader makes of "against", "in front of" or "by".
    stated = stated_value(state.objects[args[0]], "exit_way", "exit", "fire_exit")
    return stated if stated is not None else _names_exit(state, args[0])


@_rule("elevated")
def _elevated(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    decided, parent = _placement(state, obj, "elevated")
    if decided is not None:
        return decided
    if obj.position is not None and obj.position.z is not None:
        return obj.position.z >= ELEVATED_M
    height = obj.properties.get("height_m")
    if isinstance(height, int | float) and not isinstance(height, bool):
        return float(height) >= ELEVATED_M
    if parent is not None and normalize_type(parent.kind.name) in _LOW_SURFACES:
        return False
    if parent is None and normalize_type(obj.kind.name) in _LOW_SURFACES:
        return False  # the surface itself stands at or below table height
    return unknown_of("elevated", obj)


@_rule("in_room")
def _in_room(state: WorldState, args: tuple[str, ...]) -> FactValue:
    room = state.room_of(args[0])
    return Unknown(fact_key("in_room", args)) if room is None else room == args[1]


_OUTDOOR_ROOMS = ("garden", "yard", "drive", "patio", "lawn", "street", "road", "outside",
                  "terrace", "allotment", "pavement", "sidewalk", "orchard", "field", "beach",
                  "park")


@_rule("outdoors")
def _outdoors(state: WorldState, args: tuple[str, ...]) -> FactValue:
    room = state.room_of(args[0])
    if room is None:
        return Unknown(fact_key("outdoors", args))
    if room == AWAY:
        return False  # gone out (with a key), not left in the garden
    return any(word in room.lower() for word in _OUTDOOR_ROOMS)


@_rule("same_room")
def _same_room(state: WorldState, args: tuple[str, ...]) -> FactValue:
    first, second = state.room_of(args[0]), state.room_of(args[1])
    if first is None or second is None:
        return Unknown(fact_key("same_room", args))
    return first == second


@_rule("near")
def _near(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Within NEAR_M when both positions are known; otherwise the same room counts as near
    # (the spec's rule, and the cautious reading of a scene without positions).
    a, b = args
    if a == b or state.holder_of(a) == b or state.holder_of(b) == a:
        return True
    if (a == ROBOT_ID and _beside(state, b)) or (b == ROBOT_ID and _beside(state, a)):
        return True
    gap = state.distance(a, b)
    if gap is not None:
        return gap <= NEAR_M
    same = _same_room(state, args)
    return Unknown(fact_key("near", args)) if isinstance(same, Unknown) else same


def _beside(state: WorldState, entity_id: str) -> bool:
    """Whether the robot moved next to the entity, or to what the entity rests on."""
    beside = state.robot.beside
    for _ in range(16):
        if beside is None or entity_id == beside:
            return beside is not None
        obj = state.objects.get(entity_id)
        if obj is None or obj.parent is None or state.holder_of(entity_id) is not None:
            return False
        entity_id = obj.parent
    return False


NEXT_TO_M = 0.5


_STAIR_WORDS = ("stair", "staircase", "stairway", "steps")


def _is_stairs(room: str) -> bool:
    return any(w in normalize_type(room) for w in _STAIR_WORDS)


@_rule("via_stairs")
@_rule("room_via_stairs")
def _via_stairs(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # True only on evidence: every route of the layout passes a stairs room, or (without
    # connections) one end is the stairs or says it is upstairs and the other does not.
    # A place nobody located is not assumed to be on another floor.
    start, goal = state.robot.room, state.room_of(args[0])
    if start is None or goal is None or start == goal:
        return False
    if state.connections:
        stairs = frozenset(r for r in state.rooms if _is_stairs(r))
        if not stairs or state.route(start, goal, avoiding=stairs) is not None:
            return False
        return state.route(start, goal) is not None
    upstairs = ["upstairs" in normalize_type(r) for r in (start, goal)]
    return _is_stairs(goal) or _is_stairs(start) or upstairs[0] != upstairs[1]


@_rule("beside")
def _side_by_side(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Only what the scene or the plan says: one rests on the other, or a stated or created
    # next_to relation. Everything else in a room is not "beside" (next_to may still be).
    a, b = args
    if a == b:
        return False
    for first, second in ((a, b), (b, a)):
        obj = state.objects.get(first)
        if obj is not None and obj.parent == second and state.holder_of(first) is None:
            return True
    return any({s, o} == {a, b} and rel in ("next_to", "beside", "touching", "against")
               for s, rel, o in state.relations)


@_rule("next_to")
def _next_to(state: WorldState, args: tuple[str, ...]) -> FactValue:
    a, b = args
    if a == b or state.holder_of(a) == b or state.holder_of(b) == a:
        return True
    for first, second in ((a, b), (b, a)):
        obj = state.objects.get(first)
        if obj is not None and obj.parent == second and state.holder_of(first) is None:
            return True
    if any({s, o} == {a, b} and rel in ("next_to", "beside", "touching", "against")
           for s, rel, o in state.relations):
        return True
    same = _same_room(state, args)
    if same is False:
        return False
    gap = state.distance(a, b)
    if gap is not None:
        return gap <= NEXT_TO_M
    return Unknown(fact_key("next_to", args))


@_rule("distance")
def _distance(state: WorldState, args: tuple[str, ...]) -> FactValue:
    if state.holder_of(args[0]) == args[1] or state.holder_of(args[1]) == args[0]:
        return 0.0
    gap = state.distance(args[0], args[1])
    return Unknown(fact_key("distance", args)) if gap is None else gap


def _rests_rule(symbol: str, relation: str) -> None:
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        obj, support = state.objects[args[0]], state.objects[args[1]]
        if state.holder_of(obj.id) is not None:
            return False
        if obj.parent is not None:
            return obj.parent == support.id and (obj.relation or "on") == relation
        # Unstated: only something that can move could rest on a receptacle.
        if obj.obstacle or support.kind.flag("receptacle") is False or obj.kind.flag(
                "pickupable") is False or state.value("animal", (obj.id,)) is True:
            # furniture and fixtures stand on the floor, not on or in things; a pet the scene
            # puts nowhere is about the room, or the caller would have said where
            return False
        return Unknown(fact_key(symbol, args))
    PLACEMENT_RULES[symbol] = rule


_rests_rule("on", "on")
_rests_rule("inside", "in")


@_rule("holding")
def _holding(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Hands are known: the robot's from its profile, people's from `holding` relations. An
    # object no relation puts in someone's hands is not held.
    holder_id, object_id = args
    return state.holder_of(object_id) == holder_id


@_rule("reachable_by")
def _reachable_by(state: WorldState, args: tuple[str, ...]) -> FactValue:
    object_id, person_id = args
    holder = state.holder_of(object_id)
    if holder is not None:
        return holder == person_id
    same_room = _same_room(state, (object_id, person_id))
    if same_room is not True:
        return same_room if same_room is False else Unknown(fact_key("reachable_by", args))
    person = state.people[person_id]
    if person.properties.get("mobility") == "bedridden":
        near = _near(state, (object_id, person_id))
        return near if near is not True else _not_elevated(state, args)
    return _not_elevated(state, args)


def _not_elevated(state: WorldState, args: tuple[str, ...]) -> FactValue:
    elevated = state.value("elevated", (args[0],))
    return Unknown(fact_key("reachable_by", args)) if isinstance(elevated, Unknown) else (
        not elevated)


@_rule("occupied")
def _occupied(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # False only when the scene listed its people and every one of them is placed elsewhere.
    room = args[0]
    rooms = [state.room_of(p) for p in state.people]
    if room in rooms:
        return True
    if state.people_known and None not in rooms:
        return False
    return Unknown(fact_key("occupied", args))
