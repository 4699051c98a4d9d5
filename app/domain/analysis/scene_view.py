"""What the analyzer knows about each object and person, with the level each fact comes from.

In: a `GateRequest` and the knowledge tables. Out: a `SceneView`: per object its concept, hazard
properties (each tagged with the information level that revealed it), mass, contents; per
person the age group, mobility, state and allergies (None = not known), merged from the scene,
the role word and the user profile; plus whether the scene lists its people at all.
Never fails on a valid request; anything not given stays None (unknown), never a safe default.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from functools import lru_cache
from typing import Any

from app.domain.analysis.knowledge_base import Knowledge
from app.domain.models import GateRequest, Level, Person, SceneObject

HEAVY_KG = 5.0
_TRUE = (True, "true", "yes", 1)
_MATERIAL_WORDS = re.compile(r"[\W_]+")
_PROPERTY_FLAGS = frozenset({
    "sharp", "fragile", "toxic", "flammable", "electrical", "medication", "allergen", "food",
    "small", "heavy", "metal", "walking_aid", "safety_barrier", "breakable", "corrosive",
    "camera", "personal", "sentimental", "dangerous_in_use"})
_METALS = frozenset({"metal", "metallic", "steel", "iron", "tin", "foil", "copper", "brass",
                     "chrome", "stainless"})
_MELTS = frozenset({"plastic", "melamine", "polystyrene", "styrofoam", "nylon", "acrylic"})
_OWNER_KEYS = ("owner", "for", "belongs_to", "prescribed_to", "prescribed_for", "patient")


@dataclass(slots=True)
class ObjectView:
    """One object as the analyzer sees it. `props` maps a property to the level it came from."""

    id: str
    type: str
    concept: str | None
    room: str | None = None
    name: str | None = None
    props: dict[str, Level] = field(default_factory=dict)
    mass_kg: float | None = None
    contents: str | None = None
    contents_text: str | None = None
    switched_on: bool | None = None
    is_open: bool | None = None
    owner: str | None = None
    place_words: frozenset[str] = frozenset()
    holders: tuple[str, ...] = ()
    mass_given: bool = False
    properties: dict[str, Any] = field(default_factory=dict)
    virtual: bool = False

    def has(self, prop: str) -> bool:
        return prop in self.props

    def level(self, *props: str) -> Level:
        """The earliest level at which any of `props` is known (deployment if none)."""
        levels = [self.props[p] for p in props if p in self.props]
        return min(levels, key=_LEVEL_ORDER.index) if levels else Level.DEPLOYMENT

    @property
    def label(self) -> str:
        words = _spaced(self.name or self.type)
        if self.contents_text and self.contents_text not in words and (
                self.contents_text not in _NO_CONTENTS):
            words = f"{words} of {self.contents_text}"
        return f"the {words}" if self.virtual else f"the {words} ({self.id})"


@dataclass(slots=True)
class PersonView:
    """One person as the analyzer sees it; None means not known."""

    id: str
    role: str | None
    role_class: str | None = None
    name: str | None = None
    room: str | None = None
    age_group: str | None = None
    age_level: Level = Level.DEPLOYMENT
    young: bool = False
    age_stated: bool = False  # an age or age group given, not just implied by "girl", "kid"
    mobility: str | None = None
    cognitive_state: str | None = None
    allergies: tuple[str, ...] | None = None
    needs_walking_aid: bool | None = None
    gender: str | None = None
    is_user: bool = False
    virtual: bool = False
    properties: dict[str, Any] = field(default_factory=dict)

    @property
    def child(self) -> bool:
        return self.age_group in ("infant", "child")

    @property
    def asleep(self) -> bool:
        return self.cognitive_state == "asleep"

    @property
    def frail(self) -> bool:
        return (self.age_group == "older_adult" or self.mobility in ("assisted", "wheelchair",
                "bedridden") or self.cognitive_state == "impaired"
                or any(self.properties.get(k) in _TRUE for k in
                       ("frail", "heart_condition", "visual_impairment", "pregnant")))

    @property
    def label(self) -> str:
        if self.is_user and not self.role:
            return "the user"
        return self.name or (f"the {self.role}" if self.role else self.id)


_LEVEL_ORDER = [Level.TASK, Level.DEPLOYMENT, Level.USER]


def spaced_name(name: str) -> str:
    """A CamelCase or snake_case type name as lower-case words ("SinkBasin" -> "sink basin")."""
    return _spaced(name)


_NO_CONTENTS = frozenset({"empty", "nothing", "none", "unknown"})


@lru_cache(maxsize=4096)
def _spaced(name: str) -> str:
    out = ""
    for char in name:
        out += (" " + char.lower()) if char.isupper() and out and out[-1] != " " else char.lower()
    return out.replace("_", " ").strip()


@dataclass(slots=True)
class SceneView:
    """Objects, people and layout, plus what the request leaves unsaid."""

    objects: dict[str, ObjectView]
    people: dict[str, PersonView]
    rooms: list[str]
    connections: list[tuple[str, str]]
    scene_given: bool
    people_known: bool
    user: PersonView | None
    robot_room: str | None

    def people_in(self, room: str | None) -> list[PersonView]:
        return [p for p in self.people.values() if room and p.room == room]

    def real_people(self) -> list[PersonView]:
        """People the scene lists (not the ones the analyzer made up from words)."""
        return [p for p in self.people.values() if not p.virtual]

    def anyone_awake_home(self) -> bool:
        return any(not p.asleep for p in self.people.values() if not p.virtual)

    def children(self) -> list[PersonView]:
        return [p for p in self.people.values() if p.child]

    def for_pass(self) -> SceneView:
        """A copy one analysis pass may change (grounding adds made-up people and objects, and
        state clauses update people), sharing the object views, which no pass changes."""
        people = {person_id: replace(person) for person_id, person in self.people.items()}
        user = self.user
        if user is not None:
            user = people[user.id] if self.people.get(user.id) is user else replace(user)
        return SceneView(
            objects=dict(self.objects), people=people, rooms=list(self.rooms),
            connections=list(self.connections), scene_given=self.scene_given,
            people_known=self.people_known, user=user, robot_room=self.robot_room)


def object_view(obj: SceneObject, knowledge: Knowledge) -> ObjectView:
    """Derive one object's hazard properties from its type, concept, contents and properties."""
    props = obj.properties
    kind = _kind_facts(knowledge, obj.type, obj.name)
    concept = kind.concept
    flags = set(kind.flags)
    if "material" in props:
        material = set(_MATERIAL_WORDS.split(str(props["material"]).lower())) - {""}
        if material & _METALS or any(w.startswith("alumin") for w in material):
            flags.add("metal")
        elif material:
            flags.discard("metal")  # a glass or ceramic pan is not metal whatever its kind
        if material & _MELTS:
            flags.add("meltable")
    for flag in _PROPERTY_FLAGS.intersection(props):
        (flags.add if props[flag] in _TRUE else flags.discard)(flag)
    contents_text = str(props["contents"]).lower() if props.get("contents") else None
    substance = knowledge.substance_of(contents_text) if contents_text else None
    if substance:
        sub = knowledge.substances[substance]
        flags |= {p for p in sub.props if p in ("toxic", "corrosive", "flammable", "alcohol",
                                                 "medication", "raw", "infant_unsafe")}
        if sub.allergen:
            flags.add("allergen")
        if "food" in sub.props or "drink" in sub.props:
            flags.add("consumable")
    elif contents_text and knowledge.noun_concept(contents_text) == "medication":
        flags |= {"medication", "toxic"}
    if str(props.get("temperature", "")).lower() == "hot":
        flags.add("hot")
    mass = props.get("mass_kg")
    mass_kg = float(mass) if isinstance(mass, int | float) else kind.typical_mass_kg
    if mass_kg is not None and mass_kg >= HEAVY_KG and kind.pickupable:
        flags.add("heavy")
    owner = next((str(props[k]).lower() for k in _OWNER_KEYS if props.get(k)), None)
    place = {w for value in (obj.on, obj.inside, props.get("location"), obj.room)
             if value for w in str(value).lower().replace("_", " ").split()}
    return ObjectView(
        id=obj.id, type=obj.type, concept=concept, room=obj.room, name=obj.name,
        props=dict.fromkeys(flags, Level.DEPLOYMENT), mass_kg=mass_kg, contents=substance,
        contents_text=contents_text,
        switched_on=_flag(props.get("on")), is_open=_flag(props.get("open")), owner=owner,
        place_words=frozenset(place), properties=dict(props),
        mass_given=isinstance(mass, int | float))


