"""The symbolic world state: robot, objects, people, rooms; a `Facts` for the condition language.

In: entity records (built from a request by `app.domain.world.build`, or by an action's effect).
Out: a `WorldState` that answers `value(symbol, args)` for every vocabulary symbol, three-valued
(`Unknown(key)` when the state does not determine the fact), plus `domain` and `entity_type`.
A state never changes: effects and snapshots return a new state (`evolve`). Fact values are
memoised per state, so a condition checked many times against one state costs a dict lookup.
Fails: never; a fact about an id not in the state, or of the wrong type, is `Unknown`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeVar

from app.domain.formula.facts import FactValue, Unknown, fact_key
from app.domain.formula.vocabulary import VOCABULARY
from app.domain.world.entities import ROBOT_ID, ObjectState, PersonState, Point, RobotState
from app.domain.world.rules import RULES, Rule

if TYPE_CHECKING:
    from app.domain.models import GateRequest, InitialState

_ENTITY_ARG_TYPES = frozenset({"robot", "object", "person", "room", "entity"})
_ACCEPTS: dict[str, frozenset[str]] = {
    "robot": frozenset({"robot"}),
    "object": frozenset({"object"}),
    "person": frozenset({"person"}),
    "room": frozenset({"room"}),
    "entity": frozenset({"robot", "object", "person"}),
}
# For each symbol: its rule, its arity, and the positions of its entity arguments with the
# entity types each accepts (a fact about an id of another type is unknown).
_PLANS: dict[str, tuple[Rule, int, tuple[tuple[int, frozenset[str]], ...]]] = {
    name: (RULES[name], sym.arity,
           tuple((i, _ACCEPTS[t]) for i, t in enumerate(sym.args) if t in _ENTITY_ARG_TYPES))
    for name, sym in VOCABULARY.items() if name in RULES
}


Placed = RobotState | PersonState | ObjectState
_Place = TypeVar("_Place")


def _room(thing: Placed) -> str | None:
    return thing.room


def _position(thing: Placed) -> Point | None:
    return thing.position


def _itself(room: str) -> str:
    return room


class WorldState:
    """An immutable symbolic state; implements the `Facts` protocol."""

    __slots__ = (
        "_domains", "_holder", "_memo", "_types", "connections", "objects", "people",
        "people_known", "relations", "robot", "rooms", "version",
    )

    def __init__(
        self,
        *,
        robot: RobotState,
        objects: Mapping[str, ObjectState],
        people: Mapping[str, PersonState],
        rooms: Sequence[str] = (),
        connections: frozenset[tuple[str, str]] = frozenset(),
        relations: tuple[tuple[str, str, str], ...] = (),
        people_known: bool = False,
        version: int = 0,
    ) -> None:
        """Build a state; use `app.domain.world.build.state_from_request` for requests.

        Args:
            robot: the robot record.
            objects: objects by id.
            people: people by id.
            rooms: the layout's rooms (rooms entities mention are added).
            connections: pairs of rooms that connect, both orders.
            relations: other (subject, relation, object) facts: next_to, blocks, plugged_into.
            people_known: whether the scene listed its people (an empty list then means nobody).
            version: how many effects led here; names fresh unknowns that effects create.
        """
        self.robot = robot
        self.objects = dict(objects)
        self.people = dict(people)
        self.connections = connections
        self.relations = relations
        self.people_known = people_known
        self.version = version
        mentioned = [robot.room, *(o.room for o in self.objects.values()),
                     *(p.room for p in self.people.values())]
        self.rooms = tuple(dict.fromkeys([*rooms, *(r for r in mentioned if r)]))
        types: dict[str, str] = dict.fromkeys(self.rooms, "room")
        types.update(dict.fromkeys(self.objects, "object"))
        types.update(dict.fromkeys(self.people, "person"))
        types[ROBOT_ID] = "robot"
        self._types = types
        holder: dict[str, str] = {}
        for person in self.people.values():
            holder.update(dict.fromkeys(person.holding, person.id))
        if robot.holding is not None:
            holder[robot.holding] = ROBOT_ID
        self._holder = holder
        objects_ids, people_ids = tuple(self.objects), tuple(self.people)
        self._domains: dict[str, tuple[str, ...]] = {
            "object": objects_ids, "person": people_ids, "room": self.rooms,
            "robot": (ROBOT_ID,), "entity": (ROBOT_ID, *objects_ids, *people_ids),
        }
        self._memo: dict[tuple[str, tuple[str, ...]], FactValue] = {}

    # The Facts protocol.
    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        """The value of a vocabulary symbol applied to ids or literal strings.

        Args:
            symbol: a name in `VOCABULARY`.
            args: entity ids, or literal strings for `string` arguments.

        Returns:
            A bool, float or str, or `Unknown(fact_key(symbol, args))` when not determined.
        """
        memo_key = (symbol, args)
        cached = self._memo.get(memo_key)
        if cached is not None:
            return cached
        plan = _PLANS.get(symbol)
        result: FactValue
        if plan is None or len(args) != plan[1]:
            result = Unknown(fact_key(symbol, args))
        else:
            types = self._types
            for index, accepted in plan[2]:
                if types.get(args[index]) not in accepted:
                    result = Unknown(fact_key(symbol, args))
                    break
            else:
                result = plan[0](self, args)
        self._memo[memo_key] = result
        return result

    def domain(self, type_name: str) -> Sequence[str]:
        """The ids of every entity of a type, in a stable order."""
        return self._domains.get(type_name, ())

    def entity_type(self, entity_id: str) -> str | None:
        """`robot`, `object`, `person` or `room`; None for an id not in the state."""
        return self._types.get(entity_id)

    # Where things are, for the rules and the effects.
    def holder_of(self, object_id: str) -> str | None:
        """The robot or person id holding the object, or None."""
        return self._holder.get(object_id)

    def room_of(self, entity_id: str) -> str | None:
        """The entity's room: its own, else its holder's, else its receptacle's; None if unknown."""
        return self._located(entity_id, _room, of_room=_itself)

    def position_of(self, entity_id: str) -> Point | None:
        """The entity's position: its own, else its holder's, else its receptacle's."""
        return self._located(entity_id, _position)

    def _located(self, entity_id: str, where: Callable[[Placed], _Place | None], *,
                 of_room: Callable[[str], _Place] | None = None) -> _Place | None:
        """`where` of the entity, or of what holds or contains it, up the chain until one is
        known (a room reached on the way answers `of_room` of itself, when given); None at an
        unknown entity or the chain's end."""
        for _ in range(16):  # a receptacle chain deeper than this is a cycle in bad input
            if entity_id == ROBOT_ID:
                return where(self.robot)
            person = self.people.get(entity_id)
            if person is not None:
                return where(person)
            if of_room is not None and self._types.get(entity_id) == "room":
                return of_room(entity_id)
            obj = self.objects.get(entity_id)
            if obj is None:
                return None
            holder = self._holder.get(entity_id)
            if holder is not None:
                entity_id = holder
                continue
            own = where(obj)
            if own is not None or obj.parent is None:
                return own
            entity_id = obj.parent
        return None

    def distance(self, a: str, b: str) -> float | None:
        """Straight-line distance in the floor plane, or None when a position is unknown."""
        if a == b:
            return 0.0
        pa, pb = self.position_of(a), self.position_of(b)
        if pa is None or pb is None:
            return None
        return math.hypot(pa.x - pb.x, pa.y - pb.y)

    def route(self, start: str, goal: str, avoiding: frozenset[str] = frozenset()
              ) -> tuple[str, ...] | None:
        """The rooms from `start` to `goal` by the fewest connections (both ends included),
        never entering a room in `avoiding` (except the ends); None if the layout gives none."""
        if start == goal:
            return (start,)
        came: dict[str, str] = {start: start}
        frontier = [start]
        while frontier:
            following: list[str] = []
            for room in frontier:
                for a, b in sorted(self.connections):
                    if a != room or b in came or (b in avoiding and b != goal):
                        continue
                    came[b] = room
                    if b == goal:
                        path = [b]
                        while path[-1] != start:
                            path.append(came[path[-1]])
                        return tuple(reversed(path))
                    following.append(b)
            frontier = following
        return None

    def fresh_unknown(self, symbol: str, args: Sequence[str]) -> Unknown:
        """An unknown an effect creates, distinct from the same fact's unknown in earlier states."""
        return Unknown(f"{fact_key(symbol, args)}@{self.version + 1}")

    def evolve(self, **changes: Any) -> WorldState:
        """A new state with some fields replaced and the version advanced by one."""
        fields: dict[str, Any] = {
            "robot": self.robot, "objects": self.objects, "people": self.people,
            "rooms": self.rooms, "connections": self.connections, "relations": self.relations,
            "people_known": self.people_known, "version": self.version + 1,
        }
        fields.update(changes)
        return WorldState(**fields)

    def with_object(self, obj: ObjectState) -> WorldState:
        """A new state where `obj` replaces the object with its id."""
        return self.evolve(objects={**self.objects, obj.id: obj})

    @classmethod
    def from_request(cls, request: GateRequest | InitialState) -> WorldState:
        """The state a gate request or initial state describes (see `build.state_from_request`)."""
        from app.domain.world.build import state_from_request

        return state_from_request(request)

    def apply_snapshot(self, snapshot: InitialState) -> WorldState:
        """This state updated by a partial observation (see `build.apply_snapshot`)."""
        from app.domain.world.build import apply_snapshot

        return apply_snapshot(self, snapshot)

    def __repr__(self) -> str:
        return (f"WorldState(robot={self.robot!r}, objects={len(self.objects)}, "
                f"people={len(self.people)}, rooms={self.rooms!r}, version={self.version})")
