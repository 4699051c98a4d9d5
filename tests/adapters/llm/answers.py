"""Scripted LLM answers and requests shared by the adapter tests."""

from __future__ import annotations

from typing import Any

from app.domain.models import GateRequest

CATEGORIES = ("physical", "psychological", "operational", "consequential")


def with_cells(payload: Any) -> Any:
    """A level answer (or a batched one) with every open cell answered "none, because ...".

    Most tests are about something else than the twelve cells; a scripted model that answers
    them keeps those tests to their point. A level whose `none_because` is given (even `{}`)
    is left as written, so the cell tests can leave cells open.
    """
    if not isinstance(payload, dict):
        return payload
    if {"task", "deployment", "user"} <= payload.keys():
        return {**payload, **{k: with_cells(payload[k]) for k in ("task", "deployment", "user")}}
    if "hazards" not in payload or "none_because" in payload:
        return payload
    covered = {h.get("category") for h in payload["hazards"] if isinstance(h, dict)}
    return {**payload, "none_because": {
        c: f"none, because the scripted answer has no {c} hazard" for c in CATEGORIES
        if c not in covered}}


EMPTY_LEVEL: dict[str, Any] = with_cells({"hazards": [], "unknowns": []})


def batched(levels: list[dict[str, Any]]) -> dict[str, Any]:
    """Three level answers (task, deployment, user) as one batched answer."""
    task, deployment, user = levels
    return {"task": task, "deployment": deployment, "user": user}


def wants_batched(body: dict[str, Any]) -> bool:
    """Whether a chat request asks for the three levels at once (its schema has `task`)."""
    response_format = body.get("response_format") or {}
    schema = (response_format.get("json_schema") or {}).get("schema") \
        or response_format.get("schema") or {}
    return "task" in schema.get("properties", {})

# A command the gate authorizes when the analysis finds nothing: the contrast that shows a
# failure test would notice an authorize.
SAFE_REQUEST = GateRequest.model_validate({
    "command": "put the apple in the fridge",
    "scene": {
        "objects": [
            {"id": "apple_1", "type": "Apple", "room": "kitchen", "on": "counter_1"},
            {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "fridge_1", "type": "Fridge", "room": "kitchen"},
        ],
        "people": [{"id": "p1", "role": "owner", "room": "living_room",
                    "properties": {"age_group": "adult"}}],
    },
    "user": {"person_id": "p1", "age_group": "adult", "mobility": "independent",
             "cognitive_state": "typical"},
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place", "open", "close"],
              "payload_kg": 2.0},
})

COFFEE_REQUEST = GateRequest.model_validate({
    "command": "bring the hot coffee to the guest in the living room",
    "scene": {
        "layout": {"rooms": ["kitchen", "living_room"]},
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen",
             "properties": {"temperature": "hot", "contents": "coffee", "lidded": False}},
        ],
        "people": [{"id": "guest_1", "role": "guest", "room": "living_room"}],
    },
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place", "handover"]},
})


def hazard(
    hazard_class: str = "scald_hot_liquid",
    *,
    category: str = "physical",
    entities: dict[str, str] | None = None,
    severity: str = "high",
    preventability: str = "preventable",
    confidence: str = "certain",
) -> dict[str, Any]:
    """One matrix entry as the LLM would write it."""
    return {
        "category": category,
        "hazard_class": hazard_class,
        "mechanism": f"{hazard_class.replace('_', ' ')} while doing the task",
        "entities": entities or {},
        "severity": severity,
        "preventability": preventability,
        "confidence": confidence,
    }


def unknown(attribute: str = "age_group", *, critical: bool = True,
            entity: str | None = "guest_1") -> dict[str, Any]:
    """One unknown as the LLM would write it."""
    return {
        "attribute": attribute,
        "description": f"the {attribute} of the person is not stated",
        "critical": critical,
        "why": "a child could be scalded",
        "entity": entity,
        "question": f"What is the guest's {attribute}?",
    }


def harmless_levels(obj: str = "apple_1") -> list[dict[str, Any]]:
    """An honest matrix for an ordinary task: one negligible, preventable object_damage hazard,
    tied to its object from the deployment level on (the seed library binds it)."""
    damage = hazard("object_damage", severity="negligible")
    tied = hazard("object_damage", severity="negligible", entities={"obj": obj})
    return [{"hazards": [damage], "unknowns": []},
            {"hazards": [tied], "unknowns": []},
            {"hazards": [tied], "unknowns": []}]


# A hot drink for one of two people: the child's age is what makes it unsafe.
TWO_PEOPLE_REQUEST = GateRequest.model_validate({
    "command": "bring the hot coffee to the living room",
    "scene": {
        "layout": {"rooms": ["kitchen", "living_room"]},
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen",
             "properties": {"temperature": "hot", "contents": "coffee", "lidded": False}},
        ],
        "people": [{"id": "kid_1", "role": "child", "room": "living_room"},
                   {"id": "guest_1", "role": "guest", "room": "living_room"}],
    },
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place", "handover"]},
})


def honest_script(request: GateRequest) -> dict[str, dict[str, Any]]:
    """What a careful model answers per prompt ("task", "deployment", "user", and "entities"
    for the entity round) for SAFE_REQUEST (authorized) and TWO_PEOPLE_REQUEST (deferred: the
    child's age is not stated)."""
    if request == SAFE_REQUEST:
        task, deployment, user = (with_cells(level) for level in harmless_levels())
        return {"task": task, "deployment": deployment, "user": user, "entities": user}
    scald_mug = hazard("scald_hot_liquid", entities={"obj": "mug_1"})
    child = {"hazards": [scald_mug], "unknowns": [unknown(entity="kid_1")]}
    return {"task": with_cells({"hazards": [hazard("scald_hot_liquid")],
                                "unknowns": [unknown(entity=None)]}),
            "deployment": with_cells(child), "user": with_cells(child),
            "entities": {"hazards": [scald_mug], "unknowns": []}}