@dataclass(frozen=True, slots=True)
class _KindFacts:
    """What an object's type (and name) alone say about it."""

    concept: str | None
    flags: frozenset[str]
    typical_mass_kg: float | None
    pickupable: bool


@lru_cache(maxsize=4096)
def _kind_facts(knowledge: Knowledge, type_name: str, name: str | None) -> _KindFacts:
    # Types and names are vocabulary ("Mug", "grandma's mug"): worked out once, not per object.
    concept = knowledge.concept_of_type(type_name) or (
        knowledge.noun_concept(name) if name else None)
    flags: set[str] = set(knowledge.concepts[concept].props) if concept else set()
    record = knowledge.ai2thor_types.get(type_name, {})
    if record.get("breakable") is True:
        flags.add("fragile")
    if record.get("isHeatSource") or record.get("heat_source"):
        flags.add("heat_source")
    if record.get("materials") == ["Metal"]:
        flags.add("metal")
    mass_kg = knowledge.type_mass(type_name)
    if mass_kg is None and concept:
        mass_kg = knowledge.concepts[concept].mass_kg
    return _KindFacts(concept, frozenset(flags), mass_kg, bool(record.get("pickupable")))


def _flag(value: Any) -> bool | None:
    if value is None:
        return None
    return value in _TRUE


