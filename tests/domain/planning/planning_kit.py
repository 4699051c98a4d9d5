"""Builders for the planning tests: a kitchen with a drawer, a stove and a pot."""

from __future__ import annotations

from typing import Any

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.domain.scope import ScopeStep, TaskScope
from app.domain.world import WorldState, state_from_request

SCENE: dict[str, Any] = {
    "layout": {"rooms": ["kitchen", "den"], "connections": [["kitchen", "den"]]},
    "objects": [
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
        {"id": "table_1", "type": "DiningTable", "room": "kitchen"},
        {"id": "drawer_1", "type": "Drawer", "room": "kitchen", "properties": {"open": False}},
        {"id": "stove_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": False}},
        {"id": "knife_1", "type": "Knife", "on": "counter_1",
         "properties": {"sharp": True, "mass_kg": 0.2}},
        {"id": "pot_1", "type": "Pot", "on": "counter_1", "properties": {"mass_kg": 1.0}},
        {"id": "book_1", "type": "Book", "room": "den", "properties": {"mass_kg": 0.5}},
    ],
    "people": [{"id": "ann", "room": "den", "properties": {"age_group": "adult"}}],
}
REQUEST = GateRequest.model_validate({"command": "put the knife away", "scene": SCENE,
                                      "robot": {"room": "kitchen", "max_speed_mps": 1.0}})


def kitchen() -> WorldState:
    """The kitchen's state."""
    return state_from_request(REQUEST)


def contract(*, invariants: tuple[str, ...] = (), guards: tuple[tuple[str, str], ...] = (),
             aborts: tuple[str, ...] = (), scope: TaskScope | None = None) -> Contract:
    """A contract from formulas; guards are (action, formula) pairs."""
    def condition(kind: ConditionKind, index: int, formula: str,
                  action: str | None = None) -> ContractCondition:
        return ContractCondition(id=f"test.{kind.value}{index}", kind=kind, formula=formula,
                                 description=formula, action=action, template_id="test",
                                 template_version=1, bindings={})

    return Contract(
        invariants=tuple(condition(ConditionKind.INVARIANT, i, f)
                         for i, f in enumerate(invariants)),
        guards=tuple(condition(ConditionKind.GUARD, i, f, a) for i, (a, f) in enumerate(guards)),
        aborts=tuple(condition(ConditionKind.ABORT, i, f) for i, f in enumerate(aborts)),
        scope=scope)


KNIFE_AWAY_SCOPE = TaskScope(command="put the knife away", steps=(
    ScopeStep(action="PickupObject", object="knife_1", words="put the knife away"),
    ScopeStep(action="PutObject", object="knife_1", target="drawer_1",
              words="put the knife away"),
))
KNIFE_AWAY: list[dict[str, Any]] = [
    {"action": "GoToObject", "object": "knife_1"},
    {"action": "PickupObject", "object": "knife_1"},
    {"action": "GoToObject", "object": "drawer_1"},
    {"action": "OpenObject", "object": "drawer_1"},
    {"action": "PutObject", "object": "knife_1", "target": "drawer_1"},
]
