"""Building a world state from a gate request, and applying a runtime's partial snapshot.

In: a `GateRequest` (scene, user, robot) or an `InitialState` (scene, robot); for snapshots an
existing `WorldState` and an `InitialState` that may list only what changed. Out: a new
`WorldState`. Receptacles come from an object's `on`/`in` fields and from `on`/`in` relations
(a relation wins); `holding` relations give what people (or the robot) hold; the other
relations are kept as they are. The user profile fills the attributes of the person
`user.person_id` names (the scene's own properties win on conflict); a user not in the scene
becomes a person whose room is unknown. A person whose age group nobody gave but whose role names
one ("grandma", "toddler", "dad") gets the age group the word implies; cognitive state and
mobility, when nobody gives them, are those of a typical household member (awake unless the
posture says asleep; walking unaided). Fails: never on a validated request; ids that do not
resolve simply leave facts unknown.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import replace
from typing import Any

from app.domain.models import (
    GateRequest,
    InitialState,
    Person,
    Position,
    RobotProfile,
    Scene,
    SceneObject,
    UserProfile,
)
from app.domain.world.entities import (
    ROBOT_ID,
    ObjectState,
    PersonState,
    Point,
    RobotState,
    frozen_mapping,
)
from app.domain.world.object_rules import ANIMAL_TYPES
from app.domain.world.object_types import normalize_type
from app.domain.world.people import implied_age_group
from app.domain.world.state import WorldState

_PLACING = {"on": "on", "in": "in", "inside": "in"}


def _point(position: Position | None) -> Point | None:
    return None if position is None else Point(position.x, position.y, position.z)


def _object(obj: SceneObject) -> ObjectState:
    relation, parent = ("in", obj.inside) if obj.inside else ("on", obj.on) if obj.on else (
        None, None)
    return ObjectState(
        id=obj.id, type=obj.type, name=obj.name, room=obj.room, parent=parent,
        relation=relation, position=_point(obj.position),
        properties=frozen_mapping(obj.properties),
    )


def _species(person: Person) -> str | None:
    """The kind of animal a `people` entry is ("species": "dog", a role "pet cat"), or None
    for a human: the request schema has no place for animals, so callers list pets there."""
    species = person.properties.get("species")
    if isinstance(species, str) and species.strip().lower() not in ("", "human", "person"):
        return species.strip().lower()
    words = (person.role or "").lower().replace("_", " ").split()
    return next((w for w in words if w in ANIMAL_TYPES and w != "pet"), None)


def _given_name(person: Person) -> str | None:
    """The name field, or the name records often keep among the properties."""
    named = person.properties.get("name")
    return person.name or (named.strip() if isinstance(named, str) and named.strip() else None)


def _pet(person: Person, species: str) -> ObjectState:
    return ObjectState(
        id=person.id, type=species.title().replace(" ", ""), name=_given_name(person),
        room=person.room, position=_point(person.position),
        properties=frozen_mapping({**person.properties, "species": species, "animal": True}))


def _pets(scene: Scene, objects: Mapping[str, ObjectState]) -> Iterable[ObjectState]:
    """Pets listed among the people, unless the objects already list the same animal (by
    name, or as the one animal of that species)."""
    for person in scene.people:
        species = _species(person)
        if species is None or person.id in objects:
            continue
        same = [o for o in objects.values() if normalize_type(o.type) == normalize_type(
            species) or str(o.properties.get("species", "")).lower() == species]
        name = _given_name(person)
        if any(name and (o.name or "").lower() == name.lower() for o in same) \
                or (same and not name):
            continue
        yield _pet(person, species)


def _user_attributes(user: UserProfile) -> dict[str, Any]:
    fields = ("age_group", "mobility", "cognitive_state", "allergies")
    found = {f: getattr(user, f) for f in fields if getattr(user, f) is not None}
    found.update({k: v for k, v in (user.model_extra or {}).items() if v is not None})
    return found


def _person(person: Person, user: UserProfile | None, holding: frozenset[str]) -> PersonState:
    properties = dict(person.properties)
    if user is not None and user.person_id == person.id:
        properties = {**_user_attributes(user), **properties}
    if "age_group" not in properties:
        implied = implied_age_group(person.role, person.name)
        if implied is not None:
            properties["age_group"] = implied
    # A household member nobody describes is awake, alert and walks unaided: impairments are
    # the caller's to state. Age is never assumed (only a role word implies one).
    if "cognitive_state" not in properties and (person.posture or "").lower() not in (
            "asleep", "sleeping", "lying_asleep"):
        properties["cognitive_state"] = "typical"
    properties.setdefault("mobility", "independent")
    return PersonState(
        id=person.id, role=person.role, name=_given_name(person),
        room=person.room,
        posture=person.posture, position=_point(person.position),
        properties=frozen_mapping(properties), holding=holding,
    )


def _robot(profile: RobotProfile | None, base: RobotState | None = None) -> RobotState:
    robot = base or RobotState()
    if profile is None:
        return robot
    given = profile.model_fields_set
    extra = profile.model_extra or {}
    changes: dict[str, Any] = {}
    for field, attribute in (("name", "name"), ("room", "room"), ("holding", "holding"),
                             ("payload_kg", "payload_kg"), ("max_speed_mps", "max_speed")):
        if field in given:
            changes[attribute] = getattr(profile, field)
    if "position" in given:
        changes["position"] = _point(profile.position)
    for field in ("skills", "sensors"):
        if field in given:
            values = getattr(profile, field)
            changes[field] = None if values is None else frozenset(values)
    if isinstance(extra.get("speed"), int | float):
        changes["speed"] = float(extra["speed"])
    if isinstance(extra.get("recording"), bool):
        changes["recording"] = extra["recording"]
    return replace(robot, **changes)


def _placements(scene: Scene) -> tuple[dict[str, tuple[str, str]], dict[str, set[str]],
                                       list[tuple[str, str, str]]]:
    """Receptacles by object, holdings by holder, and the remaining relations."""
    placed: dict[str, tuple[str, str]] = {}
    held: dict[str, set[str]] = {}
    others: list[tuple[str, str, str]] = []
    for rel in scene.relations:
        kind = rel.relation.strip().lower()
        if kind in _PLACING:
            placed[rel.subject] = (_PLACING[kind], rel.object)
        elif kind == "holding":
            held.setdefault(rel.subject, set()).add(rel.object)
        elif kind == "held_by":
            held.setdefault(rel.object, set()).add(rel.subject)
        else:
            others.append((rel.subject, kind, rel.object))
    return placed, held, others


def _scene_objects(scene: Scene, placed: Mapping[str, tuple[str, str]]) -> Iterable[ObjectState]:
    for obj in scene.objects:
        state = _object(obj)
        if obj.id in placed:
            relation, parent = placed[obj.id]
            state = replace(state, relation=relation, parent=parent)
        yield state
    if scene.layout is not None:
        for obstacle in scene.layout.obstacles:
            yield ObjectState(id=obstacle.id, type=obstacle.kind, room=obstacle.room,
                              obstacle=True)


def state_from_request(request: GateRequest | InitialState) -> WorldState:
    """The symbolic state a gate request (or a verify/monitor initial state) describes.

    Args:
        request: a validated gate request or initial state.

    Returns:
        The `WorldState`, version 0.
    """
    scene = request.scene or Scene()
    user = request.user if isinstance(request, GateRequest) else None
    placed, held, others = _placements(scene)
    robot = _robot(request.robot)
    if ROBOT_ID in held and robot.holding is None:
        robot = replace(robot, holding=sorted(held[ROBOT_ID])[0])
    objects = {o.id: o for o in _scene_objects(scene, placed)}
    pets = {pet.id: replace(pet, relation=placed[pet.id][0], parent=placed[pet.id][1])
            if pet.id in placed else pet for pet in _pets(scene, objects)}
    objects.update(pets)
    people = {p.id: _person(p, user, frozenset(held.get(p.id, ()))) for p in scene.people
              if p.id not in pets and _species(p) is None}
    if user is not None and user.person_id and user.person_id not in people:
        people[user.person_id] = PersonState(
            id=user.person_id, properties=frozen_mapping(_user_attributes(user)))
    layout = scene.layout
    return WorldState(
        robot=robot,
        objects=objects,
        people=people,
        rooms=layout.rooms if layout else (),
        connections=frozenset(
            pair for a, b in (layout.connections if layout else ()) for pair in ((a, b), (b, a))),
        relations=tuple(others),
        people_known=request.scene is not None and "people" in scene.model_fields_set,
    )


def apply_snapshot(state: WorldState, snapshot: InitialState) -> WorldState:
    """A runtime's partial observation applied to a state.

    Objects and people the snapshot lists replace those with the same id (new ids are added);
    robot fields the snapshot sets replace the robot's; a layout, if given, replaces the
    rooms and connections; everything else stays as it was.

    Args:
        state: the state before the observation.
        snapshot: the observation, shaped like an initial state.

    Returns:
        The new state.
    """
    partial = state_from_request(InitialState(scene=snapshot.scene))
    objects = {**state.objects, **partial.objects}
    people = dict(state.people)
    for person in partial.people.values():
        previous = people.get(person.id)
        keep = previous.holding if previous is not None and not person.holding else frozenset()
        people[person.id] = replace(person, holding=person.holding or keep)
    changes: dict[str, Any] = {
        "objects": objects, "people": people,
        "robot": _robot(snapshot.robot, state.robot),
        "people_known": state.people_known or partial.people_known,
    }
    scene = snapshot.scene
    if scene is not None and scene.layout is not None and "layout" in scene.model_fields_set:
        changes["rooms"], changes["connections"] = partial.rooms, partial.connections
    if partial.relations:
        replaced = {s for s, _, _ in partial.relations}
        changes["relations"] = tuple(
            r for r in state.relations if r[0] not in replaced) + partial.relations
    return state.evolve(**changes)
