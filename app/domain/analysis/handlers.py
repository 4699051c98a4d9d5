"""The steps of the action model each schema asks for, added to the plan builder's sketch.

In: a `Grounded` clause (from `schemas.py`: its schema and what its words name) and the
`PlanBuilder`. Out: steps in the builder's sketch ("put the cup in the sink": go to the cup,
pick it up, go to the sink, put it in). The kitchen recipes (heat, pour, fill, water, make) live
in `recipes.py`. Fails: never; a handler whose arguments do not fit adds no steps, and
`understanding.py` then reports the clause as not understood.
"""

from __future__ import annotations

import re

from app.domain.analysis.carrying import (
    BINS,
    break_open,
    destination_id,
    discard,
    drop,
    fetch,
    give,
    object_ids,
    put,
    remove,
    throw,
)
from app.domain.analysis.phrases import TIME_UNITS
from app.domain.analysis.recipes import RECIPES, empty_container
from app.domain.analysis.schemas import DECLARED_SCHEMAS, Grounded
from app.domain.analysis.steps import PlanBuilder
from app.domain.world.object_types import CONTAINER_TYPES, normalize_type

_WET_CLEANING = frozenset({"wash", "rinse", "scrub", "mop up", "wash up", "rinse out", "scour",
                           "disinfect", "descale", "degrease", "clean out", "hose", "hose down",
                           "hose off"})


def apply_clause(builder: PlanBuilder, grounded: Grounded) -> None:
    """Add the steps of one grounded clause to the builder's sketch."""
    builder.clause = grounded.index
    schema = grounded.schema
    if schema is None or grounded.clause.negated:
        return
    handler = _HANDLERS.get(schema) or RECIPES.get(schema)
    if grounded.into_hands and schema in ("put", "fetch", "give", "pick"):
        handler = give  # "straight into his hands": handed over, not set down beside him
    along = grounded.instrument
    if along is not None and normalize_type(along.phrase.head or "") in BINS | {"bins"} and \
            (grounded.clause.verb or "").split()[0] in ("put", "take", "leave", "stick"):
        handler = discard  # "put the wallet out with the recycling": thrown out
    if schema == "put" and _timed_in_a_cooker(builder, grounded):
        handler = RECIPES["heat"]  # "stick the curry in the microwave for two minutes"
    before = len(builder.sketch.literal)
    if handler is not None and _container_task(builder, grounded):
        handler = None
    if handler is not None:
        handler(builder, grounded)
    dest = grounded.destination
    if len(builder.sketch.literal) == before and not grounded.objects and dest is not None \
            and dest.ids and dest.kind == "room" and schema in ("fetch", "go", "pick"):
        builder.go_to(dest.ids[0], kind="literal")  # "run out to the garage": go there


_A_WHILE = re.compile(r"\b(?:\d+|a|one|two|three|four|five|six|ten|a couple of|a few)\s*"
                      r"(?:mins?|minutes?|secs?|seconds?)\b")
_COOKERS = frozenset({"microwave", "oven", "toaster", "toasteroven", "airfryer", "grill",
                      "stoveburner", "stove", "hob", "slowcooker", "ricecooker"})


def _timed_in_a_cooker(builder: PlanBuilder, grounded: Grounded) -> bool:
    """Put in a cooking appliance for a length of time: the appliance is run for it."""
    spell = grounded.clause.role("for")
    dest = grounded.destination
    timed = (spell is not None and (spell.head or "") in TIME_UNITS) or bool(
        _A_WHILE.search(grounded.clause.text))
    if not timed or dest is None or not dest.ids:
        return False
    appliance = builder.state.objects.get(dest.ids[0])
    return appliance is not None and normalize_type(appliance.kind.name) in _COOKERS


# Verbs whose object is the container a task fills or empties ("load the dishwasher",
# "unpack the shopping bag"), not the thing moved.
_FILLING = frozenset({"load", "pack", "stock", "restock"})
_EMPTYING = frozenset({"unload", "unpack", "empty", "empty out", "clear out", "clear",
                       "clear off", "clear away", "strip"})


