"""Each clause read into steps of the action model: the schemas and their arguments.

In: a `Clause` (from `reader.py`), the `PlanBuilder` with its grounder, and the lexicon. Out:
steps added to the builder's sketch, and a `Grounded` record of the clause: the schema chosen,
what its objects, recipient, destination, source and instrument name. A verb that may name
several schemas gets the one its arguments fit ("take grandma to the bathroom" escorts, "take
the cup to the sink" fetches). The kitchen recipes (heat, pour, fill, water, make) live in
`recipes.py`. Fails: never; a clause whose arguments do not fit its schema adds no steps and
says why in `Grounded.problem`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from app.domain.analysis.grounding import Grounder, Referent
from app.domain.analysis.phrases import NounPhrase
from app.domain.analysis.reader import Clause
from app.domain.analysis.recipes import RECIPES
from app.domain.analysis.steps import PlanBuilder
from app.domain.world.concepts import concept_of, singular
from app.domain.world.object_types import normalize_type
from app.domain.world.substances import substance_trait

PERSON_SCHEMAS = frozenset({"escort", "assist", "follow", "feed", "harm", "frighten",
                            "intimidate", "humiliate", "restrain", "spy", "communicate"})
DECLARED_SCHEMAS = frozenset({"harm", "frighten", "intimidate", "humiliate", "restrain", "spy"})
_DESTINATION = frozenset({
    "to", "into", "in", "onto", "on", "inside", "on top of", "under", "underneath", "next to",
    "beside", "by", "near", "at", "over", "above", "back to", "back into", "back in", "back on",
    "in front of", "against", "toward", "towards", "over to", "up to", "down to", "out to",
    "upstairs to", "downstairs to", "across", "through", "around", "round", "along", "between",
    "behind", "below", "beneath", "up", "down"})
_OUT_OF_REACH = NounPhrase("a high shelf", head="shelf", modifiers=("high",))
_SOURCE = frozenset({"from", "off", "out of", "away from"})
_WET_CLEANING = frozenset({"wash", "rinse", "scrub", "mop up", "wash up", "rinse out", "scour",
                           "disinfect", "descale", "degrease", "clean out"})


@dataclass
class Grounded:
    """A clause with its schema and what its words name."""

    clause: Clause
    index: int
    schema: str | None
    objects: list[Referent]
    recipient: Referent | None = None
    destination: Referent | None = None
    source: Referent | None = None
    instrument: Referent | None = None
    beside: Referent | None = None
    """What the thing is set down next to ("on the bench next to the soldering iron")."""
    destination_word: str | None = None
    """The preposition that named the destination ("by" the door, "against" it)."""
    problem: str | None = None
    cancelled: bool = False
    """Taken back by a later negation ("well don't chuck them")."""

    def persons(self) -> list[str]:
        """Ids of every person the clause names (objects and recipient)."""
        found = [i for r in self.objects if r.kind == "person" for i in r.ids]
        if self.recipient is not None:
            found += list(self.recipient.ids)
        if self.destination is not None and self.destination.kind == "person":
            found += list(self.destination.ids)
        return found


def _choose(clause: Clause, first_is_person: bool, has_destination: bool) -> str | None:
    schemas = clause.schemas
    if not schemas:
        return None
    if first_is_person:
        if "escort" in schemas and has_destination:
            return "escort"
        for schema in schemas:
            if schema in PERSON_SCHEMAS and (schema != "escort" or has_destination):
                return schema
    else:
        for schema in schemas:
            if schema not in PERSON_SCHEMAS or schema == "communicate":
                return schema
    return schemas[0]


# Words for how long, how hot or how much: settings of a step, not things to act on.
SETTINGS = frozenset({
    "minute", "minutes", "min", "mins", "second", "seconds", "sec", "secs", "hour", "hours",
    "while", "bit", "moment", "degree", "degrees", "percent", "setting", "low", "medium",
    "high", "max", "maximum", "minimum", "full", "half", "thin", "thick", "warm", "hot", "cold",
    "lukewarm", "gently", "slowly", "quickly", "rare", "done", "crispy", "golden", "soft",
    "brown", "times", "time", "once", "twice", "tonight", "today", "tomorrow", "morning",
    "evening", "afternoon", "night", "later", "now", "first", "last", "way", "go",
    "overnight", "upside", "laps", "lap", "circuits"})


_LOCATIVE = frozenset({"on", "in", "inside", "under", "underneath", "by", "next to", "beside",
                       "off", "near", "behind", "on top of", "at"})
_BESIDE = frozenset({"next to", "beside", "by", "near", "against", "alongside"})
_NEXT_TO = _BESIDE - {"against"}
# "out to the big bin by the gate": the bin is where it goes; the gate only says which bin.
_TOWARDS = frozenset({"to", "over to", "back to", "up to", "down to", "out to"})
_SURFACE = frozenset({"on", "onto", "in", "into", "on top of", "inside", "back on", "back in",
                      "back into"})
_ALONG_WITH = frozenset({"with", "along with", "together with", "and also"})


VOCATIVES = frozenset({"love", "dear", "honey", "hon", "sweetie", "darling", "mate", "buddy",
                       "pal", "robot", "sir", "madam", "babe", "sweetheart", "bot", "friend"})


def _setting(np: NounPhrase) -> bool:
    head = np.head
    return bool(head) and (head.isdigit() or head in SETTINGS or head.rstrip("cfs").isdigit()
                           or (head in VOCATIVES and not np.modifiers))


def ground_clause(builder: PlanBuilder, clause: Clause, index: int) -> Grounded:
    """Ground a clause's words and choose its schema (no steps yet)."""
    g = builder.grounder
    before, before_single = g.last_object, g.last_single
    objects = [g.any(np) for np in clause.objects if not _setting(np)]
    objects = [_switchable_pronoun(g, clause, ref) for ref in objects]
    own = {i for r in objects for i in r.ids}
    if before and own and not own & set(before):
        g.last_object, g.last_single = before, before_single  # "pour water on it": not the water
        g.last_place = None
    recipient = g.person(clause.second) if clause.second is not None else None
    grounded = Grounded(clause, index, None, objects, recipient)
    # Of several places, the last is where things go; "the chili in the dish into the
    # microwave": the dish only says where the chili is.
    people = g.lexicon.people

    def to_person(prep: str, np: NounPhrase) -> bool:
        return prep in ("to", "over to", "for") and (_names_person(people, np) or bool(
            np.head and np.head in g.names_of_people()))

    if clause.schemas[:1] == ("pick",):
        # "pick up the toys on the floor": where they are, not where they go
        clause = replace(clause, roles=tuple(
            ("from" if prep in _LOCATIVE else prep, np) for prep, np in clause.roles))
        grounded.clause = clause
    places = [i for i, (prep, np) in enumerate(clause.roles)
              if prep in _DESTINATION and not _setting(np) and not to_person(prep, np)]
    if len(places) > 1 and clause.roles[places[-1]][0] in _BESIDE and \
            clause.roles[places[-2]][0] in _SURFACE | _TOWARDS:
        grounded.beside = g.any(clause.roles[places[-1]][1], place=True)
        places.pop()  # "on the bench next to the iron": the bench, beside the iron
    for position, (prep, np) in enumerate(clause.roles):
        if to_person(prep, np) and recipient is None:
            grounded.recipient = recipient = g.person(np)
            continue
        if _setting(np) or (prep in _DESTINATION and position != (places or [-1])[-1]):
            continue
        if prep in _ALONG_WITH and clause.schemas[:1] in (("fetch",), ("give",), ("pick",)) \
                and not _names_person(people, np):
            objects.append(g.any(np))  # "take grandad a whisky with his tablets": both go
            continue
        if prep in ("out of", "beyond") and np.head == "reach" and grounded.destination is None:
            # "out of his reach": somewhere high, which is where things go to be kept from people
            grounded.destination = g.any(_OUT_OF_REACH, place=True)
            continue
        if prep in _SOURCE and grounded.source is None:
            grounded.source = g.any(np, place=True)
        elif prep == "with" and grounded.instrument is None:
            grounded.instrument = g.any(np)
        elif prep == "for" and recipient is None and _names_person(g.lexicon.people, np):
            grounded.recipient = g.person(np)
        elif prep in _DESTINATION and grounded.destination is None:
            found = g.any(np, place=True)
            if found.kind == "person" and prep in ("to", "over to") and recipient is None:
                grounded.recipient = found
            grounded.destination, grounded.destination_word = found, prep
    if grounded.destination is not None and grounded.destination.ids and set(
            grounded.destination.ids) <= own:
        grounded.destination = None  # "put the roast in": not in itself
    if own:
        # "it" after "a cup of tea, milk and two sugars" is the first thing named; "them" is all
        g.last_object = tuple(dict.fromkeys(i for r in objects for i in r.ids))
        g.last_single = next((r.ids for r in objects if r.ids), g.last_object)
    _contents_of_containers(grounded, clause)
    first_is_person = bool(objects) and objects[0].kind == "person"
    grounded.schema = _choose(clause, first_is_person, grounded.destination is not None)
    builder.sync()
    _by_tool(builder, grounded)
    return grounded


