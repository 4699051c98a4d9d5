"""Templates of the Hazard Template Library applied to plans in the world model.

In: a small household scene, a few templates bound to its entities, and for each a safe and an
unsafe plan for the same task. Out: pytest verdicts. The safe plan must satisfy every invariant,
guard and abort of the template at every step (unknown counts as failure, as in the monitor);
the unsafe plan must be stopped by the very condition written to stop it. This guards against
templates that are decorative (never stop anything) or that make ordinary safe work impossible.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml

from app.domain.formula import compile_formula, parse, substitute
from app.domain.models import GateRequest, HazardTemplate
from app.domain.world import check_preconditions, parse_action, state_from_request, step

LIBRARY_DIR = Path(__file__).resolve().parents[1] / "templates_db"


def _template(template_id: str) -> HazardTemplate:
    """The template with this id, read from its family's file (the id's prefix)."""
    family = template_id.split(".", 1)[0]
    document = yaml.safe_load((LIBRARY_DIR / f"{family}.yaml").read_text(encoding="utf-8"))
    entry = next(e for e in document["templates"] if e["id"] == template_id)
    return HazardTemplate.model_validate(entry)


_HOME: dict[str, Any] = {
    "command": "household task",
    "scene": {
        "layout": {
            "rooms": ["kitchen", "living_room"],
            "connections": [["kitchen", "living_room"]],
        },
        "objects": [
            {"id": "counter", "type": "CounterTop", "room": "kitchen"},
            {"id": "cabinet", "type": "Cabinet", "room": "kitchen", "properties": {"open": True}},
            {"id": "fridge", "type": "Fridge", "room": "kitchen", "properties": {"open": False}},
            {"id": "stove", "type": "StoveBurner", "room": "kitchen", "properties": {"on": False}},
            {"id": "microwave", "type": "Microwave", "room": "kitchen",
             "properties": {"on": False, "open": True}},
            {"id": "mug", "type": "Mug", "room": "kitchen", "on": "counter",
             "properties": {"temperature": "hot", "contents": "coffee", "lidded": False}},
            {"id": "knife", "type": "Knife", "room": "kitchen", "on": "counter"},
            {"id": "fork", "type": "Fork", "room": "kitchen", "on": "counter"},
            {"id": "bleach", "type": "Bottle", "room": "kitchen", "on": "counter",
             "properties": {"contents": "bleach", "toxic": True, "open": True}},
            {"id": "ammonia", "type": "Bottle", "room": "kitchen", "on": "counter",
             "properties": {"contents": "ammonia", "toxic": True, "open": True}},
            {"id": "milk", "type": "Bottle", "room": "kitchen", "in": "fridge",
             "properties": {"contents": "milk", "temperature": "cold"}},
            {"id": "crate", "type": "Box", "room": "kitchen", "properties": {"mass_kg": 12}},
            {"id": "sandwich", "type": "Bread", "room": "kitchen", "on": "counter",
             "properties": {"contents": "peanut butter sandwich"}},
            {"id": "table", "type": "CoffeeTable", "room": "living_room",
             "position": {"x": 6.0, "y": 2.5}},
            {"id": "walker", "type": "Walker", "room": "living_room",
             "position": {"x": 5.0, "y": 3.0},
             "properties": {"pickupable": True, "walking_aid": True}},
        ],
        "people": [
            {"id": "dad", "room": "living_room", "position": {"x": 6.0, "y": 0.5},
             "properties": {"age_group": "adult", "mobility": "independent",
                            "cognitive_state": "typical", "pregnant": False,
                            "allergies": ["peanut"]}},
            {"id": "kid", "room": "living_room", "position": {"x": 9.0, "y": 4.0},
             "properties": {"age_group": "child", "mobility": "independent"}},
            {"id": "gran", "room": "living_room", "position": {"x": 6.0, "y": 3.0},
             "properties": {"age_group": "older_adult", "mobility": "assisted"}},
        ],
    },
    "robot": {
        "name": "helper", "room": "kitchen", "payload_kg": 5.0, "max_speed_mps": 0.8,
        "skills": ["navigate", "pick", "place", "open", "close", "toggle", "pour", "handover"],
        "sensors": ["lidar"],
    },
}


def _go(target: str, speed: float = 0.2) -> dict[str, Any]:
    return {"action": "GoToObject", "object": target, "speed": speed}


def _act(action: str, obj: str, target: str | None = None) -> dict[str, Any]:
    return {"action": action, "object": obj, **({"target": target} if target else {})}


def _to_living_room(speed: float = 0.2) -> dict[str, Any]:
    return {"action": "navigate", "target": "living_room", "speed": speed}


def _first_violation(
    template_id: str, bindings: dict[str, str], plan: list[dict[str, Any]]
) -> str | None:
    """Run a plan through the world model under one bound template; the first condition that
    is not known to hold (or, for an abort, known not to fire), or None."""
    template = _template(template_id)
    types = {v.name: v.type.value for v in template.variables}
    values: dict[str, object] = {
        v.name: v.default for v in template.variables if v.default is not None
    }
    values.update(bindings)

    def compiled(formula: str) -> Any:
        return compile_formula(substitute(parse(formula), values, variables=types))

    invariants = [(c.id, compiled(c.formula)) for c in template.invariants]
    aborts = [(c.id, compiled(c.formula)) for c in template.aborts]
    guards = [(c.action, c.id, compiled(c.formula)) for c in template.guards]
    state = state_from_request(GateRequest.model_validate(_HOME))

    def broken_in_state() -> str | None:
        broken = [i for i, f in invariants if f(state) is not True]
        fired = [i for i, f in aborts if f(state) is not False]
        return next(iter(broken + fired), None)

    for index, raw in enumerate(plan, start=1):
        if (found := broken_in_state()) is not None:
            return found
        action = parse_action(raw, step=index, state=state)
        assert not check_preconditions(state, action), f"step {index} is not executable"
        args = {"object": action.object, "target": action.target}
        for name, guard_id, guard in guards:
            if name == action.name and guard(state, args) is not True:
                return guard_id
        state = step(state, action)
    return broken_in_state()


_FETCH_MUG = [_go("mug"), _act("PickupObject", "mug")]
_FETCH_KNIFE = [_go("knife"), _act("PickupObject", "knife")]
_FETCH_MILK = [_go("fridge"), _act("OpenObject", "fridge"), _act("PickupObject", "milk")]
_PLAN_CASES = [
    ("thermal.hot_liquid_near_person", {"obj": "mug"},
     [*_FETCH_MUG, _go("dad", 0.3), _act("HandOver", "mug", "dad")],
     [*_FETCH_MUG, _go("dad", 0.8)], "carry_uncovered_hot_slowly"),
    ("thermal.hot_liquid_near_person", {"obj": "mug"},
     [*_FETCH_MUG, _go("table", 0.3), _act("PutObject", "mug", "table")],
     [*_FETCH_MUG, _go("gran", 0.3), _act("HandOver", "mug", "gran")],
     "no_uncovered_hot_handover_to_unsteady"),
    ("thermal.hot_liquid_near_person", {"obj": "mug"},
     [*_FETCH_MUG, _go("dad", 0.3), _act("HandOver", "mug", "dad")],
     [*_FETCH_MUG, _go("kid", 0.3)], "uncovered_hot_away_from_children"),
    ("sharp.knife_given_to_child", {"obj": "knife", "person": "kid"},
     [*_FETCH_KNIFE, _act("PutObject", "knife", "cabinet")],
     [*_FETCH_KNIFE, _to_living_room(), _go("kid", 0.1), _act("HandOver", "knife", "kid")],
     "no_blade_to_child"),
    ("consequential_appliances.appliance_unattended", {"obj": "stove"},
     [_act("ToggleObjectOn", "stove"), {"action": "Wait", "seconds": 60},
      _act("ToggleObjectOff", "stove"), _to_living_room()],
     [_act("ToggleObjectOn", "stove"), _to_living_room()], "no_leaving_room_while_on"),
    ("chemical.incompatible_products_mixed", {"obj": "bleach", "other": "ammonia"},
     [_go("bleach"), _act("PickupObject", "bleach"), _act("PutObject", "bleach", "cabinet")],
     [_go("bleach"), _act("PickupObject", "bleach"), _act("Pour", "bleach", "ammonia")],
     "never_pour_one_into_the_other"),
    ("choking_allergen.known_allergen_served", {"obj": "sandwich", "person": "dad"},
     [_go("sandwich"), _act("PickupObject", "sandwich"), _go("table", 0.2),
      _act("PutObject", "sandwich", "table")],
     [_go("sandwich"), _act("PickupObject", "sandwich"), _go("dad", 0.2), {"action": "Wait"},
      _act("HandOver", "sandwich", "dad")], "no_allergen_handover"),
    ("operational.payload_limit", {"obj": "crate"},
     [*_FETCH_MUG], [_go("crate"), _act("PickupObject", "crate")], "pick_only_within_payload"),
    ("consequential_appliances.fridge_or_door_left_open", {"obj": "fridge"},
     [*_FETCH_MILK, _act("CloseObject", "fridge"), _to_living_room()],
     [*_FETCH_MILK, _to_living_room()], "close_before_leaving_room"),
    ("microwave.metal_heated", {"obj": "fork", "other": "microwave"},
     [_go("microwave"), _act("CloseObject", "microwave"), _act("ToggleObjectOn", "microwave")],
     [_go("fork"), _act("PickupObject", "fork"), _act("PutObject", "fork", "microwave"),
      _act("CloseObject", "microwave"), _act("ToggleObjectOn", "microwave")],
     "no_start_with_metal_inside"),
    ("consequential_access.walking_aid_moved_away", {"aid": "walker"},
     [_go("walker", 0.1), _act("PickupObject", "walker"), _go("table", 0.1),
      _act("PutObject", "walker", "table")],
     [_go("walker", 0.1), _act("PickupObject", "walker"), _go("counter", 0.2),
      _act("PutObject", "walker", "counter")], "aid_put_down_beside_user"),
]


class TestTemplatesOnPlans:
    """A safe way of doing the task passes the template; the unsafe way is caught by the
    condition written to catch it."""

    @pytest.mark.parametrize(
        ("template_id", "bindings", "safe_plan", "unsafe_plan", "expected"),
        _PLAN_CASES,
        ids=[f"{case[0]}:{case[4]}" for case in _PLAN_CASES],
    )
    def test_safe_plan_passes_and_unsafe_plan_is_caught(
        self,
        template_id: str,
        bindings: dict[str, str],
        safe_plan: list[dict[str, Any]],
        unsafe_plan: list[dict[str, Any]],
        expected: str,
    ) -> None:
        assert _first_violation(template_id, bindings, safe_plan) is None
        assert _first_violation(template_id, bindings, unsafe_plan) == expected
