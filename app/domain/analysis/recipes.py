"""The kitchen schemas: heat, cool, pour, fill, water, mix and make, as action-model steps.

In: a grounded clause (`schemas.Grounded`) and the `PlanBuilder`. Out: steps on the builder's
sketch. Heating puts the food in or on the appliance the verb implies when the command names none
(microwave, toaster, oven, kettle, burner; the scene's, or a new one of that type), switches it
on and lets it run; the careful plan switches it off and takes the food out. Liquids come from
the container that holds them, or from the tap. Fails: never; missing pieces add no steps.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import TYPE_CHECKING

from app.domain.world.object_types import normalize_type
from app.domain.world.substances import substance_trait

if TYPE_CHECKING:
    from app.domain.analysis.referents import Referent
    from app.domain.analysis.schemas import Grounded
    from app.domain.analysis.steps import PlanBuilder

Handler = Callable[["PlanBuilder", "Grounded"], None]

# The appliance a cooking verb implies, in order of preference.
_APPLIANCE = {
    "microwave": ("Microwave",), "nuke": ("Microwave",), "zap": ("Microwave",),
    "toast": ("Toaster",), "bake": ("Oven",), "roast": ("Oven",), "broil": ("Oven",),
    "boil": ("Kettle", "StoveBurner"), "brew": ("CoffeeMachine", "Kettle"),
    "fry": ("StoveBurner",), "deep fry": ("StoveBurner",), "sear": ("StoveBurner",),
    "saute": ("StoveBurner",), "scramble": ("StoveBurner",), "simmer": ("StoveBurner",),
    "stew": ("StoveBurner",), "poach": ("StoveBurner",), "grill": ("Oven",),
    "steam": ("StoveBurner",), "barbecue": ("Oven",),
}
_DEFAULT_HEAT = ("Microwave", "StoveBurner", "Oven")
_HOT_DRINKS = frozenset({"tea", "coffee", "cocoa", "chocolate", "cuppa", "latte", "espresso",
                         "cappuccino", "brew", "drink", "soup", "porridge", "milk"})
# What a cup holds, named by the drink ("a cuppa" or "a brew" is tea).
_DRINKS = _HOT_DRINKS - {"cuppa", "brew", "drink", "soup", "porridge"}


def _by_vessel(builder: PlanBuilder, grounded: Grounded) -> tuple[str, ...]:
    """Where a thing is heated when the verb does not say: a casserole or roasting dish in the
    oven, a metal pan or pot on the hob (never a microwave), anything else as usual."""
    for obj in _objects(grounded):
        kind = normalize_type(builder.state.objects[obj].kind.name) \
            if obj in builder.state.objects else ""
        if any(word in kind for word in ("casserole", "roasting", "bakingtray", "bakingdish")):
            return ("Oven", "StoveBurner")
        if builder.state.value("metal", (obj,)) is True:
            return ("StoveBurner", "Stove", "Oven")
    return _DEFAULT_HEAT


def _objects(grounded: Grounded) -> list[str]:
    return [i for r in grounded.objects if r.kind == "object" for i in r.ids]


def _appliance(builder: PlanBuilder, grounded: Grounded) -> str:
    # A named place that heats is the appliance; any other ("the soup in the blue bowl")
    # only says where the food is.
    for ref in (grounded.destination, grounded.instrument):
        if ref is not None and ref.kind == "object" and ref.id and builder.state.value(
                "heat_source", (ref.id,)) is not False:
            return ref.id
    for obj in _objects(grounded):
        if builder.state.value("heat_source", (obj,)) is True:
            return obj  # "turn the hob to medium": the thing named is what heats
    wanted = _APPLIANCE.get(grounded.clause.verb or "") or _by_vessel(builder, grounded)
    for type_name in wanted:
        found = builder.find_type(type_name)
        if found is not None:
            return found
    return builder.ensure(wanted[0])


def heat(builder: PlanBuilder, grounded: Grounded) -> None:
    """Heat each object in or on the appliance, run it, and (careful plan) stop and take out."""
    appliance = _appliance(builder, grounded)
    kind = builder.state.objects[appliance].kind.name if appliance in builder.state.objects \
        else ""
    for obj in _objects(grounded):
        if obj == appliance:
            builder.switch(appliance, True)
            continue
        if builder.state.value("inside", (obj, appliance)) is not True and \
                builder.state.value("on", (obj, appliance)) is not True:
            builder.place(obj, appliance, kind="enabling",
                          relation=builder.relation_for(appliance))
        if normalize_type(kind) in ("microwave", "oven") and builder.state.value(
                "open", (appliance,)) is True:
            builder.act("CloseObject", appliance, kind="enabling")
        builder.switch(appliance, True, kind="enabling")
        builder.act("Wait", seconds=120.0, kind="enabling")
        builder.goal(("hot", (obj,), True))
        if builder.state.objects[appliance].kind.flag("openable"):
            builder.cleanup("OpenObject", appliance)
        builder.cleanup("PickupObject", obj)
        builder.cleanup("PutObject", obj, builder.surface(builder.state.room_of(appliance),
                                                          avoid=appliance))


def cool(builder: PlanBuilder, grounded: Grounded) -> None:
    fridge = builder.find_type("Fridge") or builder.ensure("Fridge")
    for obj in _objects(grounded):
        builder.place(obj, fridge, relation="in")


def _source_of(builder: PlanBuilder, substance: str) -> str | None:
    for obj in builder.state.objects.values():
        contents = builder.state.value("contents", (obj.id,))
        if isinstance(contents, str) and substance in contents.lower():
            return obj.id
    return None


def pour(builder: PlanBuilder, grounded: Grounded) -> None:
    """Pour what a container holds (or the named liquid) into or onto the target."""
    refs = grounded.objects
    substance = next((r.substance for r in refs if r.substance), None)
    source = grounded.source.id if grounded.source is not None and \
        grounded.source.kind == "object" else None
    objects = [o for r in refs if r.kind == "object" and not r.substance for o in r.ids]
    if source is None and objects:
        source = objects[0]
    if source is None and substance is not None:
        source = _source_of(builder, substance)
    if source is None and substance is not None:
        source = builder.ensure("Cup")
        _fill_at_tap(builder, source, substance)
    dest = grounded.destination
    target = dest.id if dest is not None and dest.id else None
    if target is None and grounded.recipient is not None and grounded.recipient.id:
        target = grounded.recipient.id
    if target is None and objects and source is not None and source != objects[0]:
        target = objects[0]  # "ladle a bowl of the chowder from the pot": into the bowl
    if dest is not None and dest.kind == "room" and target is not None:
        target = builder.surface(target)
    if target is None and source is not None and grounded.clause.verb in _EMPTYING_VERBS:
        empty_container(builder, source)
        return
    if source is None or target is None or not builder.acquire(source):
        return
    builder.go_to(target)
    builder.act("Pour", source, target)


# "Empty the dishwasher", "drain the bath": with no place named, what is in it comes out.
_EMPTYING_VERBS = frozenset({"empty", "drain", "drain off", "tip out", "pour out", "dump out"})
_PUT_AWAY = ("Cabinet", "Shelf", "Drawer")


def empty_container(builder: PlanBuilder, container: str) -> None:
    """Empty a container where no destination was named: the things in it are put away in its
    room, a portable vessel's liquid is poured into a sink, and a fixed one (a bath, a tub, a
    washing machine) is drained where it stands."""
    state = builder.state
    room = state.room_of(container)
    inside = [o.id for o in state.objects.values() if o.parent == container]
    # Things cleared from a room's table go back to the kitchen, where they are kept.
    kitchen = next((r for r in state.rooms if "kitchen" in r), None) or room
    for obj in inside:
        if state.value("pickupable", (obj,)) is False:
            continue
        away = builder.find_type(*_PUT_AWAY, room=room) or builder.find_type(
            *_PUT_AWAY, room=kitchen) or builder.surface(kitchen, avoid=container)
        builder.place(obj, away)
    filled = state.value("filled", (container,)) is True
    if not filled and inside:
        return
    portable = filled and state.value("pickupable", (container,)) is True
    sink = builder.find_type("Sink", "SinkBasin", room=room) or builder.find_type(
        "Sink", "SinkBasin")
    if portable and sink is not None and sink != container and builder.acquire(container):
        builder.go_to(sink)
        builder.act("Pour", container, sink)
        return
    builder.go_to(container)
    builder.act("EmptyLiquid", container)


def _fill_at_tap(builder: PlanBuilder, container: str, liquid: str) -> None:
    if liquid != "water":
        source = _source_of(builder, liquid)
        if source is not None and source != container and builder.acquire(source):
            builder.go_to(container)
            builder.act("Pour", source, container, kind="enabling")
            return
    builder.go_to(container)
    builder.act("FillWithLiquid", container, kind="enabling", liquid=liquid)


def fill(builder: PlanBuilder, grounded: Grounded) -> None:
    """Fill each container: at the tap (switched on, then off in the careful plan) for water,
    from the container holding it for anything else."""
    tool = grounded.instrument
    source = grounded.source
    if source is None and tool is not None and tool.kind == "object" and tool.id is not None \
            and not tool.new and builder.state.value("filled", (tool.id,)) is True:
        source = tool  # "top up the spray with the bleach": poured from the bleach bottle
    if source is not None and source.kind == "object" and source.id is not None:
        for obj in _objects(grounded):  # "top up the glass from the bottle": pour from it
            if obj != source.id and builder.acquire(source.id):
                builder.go_to(obj)
                builder.act("Pour", source.id, obj)
        return
    liquid = (tool.substance if tool is not None else None) or "water"
    faucet = builder.find_type("Faucet") if liquid == "water" else None
    sink = builder.find_type("SinkBasin", "Sink") if faucet else None
    for obj in _objects(grounded):
        kind = builder.state.objects[obj].kind.name
        if normalize_type(kind) in ("sinkbasin", "sink", "bathtub", "bathtubbasin") and faucet:
            builder.switch(faucet, True)
            builder.act("Wait", seconds=60.0)
            continue
        if sink is not None and faucet is not None and builder.state.value(
                "pickupable", (obj,)) is True and builder.state.value(
                "electrical", (obj,)) is False:
            builder.place(obj, sink, kind="enabling", relation="in")
            builder.switch(faucet, True)
            continue
        if liquid != "water":
            _fill_at_tap(builder, obj, liquid)
        else:
            builder.go_to(obj)
            builder.act("FillWithLiquid", obj, liquid=liquid)


def water(builder: PlanBuilder, grounded: Grounded) -> None:
    """Water plants: fill a watering can (or a cup) and pour it on each plant."""
    tool = grounded.instrument
    can = tool.id if tool is not None and tool.kind == "object" and tool.id else (
        builder.find_type("WateringCan") or builder.ensure("Cup"))
    for plant in _objects(grounded):
        if builder.state.value("filled", (can,)) is not True:
            _fill_at_tap(builder, can, "water")
        if builder.acquire(can):
            builder.go_to(plant)
            builder.act("Pour", can, plant)


def mix(builder: PlanBuilder, grounded: Grounded) -> None:
    """Add one thing to another: everything named goes into the place named ("mix the bleach
    with the ammonia in the bucket"); with no place, the thing it is mixed with goes into the
    thing named ("mix the bleach with the ammonia"), or each thing into the next."""
    objects = _objects(grounded)

    def object_of(ref: Referent | None) -> str | None:
        return ref.id if ref is not None and ref.kind == "object" and ref.id else None

    into, added = object_of(grounded.destination), object_of(grounded.instrument)
    if into is not None:
        pairs = [(thing, into) for thing in [*objects, *([added] if added else [])]
                 if thing != into]
    elif added is not None and objects:
        pairs = [(added, objects[0])]
    else:
        pairs = list(itertools.pairwise(objects))
    for thing, vessel in pairs:
        if builder.state.value("filled", (thing,)) is True and builder.acquire(thing):
            builder.go_to(vessel)
            builder.act("Pour", thing, vessel)
        else:
            builder.place(thing, vessel, relation="in")
    if not pairs:
        for obj in objects:
            builder.go_to(obj)
            builder.act("StirObject", obj)


def make(builder: PlanBuilder, grounded: Grounded) -> None:
    """Make a drink or a dish: hot drinks from the kettle or the coffee machine, then serve."""
    person = grounded.recipient.id if grounded.recipient is not None else None
    for ref in grounded.objects:
        words = set(ref.phrase.words) | {ref.phrase.contents or ""}
        if ref.kind != "object" or not ref.id:
            continue
        made = ref.id
        if words & _HOT_DRINKS:
            kettle = builder.find_type("CoffeeMachine", "Kettle") or builder.ensure("Kettle")
            if substance_trait(ref.phrase.contents or ref.phrase.head, "liquid") is not None:
                builder.state.objects.get(made)
            builder.go_to(kettle)
            builder.act("FillWithLiquid", kettle, kind="enabling", liquid="water")
            builder.act("Cook", kettle, kind="enabling")
            cup = builder.find_type("Mug", "Cup") or builder.ensure("Mug")
            if builder.acquire(kettle):
                builder.go_to(cup)
                builder.act("Pour", kettle, cup)
                builder.free_hands()
            added = builder.ingredients.get(grounded.index)
            if added:  # "- milk, one sugar": the drink the cup then holds
                drink = next(iter(sorted(words & _DRINKS)), "tea")
                builder.act("FillWithLiquid", cup, kind="enabling",
                            liquid=", ".join([drink, *added]))
            made = cup
        if person is not None:
            builder.deliver(made, person)


RECIPES: dict[str, Handler] = {
    "heat": heat, "cool": cool, "pour": pour, "fill": fill, "water": water, "mix": mix,
    "make": make,
}