def _switchable_pronoun(g: Grounder, clause: Clause, ref: Referent) -> Referent:
    """ "Put the potato in the microwave and turn it on": a pronoun points to what the verb can
    apply to; a potato cannot be switched on, the place it was put in can."""
    if ref.phrase.pronoun not in ("it", "this", "that") or ref.kind != "object" or not (
            set(clause.schemas) & {"switch_on", "switch_off"}) or g.last_place is None:
        return ref
    place = g.last_place
    if any(_switchable(g, i) for i in ref.ids) or place.kind != "object" or not place.ids \
            or not all(_switchable(g, i) for i in place.ids):
        return ref
    return Referent(ref.phrase, "object", place.ids)


def _switchable(g: Grounder, obj_id: str) -> bool:
    obj = g.objects.get(obj_id)
    return obj is not None and bool(obj.kind.flag("toggleable") or obj.kind.flag("heat_source"))


# A tool whose use is a task of its own: "run the hoover round the hall" is hoovering.
_TOOL_SCHEMAS = {"vacuumcleaner": "vacuum", "vacuum": "vacuum", "hoover": "vacuum",
                 "mop": "mop"}


def _by_tool(builder: PlanBuilder, grounded: Grounded) -> None:
    """Choose between a verb's schemas by what it is applied to ("run the dishwasher"
    switches it on; "run the hoover round" hoovers)."""
    schemas, first = grounded.clause.schemas, grounded.objects[0] if grounded.objects else None
    if first is None or first.kind != "object" or grounded.recipient is not None or len(
            schemas) < 2 or grounded.schema not in ("fetch", "pick", "put"):
        return
    obj = builder.grounder.objects.get(first.id or "")
    if obj is None:
        return
    tool = _TOOL_SCHEMAS.get(normalize_type(obj.kind.name)) or _TOOL_SCHEMAS.get(
        normalize_type(first.phrase.head or ""))
    if tool is not None:
        grounded.schema = tool
        grounded.objects = []
    elif "switch_on" in schemas and (obj.kind.flag("toggleable") or obj.kind.trait(
            "electrical")) and grounded.destination is None:
        grounded.schema = "switch_on"


