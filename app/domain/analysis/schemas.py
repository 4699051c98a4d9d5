"""Each clause read into steps of the action model: the schemas and their arguments.

In: a `Clause` (from `reader.py`), the `PlanBuilder` with its grounder, and the lexicon. Out:
steps added to the builder's sketch, and a `Grounded` record of the clause: the schema chosen,
what its objects, recipient, destination, source and instrument name. A verb that may name
several schemas gets the one its arguments fit ("take grandma to the bathroom" escorts, "take
the cup to the sink" fetches). `handlers.py` turns a grounded clause into steps. Fails: never;
a clause whose arguments do not fit its schema says why in `Grounded.problem`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from app.domain.analysis.arguments import Clause
from app.domain.analysis.grounding import Grounder
from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.phrases import BODY_PARTS, TIME_UNITS, NounPhrase
from app.domain.analysis.referents import Referent
from app.domain.analysis.steps import PlanBuilder
from app.domain.world.concepts import concept_of, singular
from app.domain.world.object_types import CONTAINER_TYPES, TypeInfo, normalize_type
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
    into_hands: bool = False
    """The command put the thing into the recipient's hands: a handover, never a set-down."""
    destination_word: str | None = None
    """The preposition that named the destination ("by" the door, "against" it)."""
    problem: str | None = None
    carried_on: bool = False
    """The next clause sets down what this one fetches ("bring the tins in and put them in the
    shed"): it is picked up and carried there, not handed to the user on the way."""
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


def _rolls_up_or_down(kind: TypeInfo) -> bool:
    """A garage door, a blind or a shutter: opened by raising it, closed by lowering it."""
    name = normalize_type(kind.name)
    return kind.flag("pickupable") is not True and any(w in name for w in _LOWERED)


_LOWERED = ("door", "blind", "shutter", "curtain", "gate", "hatch")
_DOOR_SCHEMAS = frozenset({("lock",), ("unlock",), ("open",), ("close",)})
# Words for how long, how hot or how much: settings of a step, not things to act on.
SETTINGS = frozenset({
    "minute", "minutes", "min", "mins", "second", "seconds", "sec", "secs", "hour", "hours",
    "while", "bit", "moment", "degree", "degrees", "percent", "setting", "low", "medium",
    "high", "max", "maximum", "minimum", "full", "half", "thin", "thick", "warm", "hot", "cold",
    "lukewarm", "gently", "slowly", "quickly", "rare", "done", "crispy", "golden", "soft",
    "halfway", "partway", "brim",
    "brown", "times", "time", "once", "twice", "tonight", "today", "tomorrow", "morning",
    "evening", "afternoon", "night", "later", "now", "first", "last", "way", "go",
    "overnight", "upside", "laps", "lap", "circuits"})


_LOCATIVE = frozenset({"on", "in", "inside", "under", "underneath", "by", "next to", "beside",
                       "off", "near", "behind", "on top of", "at"})
_BESIDE = frozenset({"next to", "beside", "by", "near", "against", "alongside"})
NEXT_TO = _BESIDE - {"against"}
"""Where a thing set down is beside the place named, not on or against it."""
_INTO_HANDS = frozenset({"in", "into", "onto", "to"})
_HANDS = frozenset({"hand", "hands", "grip", "grasp"})
# "out to the big bin by the gate": the bin is where it goes; the gate only says which bin.
_TOWARDS = frozenset({"to", "over to", "back to", "up to", "down to", "out to"})
_INTO_CONTAINERS = frozenset(normalize_type(t) for t in CONTAINER_TYPES)
_INTO_PERSON = frozenset({"into", "in to", "through to", "round to"})
_CARRYING = frozenset({"take", "bring", "carry", "run", "pop"})
_SURFACE = frozenset({"on", "onto", "in", "into", "on top of", "inside", "back on", "back in",
                      "back into"})
_INTO = frozenset({"into", "onto", "in to", "on to"})
_STATIC_PLACE = frozenset({"on", "in", "at", "by", "beside", "next to", "under", "inside",
                           "on top of", "near"})
_ALONG_WITH = frozenset({"with", "along with", "together with", "and also"})


VOCATIVES = frozenset({"love", "dear", "honey", "hon", "sweetie", "darling", "mate", "buddy",
                       "pal", "robot", "sir", "madam", "babe", "sweetheart", "bot", "friend"})


_NUMBER_HEADS = frozenset({"hundred", "hundreds", "thousand", "degree", "degrees"})
"""Heads of a number said in words ("at two hundred", "to 180 degrees"): a setting."""