def _container_task(builder: PlanBuilder, grounded: Grounded) -> bool:
    """Load or empty a receptacle named as the object, when no destination is named. A fixed
    receptacle (a dishwasher, a table) is never lifted; a portable one is emptied only by a verb
    that says so ("unpack the bag"), since "clear the plates" moves the plates."""
    verb = grounded.clause.verb
    ids = object_ids(grounded)
    if grounded.destination is not None or not ids or verb not in _FILLING | _EMPTYING:
        return False
    state = builder.state
    for obj in ids:
        kind = state.objects[obj].kind
        if kind.flag("receptacle") is not True and kind.name not in CONTAINER_TYPES:
            return False
        fixed = state.value("pickupable", (obj,)) is False
        if not fixed and verb not in ("unload", "unpack", "empty out", "clear out"):
            return False
    for obj in ids:
        builder.go_to(obj, kind="literal")
        if verb in _EMPTYING:
            empty_container(builder, obj)
        elif state.objects[obj].kind.flag("openable") is True and builder.act(
                "OpenObject", obj, kind="enabling"):
            builder.cleanup("CloseObject", obj)
    return True


def _simple(action: str, cleanup: str | None = None):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        for obj in object_ids(grounded):
            builder.go_to(obj)
            if builder.act(action, obj) and cleanup:
                builder.cleanup(cleanup, obj)
    return handler


def _switch(on: bool):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        # "Turn off the stove": every burner the words fit (switching off more is harmless).
        targets = [i for r in grounded.objects if r.kind == "object"
                   for i in (r.candidates or r.ids if not on else r.ids)]
        for obj in dict.fromkeys(targets):
            builder.switch(obj, on)
    return handler


def _slice(builder: PlanBuilder, grounded: Grounded) -> None:
    tool = grounded.instrument.id if grounded.instrument is not None and \
        grounded.instrument.kind == "object" else None
    knife = tool or builder.ensure("Knife", room=builder.state.room_of(
        (object_ids(grounded) or [""])[0]))
    for obj in object_ids(grounded):
        if builder.acquire(knife):
            builder.go_to(obj)
            builder.act("SliceObject", obj)
    if builder.holding() == knife:
        room = builder.state.robot.room
        away = builder.find_type("KnifeBlock", "Drawer", "SinkBasin", "Sink", room=room)
        builder.cleanup("PutObject", knife, away or builder.surface(room, avoid=knife))


def _clean(builder: PlanBuilder, grounded: Grounded) -> None:
    wet = grounded.clause.verb in _WET_CLEANING
    tool = grounded.instrument
    if tool is not None and tool.kind == "object" and tool.id and builder.state.value(
            "filled", (tool.id,)) is not False and builder.acquire(tool.id):
        for obj in object_ids(grounded):
            builder.go_to(obj)
            builder.act("SprayObject", tool.id, obj)
    targets = object_ids(grounded) or ([grounded.destination.id] if grounded.destination
                                 and grounded.destination.id else [])
    for obj in targets:
        if builder.state.entity_type(obj) == "room":
            builder.go_to(obj)
            continue
        builder.go_to(obj)
        builder.act("CleanObject", obj, **({"liquid": "water"} if wet else {}))


def _spray(builder: PlanBuilder, grounded: Grounded) -> None:
    objects = object_ids(grounded)
    tool = grounded.instrument
    sprayer = tool.id if tool is not None and tool.kind == "object" and tool.id else None
    targets = objects
    if sprayer is None and objects and grounded.destination is not None:
        # "spray the bleach on the counter": the first object is what is sprayed
        sprayer, targets = objects[0], [grounded.destination.id] if \
            grounded.destination.id else []
    elif sprayer is None:
        sprayer = builder.find_type("SprayBottle") or builder.ensure("SprayBottle")
    people = [i for r in grounded.objects if r.kind == "person" for i in r.ids]
    if sprayer is None or not builder.acquire(sprayer):
        return
    for target in [*targets, *people]:
        builder.go_to(target)
        builder.act("SprayObject", sprayer, target)