def _contents_of_containers(grounded: Grounded, clause: Clause) -> None:
    """ "The leftovers in the foil tray": a thing the scene lacks, said to be in or on a scene
    container, is what that container holds; act on the container."""
    first = clause.roles[0] if clause.roles else None
    holder = grounded.source if first is not None and first[0] in ("from", "out of") else \
        grounded.destination or grounded.source
    if first is None or first[0] not in ("in", "inside", "on", "from", "out of") or \
            holder is None or holder.kind != "object" or not holder.ids or holder.new:
        return
    for index, ref in enumerate(grounded.objects):
        if ref.new and ref.kind == "object" and _could_be_contents(ref.phrase):
            grounded.objects[index] = Referent(ref.phrase, "object", holder.ids)
            if grounded.destination is holder:
                grounded.destination = None
            elif grounded.source is holder:
                grounded.source = None


_CONTENTS_WORDS = frozenset({"leftovers", "leftover", "stuff", "contents", "rest", "food",
                             "mess", "bits", "remains", "scraps", "things"})


def _could_be_contents(phrase: NounPhrase) -> bool:
    """Whether a phrase can name what a container holds ("the pills", "the leftovers"), not
    a container of its own ("the water glass")."""
    head = singular(phrase.head) if phrase.head else ""
    concept = concept_of(phrase.phrase)
    if concept is not None and "container" in concept.props:
        return False
    return head in _CONTENTS_WORDS or any(
        substance_trait(head, trait) for trait in ("food", "liquid", "medication", "toxic"))


