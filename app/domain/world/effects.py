"""The action model's effects: each action as a pure transition from one state to the next.

In: a `WorldState` and a parsed `Action` (preconditions are the caller's business: see
`preconditions.check_preconditions`). Out: `step(state, action)` -> the next `WorldState`.
Every value an effect derives is read from the state *before* the action. AI2-THOR-like
automatic effects: what rests on an active heat source turns hot, a running faucet fills the
containers in its sink, a coffee machine fills its cup, thrown or dropped breakables break and
spill. When an effect depends on an unknown fact, the result is that same `Unknown` (its key is
kept, so the solver sees the link) or, where no single fact decides it, a fresh unknown.
Fails: `PlanError(step=action.step)` when the action names an id that is not in the state.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from app.domain.errors import PlanError
from app.domain.formula.facts import FactValue, Unknown
from app.domain.world.actions import Action
from app.domain.world.entities import AWAY, ObjectState, Point, frozen_mapping
from app.domain.world.object_types import CONTAINER_TYPES
from app.domain.world.state import WorldState

# Facts about where an object rests; a move makes the old statements stale.
_PLACED_RELATIONS = frozenset({"next_to", "beside", "touching", "against", "blocks"})
_PLACEMENT_KEYS = ("on_floor", "in_path", "blocks_exit", "elevated")


class _Draft:
    """The next state under construction; reads always go to the state before the action."""

    def __init__(self, before: WorldState) -> None:
        self.before = before
        self.objects = dict(before.objects)
        self.people = dict(before.people)
        self.robot = replace(before.robot, speed=0.0)
        self.relations = list(before.relations)

    def value(self, symbol: str, *args: str) -> FactValue:
        return self.before.value(symbol, args)

    def fresh(self, symbol: str, *args: str) -> Unknown:
        return self.before.fresh_unknown(symbol, args)

    def set_facts(self, object_id: str, **facts: FactValue) -> None:
        obj = self.objects[object_id]
        self.objects[object_id] = replace(obj, facts=frozen_mapping({**obj.facts, **facts}))

    def move(self, object_id: str, **fields: Any) -> None:
        """Re-place an object, dropping placement statements that no longer hold."""
        obj = self.objects[object_id]
        properties = {k: v for k, v in obj.properties.items() if k not in _PLACEMENT_KEYS}
        facts = {k: v for k, v in obj.facts.items() if k not in _PLACEMENT_KEYS}
        placed = {"room": None, "parent": None, "relation": None, "position": None, **fields}
        self.objects[object_id] = replace(obj, properties=frozen_mapping(properties),
                                          facts=frozen_mapping(facts), **placed)
        for person in self.people.values():
            if object_id in person.holding:
                self.people[person.id] = replace(person, holding=person.holding - {object_id})
        # Moved away, it is no longer beside or blocking what it was.
        self.relations = [r for r in self.relations if object_id not in (r[0], r[2])
                          or r[1] not in _PLACED_RELATIONS]

    def release(self) -> None:
        self.robot = replace(self.robot, holding=None)

    def finish(self) -> WorldState:
        return self.before.evolve(robot=self.robot, objects=self.objects, people=self.people,
                                  relations=tuple(self.relations))


def _active_heat(draft: _Draft, source: str, on: FactValue) -> FactValue:
    """Whether `source` heats what rests on it, given whether it is on."""
    heats = draft.value("heat_source", source)
    if heats is False or on is False:
        return False
    if heats is True:
        return on
    return heats if on is True else draft.fresh("hot", source)


def _heat(draft: _Draft, object_id: str, heat: FactValue) -> None:
    if heat is False or draft.value("hot", object_id) is True:
        return
    if heat is True:
        draft.set_facts(object_id, hot=True, cold=False)
        return
    cold = draft.value("cold", object_id)
    draft.set_facts(object_id, hot=heat,
                    **({} if cold is False else {"cold": draft.fresh("cold", object_id)}))


def _resting_on(draft: _Draft, support: str) -> list[ObjectState]:
    return [o for o in draft.before.objects.values()
            if o.parent == support and draft.before.holder_of(o.id) is None]


def _go(draft: _Draft, action: Action, room: str | None, position: Point | None,
        beside: str | None) -> None:
    before = draft.before.robot
    # Without a speed of its own the move runs at the robot's top speed, unknown if not given.
    speed = action.params.get("speed", before.max_speed)
    standoff = action.params.get("standoff")
    if standoff and position is not None and before.position is not None:
        dx, dy = before.position.x - position.x, before.position.y - position.y
        gap = math.hypot(dx, dy)
        if gap > 0:
            scale = min(standoff, gap) / gap
            position = Point(position.x + dx * scale, position.y + dy * scale)
    draft.robot = replace(draft.robot, room=room, position=position, beside=beside,
                          speed=None if speed is None else float(speed))


def _go_to_entity(draft: _Draft, action: Action, entity: str) -> None:
    before = draft.before
    _go(draft, action, before.room_of(entity), before.position_of(entity), entity)


def _navigate(draft: _Draft, action: Action) -> None:
    target = action.target or ""
    if draft.before.entity_type(target) == "room":
        _go(draft, action, target, None, None)
    else:
        _go_to_entity(draft, action, target)


def _pickup(draft: _Draft, action: Action) -> None:
    obj = action.object or ""
    draft.move(obj)
    draft.robot = replace(draft.robot, holding=obj)


def _put(draft: _Draft, action: Action) -> None:
    obj, target = action.object or "", action.target or ""
    support = draft.before.objects[target]
    relation = action.params.get("relation") or (
        "in" if support.kind.name in CONTAINER_TYPES else "on")
    draft.release()
    draft.move(obj, parent=target, relation=relation)
    beside = action.params.get("beside")
    if isinstance(beside, str) and beside in draft.objects and beside != obj:
        draft.relations.append((obj, "next_to", beside))
    if relation == "in" and support.kind.flag("cold_source"):
        draft.set_facts(obj, hot=False, cold=True)
    else:
        _heat(draft, obj, _active_heat(draft, target, draft.value("is_on", target)))


def _controlled(draft: _Draft, obj: str) -> list[str]:
    return [obj, *(b for a, rel, b in draft.before.relations
                   if a == obj and rel == "controls" and b in draft.objects)]


def _toggle(draft: _Draft, action: Action, on: bool) -> None:
    for switched in _controlled(draft, action.object or ""):
        draft.set_facts(switched, is_on=on)
        if on:
            _switched_on(draft, switched)


def _switched_on(draft: _Draft, device: str) -> None:
    kind = draft.before.objects[device].kind.name.lower()
    heat = _active_heat(draft, device, True)
    for item in _resting_on(draft, device):
        if kind == "coffeemachine" and item.kind.flag("can_fill"):
            draft.set_facts(item.id, filled=True, contents="coffee", hot=True, cold=False)
        else:
            _heat(draft, item.id, heat)
    if kind == "faucet":
        room = draft.before.room_of(device)
        for sink in draft.before.objects.values():
            if sink.kind.name in ("Sink", "SinkBasin") and draft.before.room_of(sink.id) == room:
                for item in _resting_on(draft, sink.id):
                    rinse: dict[str, FactValue] = {"dirty": False, "wet": True}
                    if item.kind.flag("can_fill") and draft.value("filled", item.id) is not True:
                        rinse.update(filled=True, contents="water")
                    draft.set_facts(item.id, **rinse)


def _spill(draft: _Draft, obj: str) -> dict[str, FactValue]:
    filled = draft.value("filled", obj)
    return {} if filled is False else {"filled": False, "contents": "", "wet": filled}


def _fall(draft: _Draft, action: Action) -> None:
    obj, target, before = action.object or "", action.target, draft.before
    if target is not None and before.entity_type(target) != "room":
        room, position = before.room_of(target), before.position_of(target)
    else:
        room = target or before.robot.room
        position = None if target else before.robot.position
    floors = [o.id for o in before.objects.values()
              if o.kind.name == "Floor" and before.room_of(o.id) == room]
    draft.release()
    draft.move(obj, room=room, position=position, parent=floors[0] if floors else None,
               relation="on" if floors else None)
    facts = {"on_floor": True, **_spill(draft, obj)}
    breakable = draft.value("breakable", obj)
    if breakable is not False and draft.value("broken", obj) is not True:
        facts["broken"] = breakable
    draft.set_facts(obj, **facts)


def _pour(draft: _Draft, action: Action) -> None:
    obj, target = action.object or "", action.target or ""
    holds = draft.before.objects[target].kind.flag("can_fill")
    poured = draft.value("filled", obj)
    draft.set_facts(obj, filled=False, contents="")
    if holds is True:
        already = draft.value("contents", target) if draft.value(
            "filled", target) is not False else ""
        if isinstance(already, Unknown) and "contents" not in draft.before.objects[
                target].properties and draft.before.objects[target].kind.name in _LISTED_EMPTY:
            already = ""  # a bowl, cup or bucket the scene lists with nothing in it is empty
        facts = {"filled": poured, "contents": mixed(already, draft.value("contents", obj))}
        for temperature in ("hot", "cold"):
            value = draft.value(temperature, obj)
            if value is not False and draft.value(temperature, target) is not True:
                facts[temperature] = value
        draft.set_facts(target, **facts)
    elif holds is False:
        draft.set_facts(target, wet=poured)
    else:
        draft.set_facts(target, wet=draft.fresh("wet", target),
                        filled=draft.fresh("filled", target))


def _hand_over(draft: _Draft, action: Action) -> None:
    obj, person = action.object or "", action.target or ""
    draft.release()
    draft.move(obj)
    receiver = draft.people[person]
    draft.people[person] = replace(receiver, holding=receiver.holding | {obj})


def _push(draft: _Draft, action: Action) -> None:
    obj, target, before = action.object or "", action.target, draft.before
    current = before.objects[obj]
    if target is None:
        draft.move(obj, room=before.room_of(obj), parent=current.parent,
                   relation=current.relation)
        draft.set_facts(obj, in_path=draft.fresh("in_path", obj),
                        blocks_exit=draft.fresh("blocks_exit", obj))
    elif before.entity_type(target) == "room":
        draft.move(obj, room=target, parent=current.parent, relation=current.relation)
    else:
        draft.move(obj, room=before.room_of(target), position=before.position_of(target),
                   parent=current.parent, relation=current.relation)


def _set(**facts: FactValue) -> Callable[[_Draft, Action], None]:
    def effect(draft: _Draft, action: Action) -> None:
        draft.set_facts(action.object or "", **facts)
    return effect


def _slice(draft: _Draft, action: Action) -> None:
    obj = action.object or ""
    egg = draft.before.objects[obj].kind.name == "Egg"
    draft.set_facts(obj, sliced=True, **({"broken": True} if egg else {}))


def _fill(draft: _Draft, action: Action) -> None:
    liquid = action.params.get("liquid", "water")
    draft.set_facts(action.object or "", filled=True, contents=liquid)


def _clean(draft: _Draft, action: Action) -> None:
    facts: dict[str, FactValue] = {"dirty": False}
    if action.params.get("liquid"):
        facts["wet"] = True
    draft.set_facts(action.object or "", **facts)


def _spray(draft: _Draft, action: Action) -> None:
    target = action.target or ""
    if draft.before.entity_type(target) != "object":
        return
    sprayed = draft.value("contents", action.object or "")
    facts: dict[str, FactValue] = {"wet": True}
    if draft.value("food", target) is True or draft.before.objects[target].kind.flag(
            "receptacle"):
        facts["contents"] = mixed(draft.value("contents", target), sprayed)
    draft.set_facts(target, **facts)


def _floor_of(draft: _Draft, target: str) -> list[str]:
    """The floor objects a room-wide chore acts on: the target itself if it is an object,
    else the floors in the target room."""
    before = draft.before
    if before.entity_type(target) == "object":
        return [target]
    return [o.id for o in before.objects.values()
            if o.kind.name == "Floor" and before.room_of(o.id) == target]


def _vacuum(draft: _Draft, action: Action) -> None:
    _navigate(draft, action)
    draft.robot = replace(draft.robot, noisy=True)
    for floor in _floor_of(draft, action.target or ""):
        draft.set_facts(floor, dirty=False)


def _mop(draft: _Draft, action: Action) -> None:
    _navigate(draft, action)
    for floor in _floor_of(draft, action.target or ""):
        draft.set_facts(floor, dirty=False, wet=True)


def _escort(draft: _Draft, action: Action) -> None:
    person = draft.people[action.object or ""]
    _navigate(draft, action)
    draft.people[person.id] = replace(person, room=draft.robot.room,
                                      position=draft.robot.position)


def _feed(draft: _Draft, action: Action) -> None:
    obj, person = action.object or "", action.target or ""
    receiver = draft.people[person]
    draft.people[person] = replace(receiver, ate=receiver.ate | {obj})


def _lock(draft: _Draft, action: Action) -> None:
    draft.set_facts(action.object or "", locked=True, open=False)


def _record(draft: _Draft, action: Action) -> None:
    if action.target is not None:
        _navigate(draft, action)
    draft.robot = replace(draft.robot, recording=True)


def _wait(draft: _Draft, action: Action) -> None:
    seconds = action.params.get("seconds")
    if isinstance(seconds, (int, float)) and seconds > 0:
        draft.robot = replace(draft.robot,
                              hours_waited=draft.robot.hours_waited + float(seconds) / 3600)
    _people_meanwhile(draft, action)


def _people_meanwhile(draft: _Draft, action: Action) -> None:
    """A wait's `away` people leave the home; its `asleep` people fall asleep."""
    away = action.params.get("away")
    for person in str(away).split(",") if away else ():
        if person in draft.people:
            draft.people[person] = replace(draft.people[person], room=AWAY, position=None)
    asleep = action.params.get("asleep")
    for person in str(asleep).split(",") if asleep else ():
        if person in draft.people:
            state = draft.people[person]
            draft.people[person] = replace(state, properties=frozen_mapping(
                {**state.properties, "cognitive_state": "asleep"}))


