"""The RoboGuard-style world model: a scene graph, and the command grounded in it.

In: a `GateRequest` and synonym tables (`data/roboguard_rules.yaml`). Out: a `SceneGraph`
(objects and people as `Entity` records with their attributes, rooms and their connections, the
robot, the user) and a `Grounding` of the command: which objects, people and rooms it mentions
and which action kinds it implies. Matching is on words: an object is mentioned by its type
("StoveBurner" -> "stove burner"), its name, its contents or a synonym; a person by name, role,
a synonym of the role, an age word, a group word ("kids", "everyone") or "me".
Fails: never on a well-formed request; a scene without a layout simply has no routes.
"""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from app.domain.models import GateRequest, RobotProfile
from bench.baselines.text import Lexicon, actions_in, normalise

_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])")
_ME = re.compile(r"\b(me|my|i|i'm|i'll)\b")
_AGE_WORDS: dict[str, tuple[str, ...]] = {
    "infant": ("baby", "babies", "toddler", "infant", "little one"),
    "child": ("kid", "kids", "child", "children", "little"),
}


@dataclass(frozen=True)
class Entity:
    """An object or a person of the scene, with the phrases that refer to it."""

    id: str
    type: str
    room: str | None
    phrases: frozenset[str]
    attrs: Mapping[str, Any]


@dataclass(frozen=True)
class SceneGraph:
    """The grounded world model of one request."""

    objects: tuple[Entity, ...]
    people: tuple[Entity, ...]
    rooms: tuple[str, ...]
    neighbours: Mapping[str, frozenset[str]]
    robot: RobotProfile | None
    user_id: str | None

    def route(self, start: str | None, goal: str) -> list[str] | None:
        """The rooms of a shortest route from `start` to `goal`, or None when unknown."""
        if start is None or start not in self.neighbours or goal not in self.neighbours:
            return None
        parents: dict[str, str | None] = {start: None}
        queue = deque([start])
        while queue:
            room = queue.popleft()
            if room == goal:
                path = [room]
                while (parent := parents[path[-1]]) is not None:
                    path.append(parent)
                return path[::-1]
            for nxt in sorted(self.neighbours[room]):
                if nxt not in parents:
                    parents[nxt] = room
                    queue.append(nxt)
        return None

    def people_in(self, rooms: Iterable[str]) -> list[Entity]:
        """The people whose stated room is one of `rooms`."""
        wanted = set(rooms)
        return [p for p in self.people if p.room in wanted]


@dataclass(frozen=True)
class Grounding:
    """What the command refers to in the scene and which actions it implies."""

    actions: frozenset[str]
    objects: tuple[Entity, ...]
    people: tuple[Entity, ...]
    rooms: frozenset[str]
    recipients: tuple[Entity, ...] = field(default=())


def _phrase_pattern(phrase: str) -> re.Pattern[str]:
    # Singular and plural both refer: "a cookie" names the jar of "peanut cookies".
    if len(phrase) > 3 and phrase.endswith("s") and not phrase.endswith("ss"):
        phrase = phrase[:-1]
    return re.compile(rf"\b{re.escape(phrase)}(?:s|es)?\b")


def _type_phrases(kind: str) -> set[str]:
    words = _CAMEL.sub(" ", kind).lower().split()
    phrases = {" ".join(words)}
    if len(words) > 1 and len(words[-1]) > 3:
        phrases.add(words[-1])
    return phrases


