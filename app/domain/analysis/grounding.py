"""Grounding: which entities of the scene a clause's words name.

In: the request's `WorldState` (the one scene model `/verify` and the monitor use), the user
profile and the lexicon; then, phrase by phrase, `NounPhrase`s in command order. Out:
`Referent`s (ids of objects, people or a room; several for "all the plates"), and `Gap`s for
words that name nothing it can place. A thing the command names that the scene lacks, but that
the object concepts know ("a glass of water"), becomes a new entity of that type whose facts are
unknown unless the words give them; so does a person a role word names ("the guest").
`scene()` returns the state with those entities added. Pronouns point to the last person or
object named. People and pets are resolved by `PeopleGrounding` (grounding_people.py), which
`Grounder` extends. Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping
from dataclasses import replace

from app.domain.analysis.grounding_people import PeopleGrounding
from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.phrases import BODY_PARTS, PROGRAM_NOUNS, NounPhrase
from app.domain.analysis.referents import (
    GENERIC_WORDS,
    MAX_GROUP,
    Gap,
    Referent,
    words_of,
)
from app.domain.formula.facts import Unknown
from app.domain.models import GateRequest
from app.domain.world import ObjectState, WorldState, type_info
from app.domain.world.concepts import concept_of, singular
from app.domain.world.entities import frozen_mapping
from app.domain.world.object_types import normalize_type
from app.domain.world.substances import substance_trait

_STATE_WORDS = {"hot": ("hot", True), "warm": ("hot", True), "cold": ("cold", True),
                "empty": ("filled", False), "full": ("filled", True), "open": ("open", True),
                "closed": ("open", False), "dirty": ("dirty", True), "clean": ("dirty", False),
                "broken": ("broken", True), "lit": ("is_on", True), "running": ("is_on", True)}
_SIGNATURE = ("hot", "sharp", "toxic", "electrical", "breakable", "filled", "contents", "is_on",
              "medication", "heavy", "valuable", "food", "flammable", "metal", "open")


_CLAUSE_MARKERS = frozenset({"that", "which", "who", "whom", "whose", "where", "when", "you",
                             "i", "he", "she", "we", "they", "it", "is", "are", "was", "were",
                             "has", "have", "had", "will", "would", "can", "could"})
_POSITION_WORDS = frozenset({"top", "bottom", "high", "low", "upper", "lower", "left", "right",
                             "front", "back", "middle"})
"""Where a thing is among its like: never matched against the words of a compound type."""
_FIXED_KG = 20.0
"""A thing the simulator cannot pick up and at least this heavy stays where it is (an appliance,
furniture): what it holds is taken out of it."""
_LOAD_FACTS = frozenset({"flammable", "toxic", "wet", "hot", "temperature", "sharp",
                         "allergen", "allergens", "dirty", "soaked"})
"""What a scene says of a fixed thing's load rather than of the thing itself."""
_EVERYTHING = frozenset({"lot", "everything", "all", "rest", "whole"})
_ROBOT_PRONOUNS = frozenset({"yourself", "you", "yourselves"})
# "a 40 degree cycle", "medium heat": a run of a machine, named by its setting.
_PROGRAMS = PROGRAM_NOUNS | {"heat"}
_PROGRAM_MACHINES = frozenset({"washingmachine", "washer", "dishwasher", "clothesdryer", "dryer",
                               "tumbledryer", "washerdryer"})
_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])")


_LOCKED = frozenset({"locked", "child-locked", "childproof", "child-proof", "padlocked"})
_INDEFINITE = frozenset({"everything", "anything", "something", "whatever"})


def _last_words(*texts: str | None) -> set[str]:
    """The nouns that head each name ("rail" of "heated towel rail", "kettle" of "kettle_2"):
    what a phrase's head must be to name the thing by its kind, since "the towels" are no
    towel rail."""
    found: set[str] = set()
    for text in texts:
        words = [w for w in re.split(r"[\s_\-]+", _CAMEL.sub(" ", text or "").lower())
                 if w and not w.isdigit()]
        if words:
            found |= {words[-1], singular(words[-1])}
    return found