def _go(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination or (grounded.objects[0] if grounded.objects else None)
    if dest is not None and dest.id:
        if dest.kind == "room":
            builder.act("navigate", target=dest.id)
        else:
            builder.act("GoToObject", dest.id)


def _find(builder: PlanBuilder, grounded: Grounded) -> None:
    for ref in [*grounded.objects, *([grounded.destination] if grounded.destination else [])]:
        for entity in ref.ids:
            builder.go_to(entity, kind="literal")


def _person_act(action: str):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        for person in object_ids(grounded, "person"):
            builder.go_to(person)
            if action == "Escort":
                dest = grounded.destination
                if dest is not None and dest.id:
                    builder.act("Escort", person, dest.id)
            elif action == "Assist":
                builder.act("Assist", person, activity=grounded.clause.verb or "help")
            elif action == "Follow":
                builder.act("Follow", person)
    return handler


_PET_BOWLS = ("PetBowl", "DogBowl", "CatBowl", "PetFoodBowl")


def _feed(builder: PlanBuilder, grounded: Grounded) -> None:
    people = object_ids(grounded, "person") or (
        [grounded.recipient.id] if grounded.recipient and grounded.recipient.id else [])
    foods = object_ids(grounded) or ([grounded.instrument.id] if grounded.instrument is not None
                               and grounded.instrument.kind == "object"
                               and grounded.instrument.id else [])
    for person in people:
        pet = builder.state.entity_type(person) == "object"
        bowl = (builder.find_type(*_PET_BOWLS, room=builder.state.room_of(person))
                or builder.find_type(*_PET_BOWLS)) if pet else None
        for food in foods:
            if pet:  # a pet eats from its bowl, or from the floor in front of it
                builder.place(food, bowl or person, relation="in" if bowl else None)
            elif builder.acquire(food):
                builder.go_to(person)
                builder.act("Feed", food, person)


def _record(builder: PlanBuilder, grounded: Grounded) -> None:
    targets: list[str | None] = [i for r in grounded.objects for i in r.ids] or (
        [grounded.destination.id] if grounded.destination and grounded.destination.id else [])
    for target in targets or [None]:
        builder.act("Record", target=target)


def _floor_chore(action: str):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        refs = [*grounded.objects, *([grounded.destination] if grounded.destination else [])]
        targets = [i for r in refs if r.kind in ("room", "object") for i in r.ids]
        for target in targets or [builder.state.robot.room or builder.surface(None)]:
            if builder.state.entity_type(target) == "room" and \
                    builder.state.robot.room != target:
                builder.go_to(target)  # the robot walks there first (and leaves where it was)
            builder.act(action, target=target)
    return handler


def _push(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    for obj in object_ids(grounded):
        builder.go_to(obj)
        builder.act("PushObject", obj, dest.id if dest is not None and dest.id else None)


def _pick(builder: PlanBuilder, grounded: Grounded) -> None:
    if grounded.destination is not None or grounded.recipient is not None:
        fetch(builder, grounded)
        return
    for obj in object_ids(grounded):
        builder.acquire(obj, kind="literal")


def _plug(on: bool):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        target = destination_id(builder, grounded)
        for obj in object_ids(grounded):
            if on and target is not None and builder.state.holder_of(obj) is None:
                builder.place(obj, target, kind="enabling")
            builder.go_to(obj)
            builder.act("PlugIn" if on else "Unplug", obj)
    return handler


def _lock(locked: bool):  # type: ignore[no-untyped-def]
    action = "LockObject" if locked else "UnlockObject"
    simple = _simple(action)

    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        # "lock the scissors in the staff cupboard": put them there, then lock the cupboard
        place = destination_id(builder, grounded) if locked else None
        if place is None:
            simple(builder, grounded)
            return
        put(builder, grounded)
        builder.go_to(place)
        builder.act(action, place)
    return handler


def _wait(builder: PlanBuilder, grounded: Grounded) -> None:
    builder.act("Wait", seconds=60.0)


def _visit_people(builder: PlanBuilder, grounded: Grounded) -> None:
    for person in [*object_ids(grounded, "person"), *grounded.persons()]:
        builder.go_to(person, kind="literal")


_HANDLERS = {
    "fetch": fetch, "give": give, "put": put, "discard": discard, "remove": remove,
    "throw": throw, "drop": drop, "break": break_open, "crack": break_open,
    "open": _simple("OpenObject"), "close": _simple("CloseObject"),
    "lock": _lock(True), "unlock": _lock(False),
    "switch_on": _switch(True), "switch_off": _switch(False), "slice": _slice,
    "clean": _clean, "spray": _spray, "plug": _plug(True), "unplug": _plug(False),
    "push": _push, "pick": _pick, "go": _go, "find": _find, "wait": _wait,
    "follow": _person_act("Follow"), "escort": _person_act("Escort"),
    "assist": _person_act("Assist"), "feed": _feed, "record": _record,
    "vacuum": _floor_chore("Vacuum"), "mop": _floor_chore("Mop"),
    "fold": _simple("FoldObject"), "chore": _find, "communicate": _visit_people,
    **{schema: _visit_people for schema in DECLARED_SCHEMAS},
}
