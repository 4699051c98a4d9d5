"""Grounding things: which objects of the scene a phrase names, or the new one it makes up.

In: a `NounPhrase`. Out: a `Referent` of objects: by id, name, the noun that heads a type's
name ("the bottle" is the PillBottle when nothing else fits), a concept, or what a thing holds;
narrowed by state words, room words and owners; the load a fixed appliance holds, taken out as a
thing of its own; a part of one object ("the fridge door"); else a new object of that type whose
facts are unknown unless the words give them. Several things that differ in what is safe to do
with them are candidates, for a question. `Grounder` (grounding.py) adds places, pronouns and
memory; `PeopleGrounding` the people. Fails: never.
"""

from __future__ import annotations

import re
from dataclasses import replace

from app.domain.analysis.grounding_people import PeopleGrounding
from app.domain.analysis.phrases import NounPhrase
from app.domain.analysis.referents import GENERIC_WORDS, MAX_GROUP, Gap, Referent, words_of
from app.domain.formula.facts import Unknown
from app.domain.world import ObjectState, type_info
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

CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])")
"""Where the words of a CamelCase type name meet ("Pill|Bottle")."""


_LOCKED = frozenset({"locked", "child-locked", "childproof", "child-proof", "padlocked"})
_INDEFINITE = frozenset({"everything", "anything", "something", "whatever"})


def _last_words(*texts: str | None) -> set[str]:
    """The nouns that head each name ("rail" of "heated towel rail", "kettle" of "kettle_2"):
    what a phrase's head must be to name the thing by its kind, since "the towels" are no
    towel rail."""
    found: set[str] = set()
    for text in texts:
        words = [w for w in re.split(r"[\s_\-]+", CAMEL.sub(" ", text or "").lower())
                 if w and not w.isdigit()]
        if words:
            found |= {words[-1], singular(words[-1])}
    return found

_KINDS_OF_STUFF = frozenset({"stuff", "thing", "things", "product", "products", "supplies",
                             "gear", "kit", "bits"})
_STEM = re.compile(r"(ing|er|ers|s)$")
_OPENED_BY = frozenset({"door", "lid", "flap", "hatch"})
_DOOR_KINDS = frozenset({"door", "gate", "frenchdoor", "slidingdoor"})
_OUTSIDE_DOOR_WORDS = frozenset({"front", "back", "garden", "patio", "outside", "porch",
                                 "side", "yard"})


class ThingGrounding(PeopleGrounding):
    """The things half of `Grounder`: the state it reads is set up by `Grounder.__init__`."""

    gaps: list[Gap]
    stated: dict[str, dict[str, object]]
    last_object: tuple[str, ...]
    last_single: tuple[str, ...]
    named_objects: list[str]

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
                     if singular(CAMEL.sub(" ", o.type).split()[-1].lower()) == head
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
                CAMEL.sub(" ", self.objects[i].type) if split else "",
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
        if not ids:
            ids = self._narrow(self._vessels_made_of(phrase), phrase)
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

    def _vessels_made_of(self, phrase: NounPhrase) -> list[str]:
        """ "The glass off the draining board" when the scene lists a cup made of glass: a
        drinking vessel the phrase names by its material."""
        if "drinking_vessel" not in _props_of(phrase.head or ""):
            return []
        material = singular(phrase.head)
        return [o.id for o in self.objects.values() if "drinking_vessel" in _props_of(o.type)
                and str(o.properties.get("material", "")).lower() == material]

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


def _props_of(word: str) -> frozenset[str]:
    concept = concept_of(word)
    return concept.props if concept is not None else frozenset()