def _names_a_room(phrase: NounPhrase) -> bool:
    """ "the store room", "the boiler room", "a storeroom": a kind of room the layout does
    not list is still a room, not a thing to put something on."""
    head = phrase.head or ""
    words = [w for w in phrase.phrase.split() if w not in ("the", "a", "this", "that")]
    return (head == "room" and len(words) > 1) or (head.endswith("room") and len(head) > 6
                                                   and head not in ("mushroom", "broom"))


_KINDS_OF_STUFF = frozenset({"stuff", "thing", "things", "product", "products", "supplies",
                             "gear", "kit", "bits"})
_STEM = re.compile(r"(ing|er|ers|s)$")
_OPENED_BY = frozenset({"door", "lid", "flap", "hatch"})
_DOOR_KINDS = frozenset({"door", "gate", "frenchdoor", "slidingdoor"})
_OUTSIDE_DOOR_WORDS = frozenset({"front", "back", "garden", "patio", "outside", "porch",
                                 "side", "yard"})
_ARTICLES = frozenset({"the", "a", "an", "this", "that", "all", "every"})


class Grounder(PeopleGrounding):
    """Grounds phrases on one request's scene, remembering what pronouns point to."""

    def __init__(self, state: WorldState, request: GateRequest, lexicon: Lexicon,
                 given_names: Collection[str] = (),
                 pet_names: Mapping[str, str] | None = None) -> None:
        self.lexicon = lexicon
        self._given_names = frozenset(given_names)
        """Names the command uses that the scene lists for nobody ("Noah", "Mrs Patel")."""
        self._pet_names = dict(pet_names or {})
        """Names the command gives the scene's one unnamed pet ("feed Biscuit")."""
        self.objects = dict(state.objects)
        self.people = dict(state.people)
        self.rooms = list(state.rooms)
        self._base = state
        self.gaps: list[Gap] = []
        self.stated: dict[str, dict[str, object]] = {}
        """Facts the command's words state about scene objects ("the top shelf")."""
        self.last_object: tuple[str, ...] = ()
        self.last_single: tuple[str, ...] = ()
        self.named_objects: list[str] = []
        self.last_place: Referent | None = None
        self.last_person: dict[str | None, str] = {}
        # A pet a remark names ("Biscuit's been good, give him a treat") is who a later him or
        # her means, unless a person was named after it: mention counts say which came last.
        self._mentions = 0
        self._last_person_at = 0
        self._last_animal: tuple[str, int] | None = None
        self._request = request
        self._user_id: str | None = None
        self._names = {p.id: words_of(p.id, p.name, p.role) for p in self.people.values()}

    # The scene with what grounding added.
    def scene(self) -> WorldState:
        """The request's state plus the entities the command named and the scene lacked."""
        base = self._base
        if (len(self.objects) == len(base.objects) and len(self.people) == len(base.people)
                and len(self.rooms) == len(base.rooms) and not self.stated):
            return base
        return base.evolve(objects=self.objects, people=self.people, rooms=tuple(self.rooms),
                           version=base.version)

    # Entry points (`person` is in PeopleGrounding).
    def _owners_one(self, phrase: NounPhrase) -> Referent | None:
        """"mum's" after "his heart tablets": the owner's thing of the kind last named, or the
        one thing the owner has; None when neither is found."""
        kinds = {self.objects[i].type for i in self.last_object or () if i in self.objects}
        candidates = [i for i, o in self.objects.items()
                      if (not kinds or o.type in kinds) and i not in (self.last_object or ())]
        owned = self._owned_by(candidates, phrase.possessor or "")
        if len(owned) != 1:
            return None
        self.last_object = self.last_single = (owned[0],)
        return Referent(phrase, "object", (owned[0],))

    def _owned_by(self, ids: list[str], possessor: str) -> list[str]:
        """The objects among `ids` whose `owner` is the person the possessor names ("mum",
        "her", "Sam")."""
        owner = self._possessor(possessor)
        names = words_of(possessor, *(owner.ids if owner else ()))
        if owner is not None and owner.ids:
            person = self.people[owner.ids[0]]
            names |= words_of(person.name, person.role)
        names -= GENERIC_WORDS  # "person" in "person_mum" names nobody in particular
        return [i for i in ids if words_of(str(self.objects[i].properties.get("owner", "")))
                & names]

    def any(self, phrase: NounPhrase, *, place: bool = False) -> Referent:
        """A phrase that may name an object, a person, a room or a substance. A place (a
        destination, a source) does not change what "it" points to next."""
        if place and phrase.pronoun in ("there", "here") and self.last_place is not None:
            return self.last_place
        if phrase.pronoun == "one" and phrase.possessor:
            owned = self._owners_one(phrase)
            if owned is not None:
                return owned
        if phrase.pronoun in ("it", "this", "that", "these", "those", "one", "ones") or (
                phrase.pronoun == "them" and self.last_object):
            if self.last_object:
                singular_pronoun = phrase.pronoun in ("it", "this", "that", "one")
                pointed = self.last_single if singular_pronoun and self.last_single else \
                    self.last_object
                return Referent(phrase, "object", pointed)
            self.gaps.append(Gap(phrase.text, "nothing named earlier for it to point to"))
            return Referent(phrase, "none")
        if phrase.pronoun in _ROBOT_PRONOUNS:
            # "plug yourself in", "park yourself in the cab": the robot, who does the step
            # anyway; it names no thing to act on
            return Referent(phrase, "none")
        if phrase.head in _PROGRAMS and phrase.modifiers and not place:
            appliance = self._program_appliance()
            if appliance is not None:  # "start a 40 degree cycle": the washer it is a cycle of
                return Referent(phrase, "object", (appliance,))
        if phrase.head in BODY_PARTS and phrase.possessor and not place:
            # "hold her arm", "take his hand": the person, touched, not a thing to carry
            owner = self._possessor(phrase.possessor)
            if owner is not None:  # whose arm is not clear: ask, never fetch "an arm"
                return Referent(phrase, "person", owner.ids, owner.candidates)
            self.gaps.append(Gap(phrase.text, "nobody it could belong to"))
            return Referent(phrase, "none")
        if phrase.head in _EVERYTHING and not phrase.contents and self.named_objects:
            # "put the lot in the bowl", "everything back in the fridge": all named so far
            return Referent(phrase, "object", tuple(self.named_objects[:MAX_GROUP]))
        if not place:
            return self._any(phrase, place)
        remembered = self.last_object, self.last_single
        found = self._any(phrase, place)
        self.last_object, self.last_single = remembered
        if found.ids:
            self.last_place = found
        return found

    def _any(self, phrase: NounPhrase, place: bool) -> Referent:
        person = self._person(phrase)
        if person is not None:
            return person
        if phrase.head and (self.lexicon.people.get(phrase.phrase) or self.lexicon.people.get(
                phrase.head)) and not self._names_a_product(phrase):
            return self._new_person(phrase)
        several = self._rooms_of_a_kind(phrase)
        if several:
            return Referent(phrase, "room", several)  # "all three bedrooms"
        room = self.room(phrase)
        named_room = phrase.phrase in self.lexicon.rooms and self.lexicon.rooms[
            phrase.phrase] not in ("bathroom", "hallway", "garden")
        if room is not None and (named_room or not self._object_matches(phrase)):
            return Referent(phrase, "room", (room,))
        return self._object(phrase, place=place)

    def _rooms_of_a_kind(self, phrase: NounPhrase) -> tuple[str, ...]:
        """The layout's rooms a plural names ("the bedrooms": bedroom_1, bedroom_2, ...)."""
        head = phrase.head or ""
        if not head.endswith("s") or len(head) < 4:
            return ()
        kind = normalize_type(head[:-1])
        if kind not in {normalize_type(r) for r in self.lexicon.rooms.values()} | {
                normalize_type(k) for k in self.lexicon.rooms}:
            return ()
        found = tuple(r for r in self.rooms if normalize_type(r).rstrip("0123456789") == kind
                      or normalize_type(r).endswith(kind))
        return found if len(found) > 1 else ()

    def room(self, phrase: NounPhrase) -> str | None:
        """The room a phrase names (a layout room, or a room word the layout lacks)."""
        text = phrase.phrase.replace("'s", "")
        if text in ("upstairs", "downstairs"):
            # "nip upstairs": the landing or a room the layout names as on that floor
            for room in self.rooms:
                key = normalize_type(room)
                if text in key or (text == "upstairs" and "landing" in key):
                    return room
        bare = normalize_type(" ".join(w for w in text.split() if w not in _ARTICLES))
        exact = next((room for room in self.rooms if normalize_type(room) == bare), None)
        if exact is not None:
            return exact  # "the landing" is the landing, though the lexicon files it as a hall
        canonical = self.lexicon.rooms.get(text) or self.lexicon.rooms.get(phrase.head)
        if canonical is None and normalize_type(text) not in {normalize_type(r)
                                                              for r in self.rooms}:
            if not _names_a_room(phrase):
                return None
            text = " ".join(w for w in text.split() if w not in ("the", "a", "this", "that"))
        wanted = {normalize_type(text), normalize_type(canonical or text)}
        for room in self.rooms:
            key = normalize_type(room)
            if key in wanted or any(w and (w in key or key in w) for w in wanted):
                return room
        room = canonical or text.replace(" ", "_")
        self.rooms.append(room)
        return room

    # People.
    def _program_appliance(self) -> str | None:
        """The machine a program or setting belongs to: the last one named, else the only one
        the scene has."""
        machines = [i for i, o in self.objects.items()
                    if normalize_type(o.kind.name) in _PROGRAM_MACHINES
                    or normalize_type(o.type) in _PROGRAM_MACHINES]
        named = [i for i in reversed(self.named_objects) if i in machines]
        if named:
            return named[0]
        return machines[0] if len(machines) == 1 else None

    def _names_a_product(self, phrase: NounPhrase) -> bool:
        """A qualified role word that a scene object answers to is that object: "the ammonia
        cleaner" is the bottle that holds it, not a cleaner by trade."""
        wanted = set(phrase.modifiers)
        return bool(wanted) and any(
            wanted <= words_of(o.id, o.name, o.type, str(o.properties.get("contents") or ""))
            for o in map(self.objects.__getitem__, self._object_matches(phrase)))

    def _object_matches(self, phrase: NounPhrase) -> list[str]:
        if not phrase.head:
            return []
        named = [i for i in self.objects if "_" in i and i.lower() in phrase.text.split()]
        if named:
            return named  # "the high cupboard cabinet_high_1": an id the caller wrote out
        wanted = words_of(phrase.phrase)
        head = singular(phrase.head)
        concept = concept_of(phrase.phrase)
        kind = type_info(phrase.phrase)
        exact, typed = [], []
        for obj in self.objects.values():
            names = words_of(obj.id, obj.name)
            if wanted <= names or normalize_type(phrase.phrase) == normalize_type(obj.id):
                exact.append(obj.id)
            elif head in _last_words(obj.type, obj.kind.name, obj.id, obj.name) or normalize_type(
                    phrase.phrase) == normalize_type(obj.type) or (
                    kind.name == obj.kind.name and kind.name != phrase.phrase) or (
                    concept is not None and concept.name != "generic"
                    and concept_of(obj.type) == concept and len(concept.types) <= 1) or (
                    self._holds_substance(obj, head) and (
                        self._carried(obj.id) or substance_trait(head, "liquid") is True)):
                typed.append(obj.id)
        found = exact or typed
        if not found and len(phrase.modifiers) <= 1:
            # "the bottle" and nothing else fits: the "PillBottle", a kind of bottle by the
            # last word of its type; "the strobe light": the "PartyLight" whose id or name
            # says strobe
            found = [o.id for o in self.objects.values()
                     if singular(_CAMEL.sub(" ", o.type).split()[-1].lower()) == head
                     and set(phrase.modifiers) <= words_of(o.id, o.name)]
        if not found and head in _KINDS_OF_STUFF and phrase.modifiers:
            # "the cleaning stuff", "the baking things": what the modifier's stem names
            stem = _STEM.sub("", phrase.modifiers[-1])
            found = [o.id for o in self.objects.values() if len(stem) >= 4 and any(
                w.startswith(stem) for w in words_of(o.id, o.name, o.type) | set(str(
                    o.properties.get("contents") or "").lower().split()))]
        if phrase.contents:
            # "the cup of tea" when the tea is in a mug (and the cup is empty): the vessel
            # holding what was named
            held = singular(phrase.contents.split()[-1])
            holders = [i for i, o in self.objects.items() if self._holds_substance(o, held)]
            if holders and not set(holders) & set(found):
                found = holders
        return found

    def _carried(self, object_id: str) -> bool:
        """Whether the thing can be carried about: "the wet towels" a washing machine holds
        are the towels, taken out of it, never the machine (but "the water" in the bath is the
        bath's: a liquid is run, drained or poured through what holds it)."""
        if self._base.value("pickupable", (object_id,)) is not False:
            return True
        mass = self._base.value("mass_kg", (object_id,))
        # a bin bag is carried out full; a washing machine or a fridge never moves
        return isinstance(mass, float) and mass < _FIXED_KG

    def _holds_substance(self, obj: ObjectState, word: str) -> bool:
        contents = obj.facts.get("contents", obj.properties.get("contents"))
        return isinstance(contents, str) and word in words_of(contents)

    def _narrow(self, ids: list[str], phrase: NounPhrase) -> list[str]:
        kept = ids
        for modifier in phrase.modifiers:
            if modifier in _STATE_WORDS:
                symbol, wanted = _STATE_WORDS[modifier]
                fits = [i for i in kept if self._base.value(symbol, (i,)) in (wanted,)]
                possible = [i for i in kept if self._base.value(symbol, (i,)) is not (
                    not wanted)]
                kept = fits or possible or kept
                continue
            room = self.lexicon.rooms.get(modifier)
            if room is not None:
                # "the hall table": the table in the hallway
                inside = [i for i in kept if normalize_type(room) in normalize_type(
                    self.objects[i].room or "")]
                kept = inside or kept
                continue
            # "the side table" is the SideTable; "the top cupboard" no CounterTop
            split = modifier not in _POSITION_WORDS
            named = [i for i in kept if modifier in words_of(
                i, self.objects[i].name, self.objects[i].type,
                _CAMEL.sub(" ", self.objects[i].type) if split else "",
                *(str(v) for v in self.objects[i].properties.values()))]
            kept = named or kept
        if phrase.possessor:
            kept = self._owned_by(kept, phrase.possessor) or kept
        if phrase.contents:
            holding = [i for i in kept if self._holds_substance(
                self.objects[i], singular(phrase.contents.split()[-1]))]
            kept = holding or kept
        return kept

    def _signature(self, object_id: str) -> tuple[str, ...]:
        values = (self._base.value(s, (object_id,)) for s in _SIGNATURE)
        return tuple("?" if isinstance(v, Unknown) else str(v) for v in values)

    def _object(self, phrase: NounPhrase, *, place: bool = False) -> Referent:
        ids = self._narrow(self._object_matches(phrase), phrase)
        held = None if ids or place else self._taken_out(phrase)
        if held is not None:
            return held
        if not ids:
            ids = self._narrow(self._named_in_passing(phrase), phrase)
        if ids:
            ids.sort()
            plural = phrase.every or phrase.head in _KINDS_OF_STUFF - {"thing", "product"} or (
                phrase.head.endswith("s") and not phrase.head.endswith(
                "ss") and len(ids) > 1 and phrase.quantity != 1)
            if plural:
                chosen = tuple(ids[:MAX_GROUP])
            elif len({self._signature(i) for i in ids}) > 1:
                return Referent(phrase, "object", (), tuple(ids))
            else:
                chosen = (ids[0],)
            self.last_object = self.last_single = chosen
            self.named_objects += [i for i in chosen if i not in self.named_objects]
            self._annotate(chosen, phrase)
            return Referent(phrase, "object", chosen, tuple(ids[:MAX_GROUP]))
        head = singular(phrase.head or "")
        unknown_head = bool(head) and not self.lexicon.is_english(head) and \
            concept_of(head) is None
        # "Ivy's high chair tray" (a place), "the drain unblocker" (a word no table knows):
        # the one scene object the other words name
        # ... and "the fridge door", "the freezer lid": the appliance, opened or shut by it
        part_of = self._part_of(phrase) if place or unknown_head or head in _OPENED_BY else None
        if part_of is not None:
            return part_of
        return self._new_object(phrase, place=place)

    def _named_in_passing(self, phrase: NounPhrase) -> list[str]:
        """Things whose name has the phrase's noun anywhere in it, when none is named by it:
        "the walk-in freezer" is the "walk-in freezer door" the scene lists."""
        head = singular(phrase.head or "")
        return [o.id for o in self.objects.values()
                if head and head in words_of(o.id, o.name, o.type, o.kind.name)]

    def _taken_out(self, phrase: NounPhrase) -> Referent | None:
        """ "the darks from the hamper", "the wet towels" in the washing machine: what one
        fixed thing the scene says holds, as a thing of its own inside it, with the hazards the
        scene states of the load (oily rags are flammable, taken out or not)."""
        head = singular(phrase.head or "")
        holders = [o for o in self.objects.values() if not self._carried(o.id)
                   and self._holds_substance(o, head)]
        if len(holders) != 1 or substance_trait(head, "liquid") is True:
            return None
        holder = holders[0]
        load = str(holder.facts.get("contents", holder.properties.get("contents")))
        stated = {k: v for k, v in holder.properties.items() if k in _LOAD_FACTS}
        object_id = f"new_{normalize_type(phrase.phrase) or 'load'}"
        self.objects[object_id] = ObjectState(
            id=object_id, type=load, room=holder.room, parent=holder.id, relation="in",
            properties=frozen_mapping(stated))
        self.last_object = self.last_single = (object_id,)
        return Referent(phrase, "object", (object_id,), new=True)

    def _part_of(self, phrase: NounPhrase) -> Referent | None:
        """ "Ivy's high chair tray", "the fridge door shelf": a place named as a part of one
        scene object is that object."""
        if not phrase.modifiers:
            return None
        whole = NounPhrase(" ".join(phrase.modifiers), head=phrase.modifiers[-1],
                           modifiers=phrase.modifiers[:-1], possessor=phrase.possessor)
        found = self._object_matches(whole)
        if len(found) != 1:
            return None
        self.named_objects += [i for i in found if i not in self.named_objects]
        return Referent(phrase, "object", (found[0],))

    def remember(self, text: str) -> None:
        """Note what a remark names ("the iron's still on - switch it off"): scene things only,
        never new ones, so a later pronoun can point to them."""
        words = words_of(text)
        order = re.findall(r"[a-z]+", text.lower())
        named: list[tuple[int, str]] = []
        for obj in self.objects.values():
            type_head = singular(_CAMEL.sub(" ", obj.type).split()[-1].lower()) if obj.type \
                else ""
            shared = words & words_of(obj.type, obj.name) - GENERIC_WORDS
            if shared or (type_head and type_head not in GENERIC_WORDS and type_head in words):
                first = min((order.index(w) for w in shared | {type_head} if w in order),
                            default=len(order))
                named.append((first, obj.id))
                if obj.name and words & words_of(obj.name) and \
                        self._base.value("animal", (obj.id,)) is True:
                    self._mentions += 1
                    self._last_animal = (obj.id, self._mentions)
        if named:
            # "The power strip under Dana's desk is sticky... rinse it": the remark's subject,
            # the thing it names first, is what a later "it" means.
            self.last_object = self.last_single = (min(named)[1],)
        if not self.last_object:
            self._remember_by_kind(text)
        for person_id, names in self._names.items():
            if words & names - GENERIC_WORDS:
                self._remember_person(Referent(NounPhrase(text), "person", (person_id,)))

    def _remember_by_kind(self, text: str) -> None:
        """ "I left the hob on": a word for a kind of thing (hob, telly, loo roll) that names
        exactly one scene object of that kind, for the "it" of the next order."""
        for word in reversed(re.findall(r"[a-z]+", text.lower())):
            concept = concept_of(word)
            if concept is None or word in GENERIC_WORDS:
                continue
            found = [i for i, o in self.objects.items() if concept_of(o.type) == concept
                     or o.type in concept.types]
            if len(found) == 1:
                self.last_object = self.last_single = (found[0],)
                return

    def _annotate(self, ids: tuple[str, ...], phrase: NounPhrase) -> None:
        """What the words say of where a thing is: "the top shelf" is high up; "the garden
        door" opens to the outside."""
        said: dict[str, bool] = {}
        high = {"top", "high", "upper", "highest", "tall"} & set(phrase.modifiers)
        low = {"bottom", "low", "lower", "lowest"} & set(phrase.modifiers)
        if high or low:
            said["elevated"] = bool(high)
        doors = [i for i in ids if normalize_type(self.objects[i].type) in _DOOR_KINDS]
        if doors and _OUTSIDE_DOOR_WORDS & set(phrase.modifiers) and len(doors) == len(ids):
            said["exterior"] = True
        if not said:
            return
        for object_id in ids:
            obj = self.objects[object_id]
            properties = {**obj.properties, **said}
            self.objects[object_id] = replace(obj, properties=frozen_mapping(properties))
            self.stated[object_id] = {**self.stated.get(object_id, {}), **said}
        self._base = self._base.evolve(objects=self.objects, version=self._base.version)

    def _new_object(self, phrase: NounPhrase, *, place: bool = False) -> Referent:
        # A thing to handle must be named by a noun for a physical thing ("the full volume" is
        # none); a place only needs to be a word ("the bedside", "each end").
        head = singular(phrase.head) if phrase.head else ""
        # "everything left on the nightstand" names whatever is there, never a new thing.
        thing = None if _INDEFINITE & set(phrase.words) else self._thing_named(phrase)
        if thing is not None:
            phrase, head = thing, singular(thing.head)
        elif not place or not head or not self.lexicon.is_english(head):
            self.gaps.append(Gap(phrase.text, "no object, person or place of that name"))
            return Referent(phrase, "none")
        liquid = substance_trait(head, "liquid") is True and not phrase.contents
        properties: dict[str, object] = {"contents": phrase.contents} if phrase.contents else {}
        if _LOCKED & set(phrase.words):
            properties["locked"] = True  # "the locked cupboard in the art room"
        kind = phrase.phrase
        if liquid:
            # "the water", "some bleach": a cup or bottle of it, which is what a robot carries.
            properties, kind = {"contents": head, "filled": True}, (
                "Bottle" if substance_trait(head, "toxic") else "Cup")
        object_id = f"new_{normalize_type(phrase.phrase) or 'object'}"
        self.objects[object_id] = ObjectState(id=object_id, type=kind,
                                              room=self._room_named_in(phrase),
                                              properties=frozen_mapping(properties))
        self.last_object = self.last_single = (object_id,)
        self._annotate((object_id,), phrase)
        return Referent(phrase, "object", (object_id,), new=True,
                        substance=head if liquid else None)

    def _thing_named(self, phrase: NounPhrase) -> NounPhrase | None:
        """The phrase as the name of a thing the scene lacks, or None when no word of it names
        a physical thing ("the full volume", "it turn"). Words after the thing's noun are
        dropped ("the candles unlit" is candles)."""
        words = phrase.words
        # "every mug you find", "the gate is latched", "the lights that are on": what follows
        # a relative word, a subject pronoun or a copula says something of the thing.
        cut = next((i for i, w in enumerate(words) if i and w in _CLAUSE_MARKERS), len(words))
        if cut < len(words):
            words = words[:cut]
            phrase = replace(phrase, head=words[-1], modifiers=words[:-1])
        for end in range(len(words), 0, -1):
            head = singular(words[end - 1])
            named = " ".join(words[:end])
            if (concept_of(named) is not None or type_info(named).known
                    or substance_trait(head, "food") is not None
                    or substance_trait(head, "toxic") is not None or self.lexicon.is_thing(head)
                    or head.endswith("able")):  # "the flammables", "her valuables"
                return phrase if end == len(words) else replace(
                    phrase, head=words[end - 1], modifiers=words[:end - 1])
            if self.lexicon.is_verb(words[end - 1]):
                return None  # "the chili simmering": a state said of it, not a thing's name
        return None

    def _room_named_in(self, phrase: NounPhrase) -> str | None:
        """ "the living room lamps", "the kitchen bin": a layout room named before the head
        says where a thing the scene lacks is."""
        text = " ".join(phrase.modifiers)
        return next((room for room in self.rooms if normalize_type(room) and normalize_type(
            room) in normalize_type(text)), None) if text else None

    def place_new(self, object_id: str, **fields: object) -> None:
        """Put a new entity somewhere (a room) once a clause says where it is."""
        obj = self.objects.get(object_id)
        if obj is not None and object_id.startswith("new_"):
            self.objects[object_id] = replace(obj, **fields)  # type: ignore[arg-type]
