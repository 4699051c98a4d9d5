"""Grounding: which scene objects, people and rooms each phrase of a step refers to.

In: parsed `Step`s and the `SceneView`. Out: `GroundedStep`s whose phrases are `Referent`s
(candidate ids in the scene, or one virtual entity made from the phrase when the scene has no
match or no scene was given). Pronouns take the last referent of the right kind; "me" is the
user. A phrase that fits several objects keeps them all: the unknowns finder decides whether
that ambiguity matters. Never fails.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.domain.analysis.command import Step
from app.domain.analysis.knowledge_base import Knowledge, singular
from app.domain.analysis.mentions import Mention
from app.domain.analysis.scene_view import ObjectView, PersonView, SceneView, spaced_name
from app.domain.analysis.state_clauses import apply_state_clauses
from app.domain.models import Level

__all__ = ["GroundedStep", "Grounder", "Referent", "apply_state_clauses"]

_SWITCHABLE = frozenset({"heat_source", "electrical", "appliance", "light", "water_source",
                         "ignition", "controls_heat"})
_SIZE_BIG = frozenset({"big", "large", "heavy", "biggest", "largest", "heaviest", "huge"})
_SIZE_SMALL = frozenset({"small", "little", "smallest", "tiny", "light"})
_STATE_WORDS = {"hot": ("hot",), "warm": ("hot",), "sharp": ("sharp",), "full": ("consumable",),
                "open": ("open",), "broken": ("broken",)}


_TITLE_GENDER = {"mr": "male", "mrs": "female", "ms": "female", "miss": "female",
                 "sir": "male", "madam": "female", "lady": "female", "lord": "male"}
_USING_ACTIONS = frozenset({"heat", "cut", "serve", "handover", "mix", "pour"})
_GROUP_SIZES = {"twin": 2, "triplet": 3, "quad": 4, "quadruplet": 4}


@dataclass(frozen=True, slots=True)
class Referent:
    """What a phrase refers to: a kind and candidate ids (more than one = ambiguous)."""

    mention: Mention
    kind: str  # object | person | room | none
    ids: tuple[str, ...]
    virtual: bool = False


@dataclass(frozen=True, slots=True)
class GroundedStep:
    """A step with its phrases resolved."""

    step: Step
    objects: tuple[Referent, ...]
    recipient: Referent | None
    destination: Referent | None
    target: Referent | None
    instrument: Referent | None
    source: Referent | None
    away_from: Referent | None
    path: Referent | None


class Grounder:
    """Resolves phrases against one scene view, remembering referents for pronouns."""

    def __init__(self, view: SceneView, knowledge: Knowledge) -> None:
        self._view = view
        self._knowledge = knowledge
        self._last_object: Referent | None = None
        self._history: list[Referent] = []
        self._want_switchable = False
        self._using = False
        self._discarded: set[str] = set()
        self._last_person: dict[str | None, Referent] = {}
        # An object's id, name and type words, asked about for every phrase of the command.
        self._name_words: dict[str, tuple[frozenset[str], str]] = {}

    def ground(self, step: Step) -> GroundedStep:
        """Resolve every phrase of a step (objects first, so "it" can point back)."""
        before = self._last_object
        self._want_switchable = step.action in ("switch_on", "switch_off")
        self._using = step.action in _USING_ACTIONS
        objects = tuple(self.resolve(m) for m in step.objects)
        self._want_switchable = False
        if step.action == "remove" and not step.negated:
            self._discarded.update(i for r in objects for i in r.ids)
        recipient = self.resolve(step.recipient, prefer="person") if step.recipient else None
        # "put the towel on it": a pronoun after the verb's own object points further back.
        after, self._last_object = self._last_object, before or self._last_object
        try:
            return self._ground_rest(step, objects, recipient)
        finally:
            self._last_object = after

    def _ground_rest(self, step: Step, objects: tuple[Referent, ...],
                     recipient: Referent | None) -> GroundedStep:
        return GroundedStep(
            step=step, objects=objects, recipient=recipient,
            destination=self._opt(step.destination), target=self._opt(step.target),
            instrument=self._opt(step.instrument), source=self._opt(step.source),
            away_from=self._opt(step.away_from), path=self._opt(step.path))

    def _opt(self, mention: Mention | None) -> Referent | None:
        referent = self.resolve(mention, remember=False) if mention else None
        if referent is not None and referent.kind == "object":
            self._history.append(referent)
        if referent is not None and referent.kind == "person":
            self._remember_person(referent)
        return referent

    def resolve(self, mention: Mention, *, prefer: str | None = None, remember: bool = True
                ) -> Referent:
        """Resolve one phrase to a referent."""
        referent = self._resolve(mention, prefer)
        if remember and referent.kind == "object":
            self._last_object = referent
            self._history.append(referent)
        if remember and referent.kind == "person":
            self._remember_person(referent)
        return referent

    def _remember_person(self, referent: Referent) -> None:
        genders = {self._view.people[i].gender for i in referent.ids if i in self._view.people}
        title = referent.mention.text.split()[:1]
        genders.add(_TITLE_GENDER.get(title[0]) if title else None)  # "mr okafor" is "him"
        for gender in genders | {None}:
            self._last_person[gender] = referent

    def _resolve(self, mention: Mention, prefer: str | None) -> Referent:
        view = self._view
        if mention.kind == "pronoun":
            return self._pronoun(mention, prefer)
        if mention.kind == "room" or (mention.room and mention.kind != "object"):
            return Referent(mention, "room", (self.room_id(mention.room or mention.head),))
        if mention.kind == "name":
            people = [p.id for p in view.people.values()
                      if mention.head in (p.id.lower(), (p.name or "").lower())]
            if people:
                return Referent(mention, "person", tuple(people))
            objects = [o.id for o in view.objects.values()
                       if mention.head in (o.id.lower(), (o.name or "").lower())]
            if self._knowledge.noun_concept(mention.head) is not None:
                # An object named by a common noun ("bottle") is not the only bottle: the
                # phrase still means any object of that kind.
                return self._object(mention)
            return Referent(mention, "object", tuple(objects))
        if mention.kind == "person" or (prefer == "person" and mention.role_word):
            return self._person(mention)
        return self._object(mention)

    def _pronoun(self, mention: Mention, prefer: str | None) -> Referent:
        word = mention.head
        user = self._view.user
        if word in ("me", "myself", "i", "us", "we") and user is not None:
            return Referent(mention, "person", (user.id,), virtual=user.virtual)
        if word in ("whoever", "whomever") and mention.location is not None:
            # "whoever is in the shower": the people in that place, else anyone at all.
            place = mention.location[1]
            room = self.room_id(place.room or place.head)
            here = tuple(p.id for p in self._view.people.values() if p.room == room)
            return Referent(mention, "person", here or tuple(self._view.people))
        if word in ("everyone", "everybody", "anyone", "anybody", "someone", "somebody",
                    "whoever", "whomever"):
            return Referent(mention, "person", tuple(self._view.people), virtual=False)
        gender = {"him": "male", "her": "female"}.get(word)
        if word in ("him", "her") or (word == "them" and prefer == "person"):
            found = self._last_person.get(gender) or self._last_person.get(None)
            if found:
                return found
            # Nobody named yet ("he's asleep on the sofa, carry him up"): the one person in
            # the scene it can be, if there is exactly one.
            fits = [p for p in self._view.real_people() if not p.is_user
                    and (gender is None or p.gender in (gender, None))]
            if len(fits) == 1:
                return Referent(mention, "person", (fits[0].id,))
            if gender is not None and fits:
                # "give her a spoonful" with two girls present: either of them (ambiguous).
                return Referent(mention, "person", tuple(p.id for p in fits))
            return Referent(mention, "person", (word,), virtual=True)
        if self._want_switchable:
            # "put the foil in the microwave and turn it on": "it" is what can be switched.
            for earlier in reversed(self._history):
                if any(self._view.objects[i].props.keys() & _SWITCHABLE for i in earlier.ids
                       if i in self._view.objects):
                    return earlier
        if self._last_object is not None and self._using and (
                self._last_object.ids and set(self._last_object.ids) <= self._discarded):
            # "take the film off, then heat it": "it" is the food, not what was taken off.
            for earlier in reversed(self._history):
                if earlier.ids and not set(earlier.ids) <= self._discarded:
                    return earlier
        if self._last_object is not None:
            return self._last_object
        if word == "them" and self._last_person.get(None):
            return self._last_person[None]
        return Referent(mention, "none", ())

    def _person(self, mention: Mention) -> Referent:
        role = self._knowledge.role_words.get(mention.role_word or mention.head)
        if role and role.is_user and self._view.user is not None:
            return Referent(mention, "person", (self._view.user.id,), self._view.user.virtual)
        people = list(self._view.people.values())
        matches = [p for p in people if p.role and (
            p.role == mention.head or singular(p.role) == singular(mention.head)
            or (p.name or "").lower() == mention.head)]
        if not matches and role:
            matches = [p for p in people if p.role_class == role.name or (
                role.age_group and p.age_group == role.age_group and role.age_group != "adult")]
        if not matches and singular(mention.head) in _GROUP_SIZES:
            matches = _same_role_group(people, _GROUP_SIZES[singular(mention.head)])
        if mention.location and len(matches) > 1:
            room = self.room_id(mention.location[1].room or mention.location[1].head)
            matches = [p for p in matches if p.room == room] or matches
        if matches:
            return Referent(mention, "person", tuple(p.id for p in matches))
        person_id = mention.head.replace(" ", "_")
        if person_id not in self._view.people:
            self._view.people[person_id] = PersonView(
                id=person_id, role=mention.head, role_class=role.name if role else None,
                age_group=role.age_group if role else None, age_level=Level.TASK,
                young=bool(role and role.young), gender=role.gender if role else None,
                room=self.room_id(mention.location[1].head) if mention.location else None,
                virtual=True)
        return Referent(mention, "person", (person_id,), virtual=True)

    def _object(self, mention: Mention) -> Referent:
        candidates = [o for o in self._view.objects.values() if self._names(o, mention)]
        # An object named by its own word beats one that only shares the word's concept.
        literal = [o for o in candidates if self._literally(o, mention)]
        candidates = self._narrow(literal or candidates, mention)
        if candidates:
            return Referent(mention, "object", tuple(o.id for o in candidates))
        holder = self._holder(mention)
        if holder:
            # "the leftovers in the foil tray": the scene lists the tray, which holds them.
            return Referent(mention, "object", holder)
        object_id = (mention.substance or mention.head).replace(" ", "_")
        if object_id not in self._view.objects:
            concept = mention.concept
            props = set(self._knowledge.concepts[concept].props) if concept else set()
            self._view.objects[object_id] = ObjectView(
                id=object_id, type=mention.head, concept=concept,
                props=dict.fromkeys(props, Level.TASK),
                mass_kg=self._knowledge.concepts[concept].mass_kg if concept else None,
                virtual=True)
        return Referent(mention, "object", (object_id,), virtual=True)

    @staticmethod
    def _literally(obj: ObjectView, mention: Mention) -> bool:
        text = f"{obj.id} {obj.name or ''} {spaced_name(obj.type)}"
        words = text.lower().replace("_", " ").split()
        return any(w in words or singular(w) in words for w in mention.head.split())

    def _holder(self, mention: Mention) -> tuple[str, ...]:
        if mention.location is None or mention.location[0] not in ("in", "inside"):
            return ()
        place = mention.location[1]
        if place.kind != "object":
            return ()
        found = [o for o in self._view.objects.values()
                 if self._names(o, place) and o.has("container") and not o.has("fixed")]
        return tuple(o.id for o in self._narrow(found, place))

    def _names(self, obj: ObjectView, mention: Mention) -> bool:
        head = mention.head
        named = self._name_words.get(obj.id)
        if named is None:
            text = f"{obj.id} {obj.name or ''} {obj.type}".lower().replace("_", " ")
            named = self._name_words[obj.id] = (frozenset(text.split()), text.strip())
        words, whole = named
        if head in words or singular(head) in words or head == whole:
            return True
        if mention.substance and obj.contents == mention.substance:
            return True
        if mention.concept == "generic":
            return not obj.has("fixed") and not obj.has("furniture") and not obj.has("surface")
        return mention.concept is not None and obj.concept == mention.concept

    def _narrow(self, candidates: list[ObjectView], mention: Mention) -> list[ObjectView]:
        def keep(filtered: list[ObjectView]) -> list[ObjectView]:
            return filtered or candidates

        for word in mention.modifiers:
            if word in _SIZE_BIG and len(candidates) > 1:
                candidates = [max(candidates, key=lambda o: o.mass_kg or 0.0)]
            elif word in _SIZE_SMALL and len(candidates) > 1:
                candidates = [min(candidates, key=lambda o: o.mass_kg or 0.0)]
            elif word in _STATE_WORDS:
                candidates = keep([o for o in candidates if any(o.has(p) or (
                    p == "open" and o.is_open) for p in _STATE_WORDS[word])])
            else:
                candidates = keep([o for o in candidates if word in (
                    f"{o.id} {o.name or ''} {o.properties.get('color', '')} "
                    f"{o.properties.get('position', '')}").lower().replace("_", " ").split()])
        if mention.substance and len(candidates) > 1:
            candidates = keep([o for o in candidates if o.contents == mention.substance])
        if mention.location:
            place = mention.location[1]
            room = self.room_id(place.room) if place.room else None
            candidates = keep([o for o in candidates if (room and o.room == room) or
                               place.head in o.place_words or
                               singular(place.head) in o.place_words])
        if len(candidates) > 1 and any(o.properties.get("intended") for o in candidates):
            candidates = [o for o in candidates if o.properties.get("intended")]
        if mention.owner and len(candidates) > 1:
            candidates = keep([o for o in candidates if o.owner and mention.owner in o.owner])
        return candidates

    def room_id(self, word: str) -> str:
        """The layout's id for a room word ("living room" -> "living_room"), else the word."""
        canonical = self._knowledge.room_words.get(word, word)
        for room in self._view.rooms:
            plain = room.lower().replace("_", " ")
            if plain in (word, canonical.replace("_", " ")) or room == canonical:
                return room
        return canonical


def _same_role_group(people: list[PersonView], size: int) -> list[PersonView]:
    """"the twins" when the scene lists them by role: the only role held by exactly `size`."""
    by_role: dict[str, list[PersonView]] = {}
    for person in people:
        by_role.setdefault(person.role or "", []).append(person)
    groups = [group for role, group in by_role.items() if role and len(group) == size]
    return groups[0] if len(groups) == 1 else []