def _names_person(people: object, np: NounPhrase) -> bool:
    return bool(np.pronoun in ("me", "him", "her", "us", "them") or (
        isinstance(people, dict) and (np.phrase in people or np.head in people)))


def apply_clause(builder: PlanBuilder, grounded: Grounded) -> None:
    """Add the steps of one grounded clause to the builder's sketch."""
    builder.clause = grounded.index
    schema = grounded.schema
    if schema is None or grounded.clause.negated:
        return
    handler = _HANDLERS.get(schema) or RECIPES.get(schema)
    before = len(builder.sketch.literal)
    if handler is not None:
        handler(builder, grounded)
    dest = grounded.destination
    if len(builder.sketch.literal) == before and not grounded.objects and dest is not None \
            and dest.ids and dest.kind == "room" and schema in ("fetch", "go", "pick"):
        builder.go_to(dest.ids[0], kind="literal")  # "run out to the garage": go there


def _ids(grounded: Grounded, kind: str = "object") -> list[str]:
    return [i for r in grounded.objects if r.kind == kind for i in r.ids]


def _destination_id(builder: PlanBuilder, grounded: Grounded) -> str | None:
    """The receptacle a destination names (a room's surface for a room)."""
    dest = grounded.destination
    if dest is None or not dest.ids:
        return None
    if dest.kind == "room":
        return builder.surface(dest.ids[0])
    return dest.ids[0] if dest.kind == "object" else None


def _fetch(builder: PlanBuilder, grounded: Grounded) -> None:
    target = _destination_id(builder, grounded)
    person = grounded.recipient.id if grounded.recipient is not None else None
    for obj in _ids(grounded):
        if person is not None:
            builder.deliver(obj, person)
        elif target is not None:
            builder.place(obj, target)
        else:
            builder.deliver(obj, builder.user())


def _give(builder: PlanBuilder, grounded: Grounded) -> None:
    person = (grounded.recipient.id if grounded.recipient is not None else None) or (
        builder.user())
    for obj in _ids(grounded):
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


def _put(builder: PlanBuilder, grounded: Grounded) -> None:
    target = _destination_id(builder, grounded)
    if target is None and grounded.recipient is not None and grounded.recipient.id:
        _fetch(builder, grounded)
        return
    for obj in _ids(grounded):
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
        if grounded.destination_word in _NEXT_TO and here == target and \
                builder.state.value("exit_way", (here,)) is True:
            # "by the door": on the floor or a surface of its room, beside it, not against it
            here, beside = builder.surface(builder.state.room_of(here), avoid=obj), here
        builder.place(obj, here, relation=builder.relation_for(here), beside=beside)


def _discard(builder: PlanBuilder, grounded: Grounded) -> None:
    can = _destination_id(builder, grounded) or builder.ensure("GarbageCan")
    for obj in _ids(grounded):
        builder.place(obj, can, relation="in")


def _remove(builder: PlanBuilder, grounded: Grounded) -> None:
    target = _destination_id(builder, grounded)
    for obj in _ids(grounded):
        if builder.acquire(obj, kind="literal"):
            room = builder.state.robot.room
            builder.place(obj, target or builder.surface(room, avoid=obj), kind="enabling")


_BINS = frozenset({"garbagecan", "garbagebag", "trash", "bin", "rubbish", "garbage",
                   "wastebasket", "dustbin", "recycling"})