def _setting(np: NounPhrase) -> bool:
    head = np.head
    return bool(head) and (head.isdigit() or head in SETTINGS or head.rstrip("cfs").isdigit()
                           or head in _NUMBER_HEADS or (head in VOCATIVES and not np.modifiers))


def _less_setting(np: NounPhrase) -> NounPhrase:
    """ "fill it halfway": the thing, without how much ("it")."""
    if np.head not in _HOW_FULL or not np.modifiers or np.modifiers[-1] not in _PRONOUN_OBJECTS:
        return np
    return NounPhrase(np.modifiers[-1], pronoun=np.modifiers[-1])


_PRONOUN_OBJECTS = frozenset({"it", "them", "this", "that", "these", "those"})
_HOW_FULL = frozenset({"halfway", "partway", "half", "full", "brim"})


def ground_clause(builder: PlanBuilder, clause: Clause, index: int) -> Grounded:
    """Ground a clause's words and choose its schema (no steps yet)."""
    g = builder.grounder
    before, before_single = g.last_object, g.last_single
    # "give her one of Nana's tablets": the recipient stands before the thing in the words
    # and is read first, so a person named inside the thing's phrase is never who "her" means
    recipient = g.person(clause.second) if clause.second is not None else None
    objects = [g.any(np) for np in map(_less_setting, clause.objects) if not _setting(np)]
    objects = [_switchable_pronoun(g, clause, ref) for ref in objects]
    own = {i for r in objects for i in r.ids}
    if before and own and not own & set(before):
        g.last_object, g.last_single = before, before_single  # "pour water on it": not the water
        g.last_place = None
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
              if prep in _DESTINATION and not _setting(np) and not to_person(prep, np)
              and (np.head or "") not in TIME_UNITS]
    if len(places) > 1 and clause.roles[places[-1]][1].text.split()[:1] in (["its"], ["their"]):
        places.pop()  # "the curry in the microwave in its foil tray": what it is in already
    if len(places) > 1 and clause.roles[places[-1]][0] in ("in", "inside", "at") and \
            _names_room(g, clause.roles[places[-1]][1]) and \
            not _names_room(g, clause.roles[places[-2]][1]):
        places.pop()  # "beside the heater in the garage": the garage says which heater
    if len(places) > 1 and clause.roles[places[-2]][0] in _INTO | {"to"} and \
            clause.roles[places[-1]][0] in _STATIC_PLACE:
        places.pop()  # "into the plant pot on the TV stand": the stand says which pot
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
        if prep == "to" and clause.schemas[:1] in _DOOR_SCHEMAS:
            continue  # "lock the back door to the garden": which door, not where it goes
        if prep in _ALONG_WITH and clause.schemas[:1] in (("fetch",), ("give",), ("pick",)) \
                and not _names_person(people, np):
            objects.append(g.any(np))  # "take grandad a whisky with his tablets": both go
            continue
        if prep in ("out of", "beyond") and np.head == "reach" and grounded.destination is None:
            # "out of his reach": somewhere high, which is where things go to be kept from people
            grounded.destination = g.any(_OUT_OF_REACH, place=True)
            continue
        if prep in _INTO_HANDS and np.head in _HANDS and np.possessor and recipient is None:
            # "put it straight into his hands": a handover to him, not a place called hands
            grounded.recipient = recipient = g.person(NounPhrase(
                np.possessor, head=np.possessor, pronoun=np.possessor if np.possessor in (
                    "me", "him", "her", "them", "us") else None))
            grounded.into_hands = True
            continue
        if prep in _SOURCE and grounded.source is None:
            grounded.source = g.any(np, place=True)
        elif prep == "with" and grounded.instrument is None:
            grounded.instrument = g.any(np)
        elif prep == "for" and recipient is None and _names_person(g.lexicon.people, np):
            grounded.recipient = g.person(np)
        elif prep in _DESTINATION and grounded.destination is None:
            # "spray it in Dave's face": aimed at Dave; "by her feet" stays a place beside her
            aimed = np.head in BODY_PARTS and bool(np.possessor) and prep not in _BESIDE
            found = g.any(np, place=not aimed)
            if found.kind == "person" and prep in _TOWARDS | _INTO_PERSON and recipient is None:
                grounded.recipient = found  # "take the tea into Gran": to her
            grounded.destination, grounded.destination_word = found, prep
    around = next((np for prep, np in clause.roles if prep in ("round", "around")), None)
    if around is not None and recipient is None and (clause.schemas[:1] in (
            ("give",), ("fetch",)) or (clause.verb or "").split()[:1] in (["take"], ["carry"])):
        # "pass the crackers round the lounge", "take it round the guests": each of them
        named = g.person(around) if _names_person(people, around) else None
        grounded.recipient = named if named is not None and named.ids else _everyone_in(
            g, around)
        if grounded.destination is not None and grounded.destination.phrase is around:
            grounded.destination = None
    if grounded.destination is not None and grounded.destination.ids and set(
            grounded.destination.ids) <= own:
        grounded.destination = None  # "put the roast in": not in itself
    if own:
        # "it" after "a cup of tea, milk and two sugars" is the first thing named; "them" is all
        g.last_object = tuple(dict.fromkeys(i for r in objects for i in r.ids))
        g.last_single = next((r.ids for r in objects if r.ids), g.last_object)
    _contents_of_containers(g, grounded, clause)
    first_is_person = bool(objects) and objects[0].kind == "person"
    grounded.schema = _choose(clause, first_is_person, grounded.destination is not None)
    dest = grounded.destination
    if grounded.schema == "push" and dest is not None and dest.kind == "object" and dest.ids \
            and grounded.destination_word in ("in", "into", "inside") and \
            normalize_type(g.objects[dest.ids[0]].kind.name) in _INTO_CONTAINERS:
        grounded.schema = "put"  # "shove the box in the oven": put in it, not pushed at it
    first_id = objects[0].id if objects and objects[0].kind == "object" and \
        objects[0].id in g.objects else None
    verb_words = (clause.verb or "").split()
    if grounded.schema in ("fetch", "pick", "put", "push") and first_id and verb_words[-1:] in (
            ["down"], ["up"]) and grounded.destination is None and \
            _rolls_up_or_down(g.objects[first_id].kind):
        # "bring the garage door down", "pull the blind up": closed or opened, not carried
        grounded.schema = "close" if verb_words[-1] == "down" else "open"
        grounded.recipient = recipient = None
    if grounded.schema == "switch_off" and clause.verb == "put out" and \
            grounded.destination is not None and grounded.destination.kind == "object":
        grounded.schema = "put"  # "put dad's tablets out on the table": set out there
    if grounded.recipient is not None and grounded.schema in ("chore", "pick") and \
            not first_is_person and (clause.verb or "").split()[0] in _CARRYING:
        grounded.schema = "fetch"  # "take the crackers in to Ruth": carried to her
    if grounded.schema == "go" and (clause.verb or "").split()[-1:] in (["round"], ["around"]) \
            and grounded.instrument is not None and grounded.instrument.kind == "object":
        _round_with(g, grounded)  # "go round everyone in the lounge with the rolls"
    if grounded.schema in ("clean", "cool") and dest is not None and dest.ids and \
            g.scene().value("heat_source", (dest.ids[0],)) is True:
        grounded.schema = "heat"  # "dry it off in the microwave": heated there
    builder.sync()
    _by_tool(builder, grounded)
    return grounded


