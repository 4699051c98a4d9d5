"""Answers to the gate's questions, folded back into the request so the pipeline can run again.

In: a `GateRequest`, the caller's answers keyed by the unknowns' attributes ({"age_group":
"adult"}, {"contents": "water"}, {"allergic_to": false}, {"owner": "grandpa"}, {"location":
"bedroom"}, {"hot": false}, {"command": "put the blue mug in the sink"}), and the unknowns they
answer (whose `entity` says which person or object each is about). Out: a new `GateRequest`
with each answer written onto that entity (an entity the scene lacked is added); a `command`
answer (to a comprehension question) replaces the command. Pure; unexpected keys are ignored.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from app.domain.models import GateRequest, UnknownFact

_PERSON_KEYS = frozenset({"age_group", "age", "mobility", "cognitive_state", "pregnant",
                          "consents", "needs_walking_aid", "visual_impairment",
                          "hearing_impairment", "allergies"})
_USER_FIELDS = frozenset({"age_group", "mobility", "cognitive_state", "allergies"})
# Object questions by attribute, and the request property each answer sets.
_OBJECT_KEYS = {"contents": "contents", "owner": "owner", "is_on": "on", "hot": "temperature",
                "mass_kg": "mass_kg"}
_ASLEEP = {"asleep": "asleep", "impaired": "impaired"}
# Object properties with a fixed meaning (gate-request spec), set by the generic rule below.
_OBJECT_FLAGS = ("lidded", "sealed", "sharp", "fragile", "toxic", "flammable", "open", "broken",
                 "electrical", "wet", "temperature")
ANSWERABLE_ATTRIBUTES: Mapping[str, str] = {
    **{key: "person" for key in sorted(_PERSON_KEYS | _ASLEEP.keys() | {"allergic_to",
                                                                         "location"})},
    **{key: "object" for key in (*_OBJECT_KEYS, *_OBJECT_FLAGS)},
    "command": "task",
}
"""Every unknown attribute an answer is applied for, and what it is about (a person, an object
the unknown names, or the task itself); analyzers that name unknowns freely (the LLM) are held to
these names, so an answer never goes unapplied and the same question does not come back."""


def apply_answers(request: GateRequest, answers: Mapping[str, Any],
                  unknowns: Iterable[UnknownFact]) -> GateRequest:
    """Write the caller's answers onto the entities the unknowns were about.

    Args:
        request: the request the unknowns came from.
        answers: attribute -> answer.
        unknowns: the unknowns being answered (their `attribute` and `entity` say where).

    Returns:
        A new `GateRequest`; the original is not changed.
    """
    data = request.model_dump(by_alias=True, exclude_unset=True)
    targets = {u.attribute: u.entity for u in unknowns}
    person_target = next((u.entity for u in unknowns if u.attribute in _PERSON_KEYS
                          or u.attribute in _ASLEEP), None)
    for key, value in answers.items():
        entity = targets.get(key) or (person_target if key in _PERSON_KEYS else None)
        if key == "command" and isinstance(value, str) and value.strip():
            data["command"] = value.strip()
        elif key == "allergic_to":
            _person(data, entity)["allergies"] = [] if value is False else (
                value if isinstance(value, list) else [str(value)])
        elif key in _ASLEEP:
            _person(data, entity)["cognitive_state"] = (
                _ASLEEP[key] if value else "typical")
        elif key in _PERSON_KEYS:
            _person(data, entity)[key] = value
        elif key == "location" and entity and isinstance(value, str):
            _item(data, "people", entity)["room"] = value
        elif key == "hot" and entity:
            _item(data, "objects", entity)["properties"]["temperature"] = (
                "hot" if value else "room")
        elif key in _OBJECT_KEYS and entity:
            _item(data, "objects", entity)["properties"][_OBJECT_KEYS[key]] = value
        elif entity and key.isidentifier():
            _item(data, "objects", entity)["properties"][key] = value
    return GateRequest.model_validate(data)


def _listed(data: dict[str, Any], key: str) -> list[dict[str, Any]]:
    # Created only when an answer needs it: an added `people` list means "people known".
    scene: dict[str, Any] = data.setdefault("scene", {})
    found: list[dict[str, Any]] = scene.setdefault(key, [])
    return found


def _item(data: dict[str, Any], key: str, entity: str) -> dict[str, Any]:
    for item in _listed(data, key):
        if item.get("id") == entity:
            item.setdefault("properties", {})
            return item
    created: dict[str, Any] = {"id": entity, "properties": {}}
    label = entity.removeprefix("new_").replace("_", " ")
    created["type" if key == "objects" else "role"] = label
    _listed(data, key).append(created)
    return created


def _person(data: dict[str, Any], entity: str | None) -> dict[str, Any]:
    """The properties to write a person answer into: the scene person's, or the user's."""
    user = data.get("user") or {}
    if entity is None or entity in ("user", user.get("person_id")):
        scene_people = (data.get("scene") or {}).get("people", [])
        if entity is None or not any(p.get("id") == entity for p in scene_people):
            if not isinstance(data.get("user"), dict):
                data["user"] = {}
            fields: dict[str, Any] = data["user"]
            return fields
    properties: dict[str, Any] = _item(data, "people", entity)["properties"]
    return properties
