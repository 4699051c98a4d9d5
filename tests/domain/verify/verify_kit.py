"""Builders for the Stage 5 tests: small kitchen scenes and hand-written contracts."""

from __future__ import annotations

import copy
from typing import Any

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.domain.world import WorldState, state_from_request

KITCHEN: dict[str, Any] = {
    "layout": {"rooms": ["kitchen", "den"], "connections": [["kitchen", "den"]]},
    "objects": [
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
        {"id": "table_1", "type": "DiningTable", "room": "kitchen"},
        {"id": "mug_1", "type": "Mug", "on": "counter_1",
         "properties": {"temperature": "hot", "contents": "coffee"}},
        {"id": "knife_1", "type": "Knife", "on": "counter_1"},
        {"id": "vase_1", "type": "Jar", "on": "table_1",
         "properties": {"pickupable": True}},
        {"id": "book_1", "type": "Book", "room": "den"},
        {"id": "widget_1", "type": "Widget", "on": "table_1"},
    ],
    "people": [
        {"id": "ann", "room": "kitchen", "properties": {"age_group": "adult"}},
        {"id": "tom", "room": "den"},
    ],
}


def kitchen(**object_properties: dict[str, Any]) -> WorldState:
    """The kitchen scene, with extra properties for some objects (`vase_1={"lidded": True}`)."""
    scene = copy.deepcopy(KITCHEN)
    for obj in scene["objects"]:
        obj.setdefault("properties", {}).update(object_properties.get(obj["id"], {}))
    request = {"command": "test", "scene": scene, "robot": {"room": "kitchen"}}
    return state_from_request(GateRequest.model_validate(request))


def condition(kind: ConditionKind, formula: str, *, action: str | None = None,
              id_: str | None = None) -> ContractCondition:
    """A bound contract condition written by hand."""
    return ContractCondition(
        id=id_ or f"test.{kind.value}", kind=kind, formula=formula,
        description=f"{kind.value}: {formula}", action=action, template_id="test",
        template_version=1, bindings={})


def contract(*, invariants: tuple[str, ...] = (), guards: tuple[tuple[str, str], ...] = (),
             aborts: tuple[str, ...] = ()) -> Contract:
    """A contract from formulas; guards are (action, formula) pairs."""
    return Contract(
        invariants=tuple(condition(ConditionKind.INVARIANT, f, id_=f"inv{i}")
                         for i, f in enumerate(invariants)),
        guards=tuple(condition(ConditionKind.GUARD, f, action=a, id_=f"guard{i}")
                     for i, (a, f) in enumerate(guards)),
        aborts=tuple(condition(ConditionKind.ABORT, f, id_=f"abort{i}")
                     for i, f in enumerate(aborts)),
    )


PICK_KNIFE: list[dict[str, Any]] = [
    {"action": "GoToObject", "object": "knife_1"},
    {"action": "PickupObject", "object": "knife_1"},
    {"action": "GoToObject", "object": "table_1"},
    {"action": "PutObject", "object": "knife_1", "target": "table_1"},
]