def _switchable_pronoun(g: Grounder, clause: Clause, ref: Referent) -> Referent:
    """ "Put the potato in the microwave and turn it on": a pronoun points to what the verb can
    apply to; a potato cannot be switched on, the place it was put in can."""
    if ref.phrase.pronoun not in ("it", "this", "that") or ref.kind != "object" or not (
            set(clause.schemas) & {"switch_on", "switch_off"}) or any(
            _switchable(g, i) for i in ref.ids):
        return ref
    place = g.last_place
    if place is not None and place.kind == "object" and place.ids and all(
            _switchable(g, i) for i in place.ids):
        return Referent(ref.phrase, "object", place.ids)
    # "tablet in, and start it": else the last thing named that can be switched
    named = [i for i in reversed(g.named_objects) if _switchable(g, i)] if ref.ids else []
    return Referent(ref.phrase, "object", tuple(named[:1])) if named else ref


def _switchable(g: Grounder, obj_id: str) -> bool:
    obj = g.objects.get(obj_id)
    return obj is not None and bool(obj.kind.flag("toggleable") or obj.kind.flag("heat_source")
                                    or obj.kind.trait("electrical"))


# A tool whose use is a task of its own: "run the hoover round the hall" is hoovering.
_TOOL_SCHEMAS = {"vacuumcleaner": "vacuum", "vacuum": "vacuum", "hoover": "vacuum",
                 "mop": "mop"}


def _by_tool(builder: PlanBuilder, grounded: Grounded) -> None:
    """Choose between a verb's schemas by what it is applied to ("run the dishwasher"
    switches it on; "run the hoover round" hoovers)."""
    schemas, first = grounded.clause.schemas, grounded.objects[0] if grounded.objects else None
    tool_ref = grounded.instrument
    if grounded.schema == "clean" and tool_ref is not None and tool_ref.kind == "object":
        tool_obj = builder.grounder.objects.get(tool_ref.id or "")
        kinds = (normalize_type(tool_obj.kind.name) if tool_obj else "",
                 normalize_type(tool_ref.phrase.head or ""))
        if any(_TOOL_SCHEMAS.get(k) == "vacuum" for k in kinds):
            grounded.schema = "vacuum"  # "go over the rug with the hoover": hoover it
            return
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