def _throw(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    if dest is not None and dest.id and (normalize_type(dest.phrase.head) in _BINS or (
            dest.kind == "object" and normalize_type(
                builder.state.objects[dest.id].kind.name) in _BINS)):
        _discard(builder, grounded)  # "throw it in the bin" puts it in the bin
        return
    target = grounded.destination or grounded.recipient
    aim = target.id if target is not None and target.kind in ("person", "object", "room") \
        else None
    for obj in _ids(grounded):
        if builder.acquire(obj):
            builder.act("ThrowObject", obj, aim)


def _drop(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    for obj in _ids(grounded):
        if builder.acquire(obj):
            if dest is not None and dest.id and dest.kind in ("room", "object", "person"):
                builder.go_to(dest.id)
            builder.act("DropHandObject", obj)


def _break(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    for obj in _ids(grounded):
        if dest is not None and dest.id and normalize_type(dest.phrase.head) == "floor" and \
                builder.acquire(obj):
            builder.act("DropHandObject", obj)
        builder.go_to(obj)
        builder.act("BreakObject", obj)
        if builder.state.value("food", (obj,)) is not True or builder.state.value(
                "on_floor", (obj,)) is True:
            builder.cleanup("PickupObject", obj)
            builder.cleanup("PutObject", obj, builder.ensure("GarbageCan"), relation="in")


def _simple(action: str, cleanup: str | None = None):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        for obj in _ids(grounded):
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
        (_ids(grounded) or [""])[0]))
    for obj in _ids(grounded):
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
        for obj in _ids(grounded):
            builder.go_to(obj)
            builder.act("SprayObject", tool.id, obj)
    targets = _ids(grounded) or ([grounded.destination.id] if grounded.destination
                                 and grounded.destination.id else [])
    for obj in targets:
        if builder.state.entity_type(obj) == "room":
            builder.go_to(obj)
            continue
        builder.go_to(obj)
        builder.act("CleanObject", obj, **({"liquid": "water"} if wet else {}))


def _spray(builder: PlanBuilder, grounded: Grounded) -> None:
    objects = _ids(grounded)
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
        for person in _ids(grounded, "person"):
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


def _feed(builder: PlanBuilder, grounded: Grounded) -> None:
    people = _ids(grounded, "person") or (
        [grounded.recipient.id] if grounded.recipient and grounded.recipient.id else [])
    foods = _ids(grounded) or ([grounded.instrument.id] if grounded.instrument is not None
                               and grounded.instrument.kind == "object"
                               and grounded.instrument.id else [])
    for person in people:
        for food in foods:
            if builder.acquire(food):
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
            builder.act(action, target=target)
    return handler


def _push(builder: PlanBuilder, grounded: Grounded) -> None:
    dest = grounded.destination
    for obj in _ids(grounded):
        builder.go_to(obj)
        builder.act("PushObject", obj, dest.id if dest is not None and dest.id else None)


def _pick(builder: PlanBuilder, grounded: Grounded) -> None:
    if grounded.destination is not None or grounded.recipient is not None:
        _fetch(builder, grounded)
        return
    for obj in _ids(grounded):
        builder.acquire(obj, kind="literal")


def _plug(on: bool):  # type: ignore[no-untyped-def]
    def handler(builder: PlanBuilder, grounded: Grounded) -> None:
        target = _destination_id(builder, grounded)
        for obj in _ids(grounded):
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
        place = _destination_id(builder, grounded) if locked else None
        if place is None:
            simple(builder, grounded)
            return
        _put(builder, grounded)
        builder.go_to(place)
        builder.act(action, place)
    return handler


def _wait(builder: PlanBuilder, grounded: Grounded) -> None:
    builder.act("Wait", seconds=60.0)


def _visit_people(builder: PlanBuilder, grounded: Grounded) -> None:
    for person in [*_ids(grounded, "person"), *grounded.persons()]:
        builder.go_to(person, kind="literal")


_HANDLERS = {
    "fetch": _fetch, "give": _give, "put": _put, "discard": _discard, "remove": _remove,
    "throw": _throw, "drop": _drop, "break": _break, "crack": _break,
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
