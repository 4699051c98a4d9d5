"""Plain-language questions for unknowns, and folding the caller's answers back into a request.

In: an unknown's attribute and the words naming what it is about (`phrase_question`), or an
`UnknownFact` (`question_for`); for `apply_answers`, a `GateRequest`, the caller's answers
({"age_group": "adult"}, {"contents": "water"}, {"person_present": false},
{"person_location": "bedroom"}, {"material": "glass"}, {"presence": true}...) and the unknowns
they answer. Out: one question string; a new `GateRequest` with the answers written onto the
entity each unknown was about (a person or object the scene lacked is added), so the pipeline
can run again. Pure functions; never fail on unexpected keys (those are ignored).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any

from app.domain.models import GateRequest, UnknownFact

_TEMPLATES = {
    "age_group": "How old is {0}?",
    "age": "How old is {0}?",
    "allergies": "Is {0} allergic to {1}?",
    "contents": "What is in {0}?",
    "referent": "Which {0} do you mean: {1}?",
    "person_present": "Is anyone in {0} right now?",
    "child_present": "Is there a baby or young child in the home?",
    "medication_owner": "Whose medication is {0}, and is it meant for {1}?",
    "needs_walking_aid": "Does {0} need {1} to get around?",
    "consent": "Has {0} agreed to this?",
    "presence": "Will someone stay at home to watch {0}?",
    "person_location": "Where is {0} right now?",
    "material": "What is {0} made of?",
    "mass_kg": "About how heavy is {0}?",
    "temperature": "How hot is {0} right now?",
    "cognitive_state": "Can {0} manage this safely on their own?",
    "last_dose": "When was the last dose of {0} taken?",
    "time_left_out": "How long has {0} been out of the fridge?",
}
_PERSON_KEYS = frozenset({"age_group", "age", "mobility", "cognitive_state", "allergies",
                          "needs_walking_aid", "pregnant", "consents", "visual_impairment",
                          "hearing_impairment"})
_USER_FIELDS = frozenset({"age_group", "mobility", "cognitive_state", "allergies"})
_OBJECT_KEYS = frozenset({"contents", "temperature", "toxic", "sharp", "mass_kg", "owner",
                          "lidded", "sealed", "on", "open", "fragile", "electrical",
                          "material", "last_dose", "time_left_out"})


def phrase_question(attribute: str, subject: str, detail: str = "") -> str:
    """One plain question about an unknown attribute of a subject.

    Args:
        attribute: the unknown's attribute (`age_group`, `contents`, `allergies`...).
        subject: the words naming what it is about ("the guest", "the cup on the counter").
        detail: a second phrase some questions need (the allergen, the candidates...).

    Returns:
        The question, ending with a question mark.
    """
    template = _TEMPLATES.get(attribute)
    if template is None:
        return f"What is the {attribute.replace('_', ' ')} of {subject}?"
    return template.format(subject, detail or "it").replace("  ", " ")


def question_for(unknown: UnknownFact) -> str:
    """The question to ask for an unknown: its own if it has one, else a generic one."""
    if unknown.question:
        return unknown.question
    return phrase_question(unknown.attribute, unknown.entity or unknown.description)


def apply_answers(request: GateRequest, answers: Mapping[str, Any],
                  unknowns: Iterable[UnknownFact]) -> GateRequest:
    """Write the caller's answers onto the entities the unknowns were about.

    Args:
        request: the request the unknowns came from.
        answers: attribute -> answer, e.g. {"age_group": "adult"} or {"person_present": False}.
        unknowns: the unknowns being answered (their `attribute` and `entity` say where).

    Returns:
        A new `GateRequest`; the original is not changed.
    """
    data = request.model_dump(by_alias=True, exclude_unset=True)

    def listed(key: str) -> list[dict[str, Any]]:
        # Created only when an answer needs it: an added `people` list means "people known".
        scene: dict[str, Any] = data.setdefault("scene", {})
        found: list[dict[str, Any]] = scene.setdefault(key, [])
        return found

    targets = {u.attribute: u.entity for u in unknowns}
    for key, value in answers.items():
        attribute = "allergies" if key == "allergy" else key
        entity = targets.get(attribute) or targets.get(_alias(attribute))
        if attribute in ("person_present", "child_present"):
            _presence(listed("people"), attribute, entity, bool(value))
        elif attribute == "referent" and isinstance(value, str):
            for obj in listed("objects"):
                if obj["id"] == value:
                    obj.setdefault("properties", {})["intended"] = True
        elif attribute == "person_location" and entity and isinstance(value, str):
            _entity(listed("people"), entity, kind="person")["room"] = value
        elif attribute == "presence" and value:
            _presence(listed("people"), "person_present", _room_of(data, entity), True)
        elif attribute == "medication_owner" and entity:
            _entity(listed("objects"), entity, kind="object")["properties"]["owner"] = str(value)
        elif attribute in _PERSON_KEYS:
            _answer_person(data, listed, entity, attribute, value)
        elif attribute in _OBJECT_KEYS and entity:
            _entity(listed("objects"), entity, kind="object")["properties"][attribute] = value
    return GateRequest.model_validate(data)


def _room_of(data: dict[str, Any], entity: str | None) -> str | None:
    for obj in (data.get("scene") or {}).get("objects", []):
        if obj.get("id") == entity:
            room = obj.get("room")
            return str(room) if room else None
    return None


def _alias(attribute: str) -> str:
    return {"age": "age_group", "owner": "medication_owner"}.get(attribute, attribute)


def _entity(items: list[dict[str, Any]], entity: str, *, kind: str) -> dict[str, Any]:
    for item in items:
        if item.get("id") == entity:
            item.setdefault("properties", {})
            return item
    created: dict[str, Any] = {"id": entity, "properties": {}}
    if kind == "object":
        created["type"] = entity.replace("_", " ")
    else:
        created["role"] = entity.replace("_", " ")
    items.append(created)
    return created


def _answer_person(data: dict[str, Any], listed: Callable[[str], list[dict[str, Any]]],
                   entity: str | None, attribute: str, value: Any) -> None:
    user = data.get("user") or {}
    user_id = user.get("person_id") or "user"
    if entity is None or entity == user_id:
        if attribute in _USER_FIELDS:
            data.setdefault("user", {})[attribute] = value
            data["user"]["unknowns"] = [u for u in data["user"].get("unknowns", [])
                                        if attribute.split("_")[0] not in u]
        scene_people = (data.get("scene") or {}).get("people", [])
        if entity is None or not any(p.get("id") == entity for p in scene_people):
            return
    person = _entity(listed("people"), entity, kind="person")
    person["properties"][attribute] = value


def _presence(people: list[dict[str, Any]], attribute: str, room: str | None,
              present: bool) -> None:
    # Listing the scene's people (even as an empty list) is what says "we know who is here".
    if not present:
        return
    person: dict[str, Any] = {"id": f"present_{room or 'home'}", "properties": {}}
    if room:
        person["room"] = room
    if attribute == "child_present":
        person["role"] = "child"
        person["properties"]["age_group"] = "child"
    people.append(person)

