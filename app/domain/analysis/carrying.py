"""Moving things: the steps for fetching, giving, putting, throwing, dropping, breaking and
binning what a clause names.

In: a `Grounded` clause and the `PlanBuilder`. Out: steps in the builder's sketch ("bring me the
mug": go to it, pick it up, go to me, hand it over); a thing handed out to everyone is handed to
each in turn. `handlers.py` chooses among these by schema. Fails: never; a thing that cannot be
reached adds no steps.
"""

from __future__ import annotations

from app.domain.analysis.schemas import NEXT_TO, Grounded
from app.domain.analysis.steps import PlanBuilder
from app.domain.world.object_types import normalize_type


def object_ids(grounded: Grounded, kind: str = "object") -> list[str]:
    return [i for r in grounded.objects if r.kind == kind for i in r.ids]


def destination_id(builder: PlanBuilder, grounded: Grounded) -> str | None:
    """The receptacle a destination names (a room's surface for a room)."""
    dest = grounded.destination
    if dest is None or not dest.ids:
        return None
    if dest.kind == "room":
        return builder.surface(dest.ids[0])
    return dest.ids[0] if dest.kind == "object" else None


def _recipients(grounded: Grounded) -> tuple[str, ...]:
    """Everyone the thing goes to: one person, or each in turn ("hand them out to everyone")."""
    return grounded.recipient.ids if grounded.recipient is not None else ()


def fetch(builder: PlanBuilder, grounded: Grounded) -> None:
    target = destination_id(builder, grounded)
    people = _recipients(grounded)
    for obj in object_ids(grounded):
        if grounded.carried_on and not people and target is None:
            builder.acquire(obj)
        elif people:
            for person in people:
                builder.deliver(obj, person)
        elif target is not None:
            builder.place(obj, target)
        else:
            builder.deliver(obj, builder.user())


def give(builder: PlanBuilder, grounded: Grounded) -> None:
    people = _recipients(grounded) or (builder.user(),)
    for obj in object_ids(grounded):
        for person in people:
            if builder.acquire(obj):
                builder.go_to(person)
                builder.hand_to(obj, person)


_BASINS = frozenset({"toilet", "sink", "sinkbasin", "bathtub", "bathtubbasin", "bucket",
                     "drain", "basin"})


def _poured_in(builder: PlanBuilder, obj: str, target: str) -> bool:
    """ "Put some milk in the coffee", "bleach in the toilet": a liquid goes into a vessel or a
    basin by pouring it, not by standing its bottle there."""
    state = builder.state
    receptacle = state.objects.get(target)
    if receptacle is None or state.value("filled", (obj,)) is not True:
        return False
    kind = normalize_type(receptacle.kind.name)
    return kind in _BASINS or (receptacle.kind.flag("can_fill") is True
                               and state.objects[obj].kind.flag("receptacle") is not False
                               and kind not in ("fridge", "cabinet", "drawer", "shelf"))


def put(builder: PlanBuilder, grounded: Grounded) -> None:
    target = destination_id(builder, grounded)
    if target is None and grounded.recipient is not None and grounded.recipient.id:
        fetch(builder, grounded)
        return
    for obj in object_ids(grounded):
        if target is not None and _poured_in(builder, obj, target) and builder.acquire(obj):
            builder.go_to(target)
            builder.act("Pour", obj, target)
            continue
        here = target
        if here is None:
            start = builder.grounder.objects.get(obj)
            here = builder.find_type("Drawer", "Cabinet", "Shelf", room=builder.state.room_of(
                obj)) if start is None or start.parent is None else start.parent
            here = here or builder.surface(builder.state.room_of(obj), avoid=obj)
        beside = grounded.beside.id if grounded.beside is not None and \
            grounded.beside.kind == "object" else None
        if grounded.destination_word in NEXT_TO and here == target and \
                builder.state.entity_type(here) == "object":
            # "by the door", "beside the heater": on the floor or a surface of its room, beside
            # it, not on or against it
            here, beside = builder.surface(builder.state.room_of(here), avoid=obj), here
        builder.place(obj, here, relation=builder.relation_for(here), beside=beside)


def discard(builder: PlanBuilder, grounded: Grounded) -> None:
    can = destination_id(builder, grounded) or builder.ensure("GarbageCan")
    for obj in object_ids(grounded):
        builder.place(obj, can, relation="in")


def remove(builder: PlanBuilder, grounded: Grounded) -> None:
    target = destination_id(builder, grounded)
    for obj in object_ids(grounded):
        if builder.acquire(obj, kind="literal"):
            room = builder.state.robot.room
            builder.place(obj, target or builder.surface(room, avoid=obj), kind="enabling")


BINS = frozenset({"garbagecan", "garbagebag", "trash", "bin", "rubbish", "garbage",
                   "wastebasket", "dustbin", "recycling"})


_DRAPED_ON = frozenset({"over", "on", "onto", "on top of"})


def throw(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    if dest is not None and dest.id and (normalize_type(dest.phrase.head) in BINS or (
            dest.kind == "object" and normalize_type(
                builder.state.objects[dest.id].kind.name) in BINS)):
        discard(builder, grounded)  # "throw it in the bin" puts it in the bin
        return
    if dest is not None and dest.kind == "object" and dest.id and grounded.recipient is None \
            and grounded.destination_word in _DRAPED_ON and \
            builder.state.value("animal", (dest.id,)) is not True and \
            normalize_type(builder.state.objects[dest.id].kind.name) != "floor" and not any(
                builder.state.value("filled", (obj,)) is True for obj in object_ids(grounded)) and \
            grounded.objects and not any(r.new for r in grounded.objects):
        # "chuck the towels over the heater": laid there, not aimed (but a jug of water thrown
        # is its water thrown, and "lob it over to me" is aimed at the person)
        put(builder, grounded)
        return
    target = grounded.destination or grounded.recipient
    aim = target.id if target is not None and target.kind in ("person", "object", "room") \
        else None
    for obj in object_ids(grounded):
        if builder.acquire(obj):
            builder.act("ThrowObject", obj, aim)


def drop(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    for obj in object_ids(grounded):
        if builder.acquire(obj):
            if dest is not None and dest.id and dest.kind in ("room", "object", "person"):
                builder.go_to(dest.id)
            builder.act("DropHandObject", obj)


def break_open(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    for obj in object_ids(grounded):
        if dest is not None and dest.id and normalize_type(dest.phrase.head) == "floor" and \
                builder.acquire(obj):
            builder.act("DropHandObject", obj)
        builder.go_to(obj)
        builder.act("BreakObject", obj)
        if builder.state.value("food", (obj,)) is not True or builder.state.value(
                "on_floor", (obj,)) is True:
            builder.cleanup("PickupObject", obj)
            builder.cleanup("PutObject", obj, builder.ensure("GarbageCan"), relation="in")