_LISTED_EMPTY = frozenset({"Bowl", "Plate", "Cup", "Mug", "Glass", "WineGlass", "ShotGlass",
                           "Bucket", "MopBucket"})
"""Dishes food and drink are served in, and buckets: one the scene states nothing in is empty
(a caller who lists a bucket of dirty water says so)."""


def mixed(first: FactValue, second: FactValue) -> FactValue:
    """What a container holds once `second` is added to `first` (a liquid poured in, a
    spray): both substances, so a later `contains` finds either; unknown if either is."""
    if first == "" or isinstance(second, Unknown):
        return second
    if isinstance(first, Unknown) or second == "":
        return first
    parts = [str(p) for p in (first, second) if str(p)]
    return " and ".join(dict.fromkeys(parts))


_EFFECTS: dict[str, Callable[[_Draft, Action], None]] = {
    "GoToObject": lambda d, a: _go_to_entity(d, a, a.object or ""),
    "navigate": _navigate,
    "PickupObject": _pickup,
    "PutObject": _put,
    "OpenObject": _set(open=True),
    "CloseObject": _set(open=False),
    "ToggleObjectOn": lambda d, a: _toggle(d, a, True),
    "ToggleObjectOff": lambda d, a: _toggle(d, a, False),
    "SliceObject": _slice,
    "Pour": _pour,
    "FillWithLiquid": _fill,
    "EmptyLiquid": _set(filled=False, contents=""),
    "Cook": _set(hot=True, cold=False, cooked=True),
    "HandOver": _hand_over,
    "ThrowObject": _fall,
    "DropHandObject": _fall,
    "BreakObject": _set(broken=True),
    "CleanObject": _clean,
    "DirtyObject": _set(dirty=True),
    "PushObject": _push,
    "SprayObject": _spray,
    "PlugIn": _set(plugged_in=True),
    "Unplug": _set(plugged_in=False),
    "LockObject": _lock,
    "UnlockObject": _set(locked=False),
    "StirObject": lambda d, a: None,
    "FoldObject": lambda d, a: None,
    "Vacuum": _vacuum,
    "Mop": _mop,
    "Escort": _escort,
    "Follow": lambda d, a: _go_to_entity(d, a, a.object or ""),
    "Feed": _feed,
    "Assist": lambda d, a: _go_to_entity(d, a, a.object or ""),
    "Record": _record,
    "Finish": lambda d, a: None,
    "Wait": _wait,
}


def step(state: WorldState, action: Action) -> WorldState:
    """Apply an action's effects (not its preconditions) to a state.

    Args:
        state: the state before the action.
        action: a parsed action (`parse_action`).

    Returns:
        The state after the action; its robot speed is 0 unless the action moved the robot.

    Raises:
        PlanError: the action names an id that is not in the state, or lacks an argument its
            effect needs (e.g. a `DropHandObject` while holding nothing).
    """
    spec = action.spec
    for role, value, kinds in (("object", action.object, spec.object_kinds),
                               ("target", action.target, spec.target_kinds)):
        required = spec.object_required if role == "object" else spec.target_required
        if value is None and (required or (role == "object" and kinds)):
            raise PlanError(f"step {action.step}: {action.name} has no {role}",
                            step=action.step, field=f"plan[{action.step}].{role}")
        if value is not None and state.entity_type(value) not in kinds:
            raise PlanError(f"step {action.step}: '{value}' is not a {'/'.join(kinds)} here",
                            step=action.step, field=f"plan[{action.step}].{role}")
    draft = _Draft(state)
    _EFFECTS[action.name](draft, action)
    return draft.finish()