def build_scene_graph(request: GateRequest, synonyms: Mapping[str, Any]) -> SceneGraph:
    """The scene graph of a request; missing parts of the request stay missing."""
    scene = request.scene
    object_synonyms: Mapping[str, list[str]] = synonyms.get("objects", {})
    people_synonyms: Mapping[str, list[str]] = synonyms.get("people", {})
    objects: list[Entity] = []
    people: list[Entity] = []
    rooms: list[str] = []
    neighbours: dict[str, set[str]] = {}
    if scene is not None:
        for obj in scene.objects:
            phrases = _type_phrases(obj.type) | set(object_synonyms.get(obj.type, []))
            if obj.name:
                phrases.add(normalise(obj.name))
            contents = obj.properties.get("contents")
            words = normalise(contents).split() if isinstance(contents, str) else []
            if words and contents not in {"empty", "unknown"}:
                phrases |= {" ".join(words), words[-1]}
            # A flag such as fire_exit=True is also how people name the thing ("the fire exit").
            phrases |= {k.replace("_", " ") for k, v in obj.properties.items() if v is True
                        and k not in {"on", "open", "electrical", "sealed", "lidded"}}
            attrs = {**obj.properties, "type": obj.type, "support": obj.on or obj.inside}
            objects.append(Entity(obj.id, obj.type, obj.room, frozenset(phrases), attrs))
        for person in scene.people:
            role = normalise(person.role or "")
            phrases = {role, *role.split(), *people_synonyms.get(role, [])} - {""}
            if person.name:
                phrases.add(normalise(person.name))
            age = person.properties.get("age_group")
            phrases |= set(_AGE_WORDS.get(str(age), ()))
            attrs = {**person.properties, "posture": person.posture, "role": role}
            people.append(Entity(person.id, "Person", person.room, frozenset(phrases), attrs))
        if scene.layout is not None:
            rooms = list(scene.layout.rooms)
            neighbours = {room: set() for room in rooms}
            for a, b in scene.layout.connections:
                neighbours.setdefault(a, set()).add(b)
                neighbours.setdefault(b, set()).add(a)
    return SceneGraph(
        objects=tuple(objects),
        people=tuple(people),
        rooms=tuple(rooms),
        neighbours={room: frozenset(n) for room, n in neighbours.items()},
        robot=request.robot,
        user_id=request.user.person_id if request.user else None,
    )


def _mentions(entities: Iterable[Entity], text: str) -> list[Entity]:
    return [e for e in entities if any(_phrase_pattern(p).search(text) for p in e.phrases)]


def ground_command(
    graph: SceneGraph, command: str, actions: Lexicon, synonyms: Mapping[str, Any]
) -> Grounding:
    """Ground a command in the scene graph.

    Args:
        graph: from `build_scene_graph`.
        command: the natural-language command.
        actions: the action-kind lexicon.
        synonyms: the `synonyms` table (rooms and group words are read here).

    Returns:
        The mentioned objects, people (with group words expanded) and rooms, the implied action
        kinds, and the recipients: the people mentioned other than the user, else the user.
    """
    text = normalise(command)
    people = {p.id: p for p in _mentions(graph.people, text)}
    for word, target in synonyms.get("groups", {}).items():
        if _phrase_pattern(str(word)).search(text):
            for person in graph.people:
                if target == "all" or person.attrs.get("age_group") in target:
                    people.setdefault(person.id, person)
    user = next((p for p in graph.people if p.id == graph.user_id), None)
    if user is not None and _ME.search(text):
        people.setdefault(user.id, user)
    room_synonyms: Mapping[str, list[str]] = synonyms.get("rooms", {})
    rooms = {
        room for room in graph.rooms
        if any(_phrase_pattern(p).search(text)
               for p in {room.replace("_", " "), *room_synonyms.get(room, [])})
    }
    others = tuple(p for p in people.values() if p.id != graph.user_id)
    recipients = others or ((user,) if user is not None else ())
    return Grounding(
        actions=actions_in(command, actions),
        objects=tuple(_mentions(graph.objects, text)),
        people=tuple(people.values()),
        rooms=frozenset(rooms),
        recipients=recipients,
    )


def matches(attrs: Mapping[str, Any], condition: Mapping[str, Any]) -> bool:
    """Whether an entity's attributes satisfy a filter of the rules file.

    `attr: value` is equality, `attr: [..]` any-of (or a non-empty overlap when the attribute is
    itself a list), `attr~: [..]` a substring of the attribute's text. A missing attribute never
    matches: an unstated fact does not ground a rule.
    """
    for key, expected in condition.items():
        if key.endswith("~"):
            value = attrs.get(key[:-1])
            if not isinstance(value, str) or not any(s in value.lower() for s in expected):
                return False
            continue
        value = attrs.get(key)
        if value is None:
            return False
        if isinstance(expected, list):
            if isinstance(value, list):
                if not set(map(str, value)) & set(map(str, expected)):
                    return False
            elif value not in expected:
                return False
        elif value != expected:
            return False
    return True


def matches_any(attrs: Mapping[str, Any], conditions: Iterable[Mapping[str, Any]]) -> bool:
    """Whether at least one of the filters matches."""
    return any(matches(attrs, c) for c in conditions)
