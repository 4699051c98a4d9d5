"""Building the induced plan: the moves every schema shares, on a running world state.

In: a `Grounder` (the scene, and the entities the command added to it). Out: `PlanBuilder`, which
the schemas (`schemas.py`) drive: `acquire` (go to an object, open what it is in, free the
gripper, pick it up), `deliver` (hand over or set down beside a person: a `Choice`), `place` (put
it in or on something, opening and closing that), `switch` and the rest. Every literal and
enabling step is applied to a running `WorldState` as it is added, so later steps know what the
robot holds and what is open; clean-up steps (close, switch off, put away) are collected for the
careful variant. Fails: never; a step the action model cannot take in the running state (an id
of the wrong kind) is left out and noted.
"""

from __future__ import annotations

from dataclasses import replace
from types import MappingProxyType
from typing import Any

from app.domain.analysis.grounding import Grounder
from app.domain.analysis.sketch import Choice, GoalFact, Planned, Sketch
from app.domain.errors import PlanError
from app.domain.world import ROBOT_ID, Action, ObjectState, WorldState, step
from app.domain.world.concepts import concept_of
from app.domain.world.entities import frozen_mapping
from app.domain.world.object_types import CONTAINER_TYPES, normalize_type

_ROLLING = ("cart", "trolley", "wheelchair", "pram", "stroller", "wheelie", "buggy")
_SURFACES = ("CounterTop", "DiningTable", "Table", "CoffeeTable", "SideTable", "Desk",
             "Dresser", "Shelf", "TVStand", "Ottoman", "Chair", "Sofa", "Bed")
_CLOSED_STORAGE = frozenset({"fridge", "cabinet", "drawer", "microwave", "oven", "dishwasher",
                             "washingmachine", "box", "safe", "garbagecan", "toaster"})


_PASSAGES = ("hall", "stair", "landing", "corridor", "porch", "entrance", "foyer", "doorway",
             "path", "walkway")


