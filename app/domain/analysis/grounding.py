"""Grounding: which entities of the scene a clause's words name.

In: the request's `WorldState` (the one scene model `/verify` and the monitor use), the user
profile and the lexicon; then, phrase by phrase, `NounPhrase`s in command order. Out:
`Referent`s (ids of objects, people or a room; several for "all the plates"), and `Gap`s for
words that name nothing it can place. A thing the command names that the scene lacks, but that
the object concepts know ("a glass of water"), becomes a new entity of that type whose facts are
unknown unless the words give them; so does a person a role word names ("the guest").
`scene()` returns the state with those entities added. Pronouns point to the last person or
object named. Objects are matched by `ThingGrounding` (grounding_things.py) and people and pets
by `PeopleGrounding` (grounding_people.py), which `Grounder` extends. Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping
from dataclasses import replace

from app.domain.analysis.grounding_things import CAMEL, ThingGrounding
from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.phrases import BODY_PARTS, PROGRAM_NOUNS, NounPhrase
from app.domain.analysis.referents import (
    GENERIC_WORDS,
    MAX_GROUP,
    Gap,
    Referent,
    words_of,
)
from app.domain.models import GateRequest
from app.domain.world import WorldState
from app.domain.world.concepts import concept_of, singular
from app.domain.world.object_types import normalize_type

_EVERYTHING = frozenset({"lot", "everything", "all", "rest", "whole"})
_ROBOT_PRONOUNS = frozenset({"yourself", "you", "yourselves"})
# "a 40 degree cycle", "medium heat": a run of a machine, named by its setting.
_PROGRAMS = PROGRAM_NOUNS | {"heat"}
_PROGRAM_MACHINES = frozenset({"washingmachine", "washer", "dishwasher", "clothesdryer", "dryer",
                               "tumbledryer", "washerdryer"})


def _names_a_room(phrase: NounPhrase) -> bool:
    """ "the store room", "the boiler room", "a storeroom": a kind of room the layout does
    not list is still a room, not a thing to put something on."""
    head = phrase.head or ""
    words = [w for w in phrase.phrase.split() if w not in ("the", "a", "this", "that")]
    return (head == "room" and len(words) > 1) or (head.endswith("room") and len(head) > 6
                                                   and head not in ("mushroom", "broom"))


_ARTICLES = frozenset({"the", "a", "an", "this", "that", "all", "every"})


class Grounder(ThingGrounding):
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
        variants = lexicon.person_variants
        self._names = {p.id: set().union(*(variants.get(w, {w}) for w in words_of(
            p.id, p.name, p.role))) for p in self.people.values()}

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











    def remember(self, text: str) -> None:
        """Note what a remark names ("the iron's still on - switch it off"): scene things only,
        never new ones, so a later pronoun can point to them."""
        words = words_of(text)
        order = re.findall(r"[a-z]+", text.lower())
        named: list[tuple[int, str]] = []
        for obj in self.objects.values():
            type_head = singular(CAMEL.sub(" ", obj.type).split()[-1].lower()) if obj.type \
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





    def place_new(self, object_id: str, **fields: object) -> None:
        """Put a new entity somewhere (a room) once a clause says where it is."""
        obj = self.objects.get(object_id)
        if obj is not None and object_id.startswith("new_"):
            self.objects[object_id] = replace(obj, **fields)  # type: ignore[arg-type]