def _contents_of_containers(g: Grounder, grounded: Grounded, clause: Clause) -> None:
    """ "The leftovers in the foil tray": a thing the scene lacks, said to be in or on a scene
    container, is what that container holds; act on the container."""
    first = clause.roles[0] if clause.roles else None
    holder = grounded.source if first is not None and first[0] in ("from", "out of") else \
        grounded.destination or grounded.source
    if first is None or first[0] not in ("in", "inside", "on", "from", "out of") or \
            holder is None or holder.kind != "object" or holder.new or not (
                holder.ids or holder.candidates):
        return
    if holder is grounded.destination and clause.schemas[:1] == ("put",):
        return  # "put the cleaning stuff in the fridge": it goes in, it is not what is there
    for index, ref in enumerate(grounded.objects):
        if ref.new and ref.kind == "object" and (_could_be_contents(ref.phrase, g.lexicon) or (
                ref.phrase.quantity is not None and _portable(g, holder))):
            # Out of one of two bowls: which one is the question, never a made-up thing.
            grounded.objects[index] = Referent(ref.phrase, "object", holder.ids,
                                               holder.candidates if not holder.ids else ())
            if grounded.destination is holder:
                grounded.destination = None
            elif grounded.source is holder:
                grounded.source = None


def _portable(g: Grounder, holder: Referent) -> bool:
    """ "two tablets from the white bottle", "a couple of biscuits out of the tin": a counted
    handful of what a thing one carries holds is brought in it (never a cupboard, lifted)."""
    scene = g.scene()
    return bool(holder.ids) and all(scene.value("pickupable", (i,)) is True for i in holder.ids)


# What a container holds, or a portion of it ("a treat out of the bowl", "a handful from the jar").
_CONTENTS_WORDS = frozenset({"leftovers", "leftover", "stuff", "contents", "rest", "food",
                             "mess", "bits", "remains", "scraps", "things", "treat", "snack",
                             "sweet", "handful", "bit", "portion", "helping", "serving", "bite",
                             "spoonful", "scoop", "piece", "nibble", "titbit", "tidbit"})


def _could_be_contents(phrase: NounPhrase, lexicon: Lexicon) -> bool:
    """Whether a phrase can name what a container holds ("the pills", "the leftovers"), not
    a container of its own ("the water glass")."""
    head = singular(phrase.head) if phrase.head else ""
    concept = concept_of(phrase.phrase)
    if concept is not None and "container" in concept.props:
        return False
    return head in _CONTENTS_WORDS or head in lexicon.portions or any(
        substance_trait(head, trait) for trait in ("food", "liquid", "medication", "toxic"))


def _names_room(g: Grounder, np: NounPhrase) -> bool:
    """Whether a phrase names a room (a layout room or a room word), without grounding it."""
    text = np.phrase.replace("'s", "")
    return text in g.lexicon.rooms or (np.head or "") in g.lexicon.rooms or normalize_type(
        text) in {normalize_type(r) for r in g.rooms}


def _round_with(g: Grounder, grounded: Grounded) -> None:
    """Going round people with something is offering it to each of them (in the room named)."""
    assert grounded.instrument is not None
    dest = grounded.destination
    room = dest.ids[0] if dest is not None and dest.kind == "room" and dest.ids else None
    people = [i for r in grounded.objects if r.kind == "person" for i in r.ids
              if room is None or g.people[i].room == room]
    if not people and dest is not None and dest.kind == "room":
        found = _everyone_in(g, dest.phrase)
        people = list(found.ids) if found is not None else []
    if not people:
        return
    grounded.schema = "give"
    grounded.recipient = Referent(grounded.instrument.phrase, "person", tuple(people))
    grounded.objects, grounded.instrument, grounded.destination = [grounded.instrument], None, None


def _everyone_in(g: Grounder, place: NounPhrase) -> Referent | None:
    """Everyone but the speaker in the room a distributive give goes round (everyone at all
    when the room is not one the layout has)."""
    room = g.room(place) if _names_room(g, place) else None
    user = g.user_id
    ids = tuple(p.id for p in g.people.values() if p.id != user and (
        room is None or p.room == room))
    return Referent(place, "person", ids) if ids else None


def _names_person(people: object, np: NounPhrase) -> bool:
    return bool(np.pronoun in ("me", "him", "her", "us", "them", "everyone", "everybody") or (
        isinstance(people, dict) and (np.phrase in people or np.head in people)))