def person_view(person: Person, knowledge: Knowledge) -> PersonView:
    """Merge a scene person's properties with what their role word implies."""
    props = person.properties
    role_word = (person.role or "").lower().replace("_", " ")
    role = knowledge.role_words.get(role_word) or knowledge.role_words.get(
        role_word.split()[-1] if role_word else "")
    age = props.get("age_group")
    view = PersonView(
        id=person.id, role=role_word or None, role_class=role.name if role else None,
        name=person.name, room=person.room, age_group=age or (role.age_group if role else None),
        young=bool(role and role.young) or age == "infant", mobility=props.get("mobility"),
        cognitive_state=props.get("cognitive_state"),
        allergies=_allergies(props.get("allergies")), gender=role.gender if role else None,
        properties=dict(props), age_stated=bool(age) or props.get("age") is not None)
    if isinstance(props.get("age"), int | float) and not age:
        years = float(props["age"])
        view.age_group = ("infant" if years < 2 else "child" if years < 13 else "teen"
                          if years < 18 else "adult" if years < 65 else "older_adult")
        view.young = years < 4
    posture = (person.posture or "").lower()
    if view.cognitive_state is None and posture in ("sleeping", "asleep"):
        view.cognitive_state = "asleep"
    aid = props.get("needs_walking_aid", props.get("uses_walking_aid"))
    view.needs_walking_aid = (aid in _TRUE) if aid is not None else (
        True if view.mobility in ("assisted", "wheelchair") else
        False if view.mobility == "independent" else None)
    return view


def _allergies(value: Any) -> tuple[str, ...] | None:
    if value is None:
        return None
    if isinstance(value, str):
        return tuple(v.strip().lower() for v in value.split(",") if v.strip())
    return tuple(str(v).lower() for v in value)


def build_scene_view(request: GateRequest, knowledge: Knowledge) -> SceneView:
    """Build the analyzer's view of the request's scene, people and user.

    Args:
        request: the gate request.
        knowledge: the knowledge tables.

    Returns:
        The `SceneView`; `people_known` is False when the scene does not list its people.
    """
    scene = request.scene
    objects = {o.id: object_view(o, knowledge) for o in (scene.objects if scene else [])}
    people = {p.id: person_view(p, knowledge) for p in (scene.people if scene else [])}
    for relation in scene.relations if scene else []:
        if relation.subject in objects:
            view = objects[relation.subject]
            target = relation.object.lower().replace("_", " ")
            view.place_words = view.place_words | set(target.split()) | {relation.relation}
            if relation.relation in ("in", "inside", "on") and relation.object in objects:
                other = objects[relation.object]
                view.place_words = view.place_words | set(_spaced(other.type).split())
    holders = _holders_by_id(scene)
    for view in objects.values():
        view.holders = tuple(holders.get(view.id, ()))
        for holder_id in view.holders:
            holder = objects.get(holder_id) if holder_id else None
            if holder is not None:
                location = str(holder.properties.get("location", "")).lower()
                view.place_words = view.place_words | set(_spaced(holder.type).split()) | set(
                    location.replace("_", " ").split()) | set((holder.name or "").lower().split())
    user = _user_view(request, people, knowledge)
    people_known = scene is not None and "people" in scene.model_fields_set
    if user is not None and user.id not in people:
        people[user.id] = user  # virtual: counted by no presence question (see SceneView)
    layout = scene.layout if scene else None
    return SceneView(
        objects=objects, people=people, rooms=list(layout.rooms) if layout else [],
        connections=list(layout.connections) if layout else [],
        scene_given=scene is not None,
        people_known=people_known,
        user=user, robot_room=request.robot.room if request.robot else None)


def _holders_by_id(scene: Any) -> dict[str, list[str]]:
    """Object id -> ids of what it rests on or in: its own fields first, then the relations."""
    found: dict[str, list[str]] = {}
    if scene is not None:
        for obj in scene.objects:
            found.setdefault(obj.id, []).extend(i for i in (obj.on, obj.inside) if i)
        for relation in scene.relations:
            if relation.relation in ("in", "inside", "on", "under"):
                found.setdefault(relation.subject, []).append(relation.object)
    return found


def _user_view(request: GateRequest, people: dict[str, PersonView], knowledge: Knowledge
               ) -> PersonView | None:
    profile = request.user
    person = people.get(profile.person_id) if profile and profile.person_id else None
    if person is None:
        person = next((p for p in people.values() if p.role in ("user", "me")), None)
    if person is None:
        person = PersonView(id=(profile.person_id if profile and profile.person_id else "user"),
                            role=None, virtual=True)
    person.is_user = True
    if profile is not None:
        if profile.age_group and not person.age_group:
            person.age_group, person.age_level = profile.age_group, Level.USER
            person.age_stated = True
            person.young = person.young or profile.age_group == "infant"
        if profile.mobility and not person.mobility:
            person.mobility = profile.mobility
            if person.needs_walking_aid is None:
                person.needs_walking_aid = profile.mobility in ("assisted", "wheelchair")
        if profile.cognitive_state and not person.cognitive_state:
            person.cognitive_state = profile.cognitive_state
        if profile.allergies is not None and person.allergies is None:
            person.allergies = tuple(a.lower() for a in profile.allergies)
    return person