class PlanBuilder:
    """Adds steps to a sketch while keeping the state they lead to."""

    def __init__(self, grounder: Grounder) -> None:
        self.grounder = grounder
        self.state: WorldState = grounder.scene()
        self.sketch = Sketch()
        self.notes: list[str] = []
        self.failed: list[str] = []
        self.clause = 0
        self.ingredients: dict[int, list[str]] = {}
        """What a later specification ("- milk, one sugar") puts in what a clause makes."""
        self._opened: set[str] = set()
        self._switched: set[str] = set()

    # State keeping.
    def sync(self) -> None:
        """Bring entities the grounder added since the last step into the running state."""
        g, s = self.grounder, self.state
        new_objects = {k: v for k, v in g.objects.items() if k not in s.objects}
        for object_id, facts in g.stated.items():
            current = s.objects.get(object_id)
            if current is not None and any(current.properties.get(k) != v
                                           for k, v in facts.items()):
                new_objects[object_id] = replace(current, properties=frozen_mapping(
                    {**current.properties, **facts}))
        new_people = {k: v for k, v in g.people.items() if k not in s.people}
        new_rooms = [r for r in g.rooms if r not in s.rooms]
        if new_objects or new_people or new_rooms:
            self.state = s.evolve(objects={**s.objects, **new_objects},
                                  people={**s.people, **new_people},
                                  rooms=(*s.rooms, *new_rooms))

    def act(self, name: str, obj: str | None = None, target: str | None = None,
            kind: str = "literal", **params: Any) -> bool:
        """Add one step and apply it to the running state; False if it cannot run here. A
        literal step's outcome becomes one of the command's goals."""
        action = Action(name, obj, target, MappingProxyType(dict(params)) if params else
                        MappingProxyType({}))
        try:
            self.state = step(self.state, action)
        except PlanError as error:
            self.notes.append(error.detail)
            if kind == "literal":
                self.failed.append(error.detail)  # the command's own step cannot run here
            return False
        self.sketch.add(action, self.clause, kind)
        if kind == "literal":
            fact = self._outcome(action)
            if fact is not None:
                self.goal(fact)
        return True

    def goal(self, *alternatives: GoalFact) -> None:
        """Record a fact the command asks for (any one of the alternatives)."""
        if alternatives and alternatives not in self.sketch.goals:
            self.sketch.goals.append(alternatives)

    def _outcome(self, action: Action) -> GoalFact | None:
        obj, target = action.object or "", action.target or ""
        simple = {"OpenObject": ("open", True), "CloseObject": ("open", False),
                  "LockObject": ("locked", True), "ToggleObjectOn": ("is_on", True),
                  "ToggleObjectOff": ("is_on", False), "CleanObject": ("dirty", False),
                  "FillWithLiquid": ("filled", True), "SliceObject": ("sliced", True),
                  "BreakObject": ("broken", True), "PlugIn": ("plugged_in", True),
                  "Unplug": ("plugged_in", False), "Cook": ("hot", True)}
        if action.name in simple:
            symbol, value = simple[action.name]
            return symbol, (obj,), value
        if action.name == "PickupObject":
            return "holding", (ROBOT_ID, obj), True
        if action.name == "HandOver":
            return "holding", (target, obj), True
        if action.name == "PutObject":
            return ("inside" if self.relation_for(target) == "in" else "on"), (obj, target), True
        if action.name in ("navigate", "Escort") and self.state.entity_type(target) == "room":
            return "in_room", (obj or ROBOT_ID, target), True
        if action.name in ("ThrowObject", "DropHandObject"):
            return "on_floor", (obj,), True
        if action.name == "Pour" and self.state.entity_type(target) == "object":
            holds = self.state.objects[target].kind.flag("can_fill")
            return ("filled" if holds else "wet"), (target,), True
        return None

    def cleanup(self, name: str, obj: str | None = None, target: str | None = None,
                **params: Any) -> None:
        """A step a careful planner adds at the end (never applied to the running state)."""
        action = Action(name, obj, target, MappingProxyType(dict(params)) if params else
                        MappingProxyType({}))
        if all(p.action != action for p in self.sketch.cleanup):
            self.sketch.cleanup.append(Planned(action, self.clause, "cleanup"))

    def user(self) -> str:
        """The person giving the command, in the running state."""
        user = self.grounder.user_id
        self.sync()
        return user

    # Where things are.
    def holding(self) -> str | None:
        return self.state.robot.holding

    def container_of(self, object_id: str) -> ObjectState | None:
        obj = self.state.objects.get(object_id)
        if obj is None or obj.parent is None or self.state.holder_of(object_id) is not None:
            return None
        return self.state.objects.get(obj.parent)

    def surface(self, room: str | None, avoid: str | None = None) -> str:
        """A surface to set things on in a room (a counter, a table...), made up if none."""
        for wanted in _SURFACES:
            for obj in self.state.objects.values():
                if (obj.kind.name == wanted and obj.id != avoid
                        and (room is None or self.state.room_of(obj.id) == room)):
                    return obj.id
        passage = any(w in normalize_type(room or "") for w in _PASSAGES)
        surface_id = f"new_{'floor' if passage else 'surface'}_{normalize_type(room or 'here')}"
        if surface_id not in self.state.objects:
            # In a hall, on a landing or a stair there is no table: things go on the floor.
            obj = ObjectState(id=surface_id, type="Floor" if passage else "Table", room=room,
                              properties=frozen_mapping({}))
            self.grounder.objects[surface_id] = obj
            self.sync()
        return surface_id

    def find_type(self, *types: str, room: str | None = None) -> str | None:
        """The first object of one of the types (in the room if given), else None."""
        keys = [normalize_type(t) for t in types]
        for key in keys:
            for obj in self.state.objects.values():
                if key in (normalize_type(obj.kind.name), normalize_type(obj.type)) and (
                        room is None or self.state.room_of(obj.id) == room):
                    return obj.id
        return None

    def ensure(self, type_name: str, room: str | None = None) -> str:
        """An object of the type: the scene's, or a new one of that type."""
        found = self.find_type(type_name, room=room) or self.find_type(type_name)
        if found is not None:
            return found
        object_id = f"new_{normalize_type(type_name)}"
        # One the robot takes for the job: empty and clean, like any it would choose.
        self.grounder.objects[object_id] = ObjectState(
            id=object_id, type=type_name, room=room or self.state.robot.room,
            properties=frozen_mapping({"contents": ""}))
        self.sync()
        return object_id

    # Shared moves.
    def go_to(self, entity: str, kind: str = "enabling") -> None:
        if self.state.robot.beside != entity:
            if self.state.entity_type(entity) == "room":
                self.act("navigate", target=entity, kind=kind)
            else:
                self.act("GoToObject", entity, kind=kind)

    def open_if_closed(self, container: ObjectState) -> None:
        key = normalize_type(container.kind.name)
        if key in _CLOSED_STORAGE and self.state.value("open", (container.id,)) is not True:
            self.go_to(container.id)
            if self.act("OpenObject", container.id, kind="enabling"):
                self._opened.add(container.id)
                self.cleanup("CloseObject", container.id)

    def free_hands(self, keep: str | None = None) -> None:
        held = self.holding()
        if held is not None and held != keep:
            self.act("PutObject", held, self.surface(self.state.robot.room, avoid=held),
                     kind="enabling")

    def acquire(self, object_id: str, kind: str = "enabling") -> bool:
        """Go to an object, open what it is in, free the gripper and pick it up."""
        if self.holding() == object_id:
            return True
        if self.state.entity_type(object_id) != "object":
            return False
        holder = self.state.holder_of(object_id)
        container = self.container_of(object_id)
        self.free_hands()
        if container is not None:
            self.open_if_closed(container)
        if holder is None:
            self.go_to(object_id)
        elif holder != ROBOT_ID:
            self.go_to(holder)
        return self.act("PickupObject", object_id, kind=kind)

    def rolls(self, object_id: str) -> bool:
        """A thing moved by pushing (a cart, a trolley, a wheelchair), not by carrying."""
        state = self.state
        if state.entity_type(object_id) != "object":
            return False
        obj = state.objects[object_id]
        words = f"{obj.id} {obj.type} {obj.name or ''}".lower()
        return state.value("pickupable", (object_id,)) is not True and any(
            w in words for w in _ROLLING)

    def push_to(self, object_id: str, target: str) -> None:
        """Push a rolling thing next to a target (a person, an object or a room)."""
        self.go_to(object_id)
        self.act("PushObject", object_id, target)

    def place(self, object_id: str, target: str, kind: str = "literal",
              relation: str | None = None, beside: str | None = None) -> None:
        """Carry a held (or fetched) object to a receptacle and put it there."""
        if self.rolls(object_id):
            self.push_to(object_id, target)
            return
        if not self.acquire(object_id):
            return
        receptacle = self.state.objects.get(target)
        if receptacle is None:
            return
        if normalize_type(receptacle.kind.name) in _CLOSED_STORAGE:
            self.open_if_closed(receptacle)
        self.go_to(target)
        params: dict[str, Any] = {"relation": relation} if relation else {}
        if beside is not None and beside != object_id:
            params["beside"] = beside
        self.act("PutObject", object_id, target, kind=kind, **params)

    def deliver(self, object_id: str, person: str) -> None:
        """Bring an object to a person: hand it over, or set it down beside them (a choice)."""
        if self.rolls(object_id):
            self.push_to(object_id, person)
            return
        if not self.acquire(object_id):
            return
        self.go_to(person)
        if self.state.entity_type(person) == "object":  # a pet: no hand-over or set-down choice
            self.hand_to(object_id, person)
            return
        before = self.state
        room = before.room_of(person)
        surface = self.surface(room)
        handover = (Planned(Action("HandOver", object_id, person), self.clause),)
        set_down = (Planned(Action("GoToObject", surface), self.clause, "enabling"),
                    Planned(Action("PutObject", object_id, surface), self.clause))
        self.sketch.literal.append(Choice((handover, set_down), "hand over or set down"))
        self.goal(("holding", (person, object_id), True), ("on", (object_id, surface), True))
        try:
            self.state = step(before, handover[0].action)
        except PlanError as error:
            self.notes.append(error.detail)

    def hand_to(self, object_id: str, recipient: str) -> None:
        """Give the held object: a person takes it from the hand; a pet takes nothing from a
        hand, so what it is given is set down in front of it."""
        pet = self.state.entity_type(recipient) == "object"
        self.act("PutObject" if pet else "HandOver", object_id, recipient)

    def switch(self, device: str, on: bool, kind: str = "literal") -> None:
        device = self._switched_by(device)
        self.go_to(device)
        if on and normalize_type(self.state.objects[device].kind.name) == "microwave" and \
                self.state.value("open", (device,)) is True:
            self.act("CloseObject", device, kind="enabling")
        if self.act("ToggleObjectOn" if on else "ToggleObjectOff", device, kind=kind) and on:
            self._switched.add(device)
            if not _gives_light(self.state.objects[device].kind.name):
                # A lamp left on harms no one (and darkness can); anything else is stopped.
                self.cleanup("ToggleObjectOff", device)

    def _switched_by(self, device: str) -> str:
        """ "Run the bath", "turn the sink on": a basin is switched by its tap (the one in its
        room, or one the scene leaves out); "leave the stew on low": a pot is switched by the
        burner it stands on; anything else is switched itself."""
        obj = self.state.objects[device]
        kind = normalize_type(obj.kind.name)
        if obj.parent in self.state.objects and self.state.value(
                "heat_source", (obj.parent,)) is True and (
                concept := concept_of(obj.type)) is not None and concept.name == "cookware":
            return obj.parent
        if kind not in _TAP_FILLED or obj.kind.flag("toggleable") is True:
            return device
        room = self.state.room_of(device)
        return self.find_type("Faucet", room=room) or self.ensure("Faucet", room=room)

    def relation_for(self, target: str) -> str:
        receptacle = self.state.objects.get(target)
        return "in" if receptacle is not None and receptacle.kind.name in CONTAINER_TYPES \
            else "on"


_TAP_FILLED = frozenset({"bathtub", "bathtubbasin", "bath", "sink", "sinkbasin", "basin", "tub",
                     "babybath"})


def _gives_light(type_name: str) -> bool:
    """Whether the thing is a light or lamp (not a lighter or a heat lamp)."""
    name = normalize_type(type_name)
    return ("lamp" in name or "light" in name) and not any(
        word in name for word in ("lighter", "heat", "candle"))
