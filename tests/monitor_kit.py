"""Shared material for the monitoring tests: a scene, a hand-written contract, message builders.

The contract is written here rather than obtained from `POST /gate`, so these tests do not move
when the analyzer or the template library changes. `store_contract` puts it in a database the
way the gate would (a gate record with its contract).
"""

from __future__ import annotations

from typing import Any

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.store.records import ContractRecord, GateRecord
from app.store.repository import Repository

REQUEST: dict[str, Any] = {
    "command": "bring the mug to the living room",
    "scene": {
        "layout": {"rooms": ["kitchen", "living_room"],
                   "connections": [["kitchen", "living_room"]]},
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen", "on": "counter_1",
             "properties": {"mass_kg": 0.3}},
            {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "knife_1", "type": "Knife", "room": "kitchen", "properties": {"sharp": True}},
            {"id": "parcel_1", "type": "Gizmo", "room": "kitchen"},
            {"id": "stove_1", "type": "StoveBurner", "room": "kitchen",
             "properties": {"on": False}},
        ],
        "people": [
            {"id": "p1", "role": "owner", "room": "living_room",
             "properties": {"age_group": "adult"}},
            {"id": "child_1", "role": "son", "room": "living_room",
             "properties": {"age_group": "child"}},
        ],
    },
    "user": {"person_id": "p1", "age_group": "adult"},
    "robot": {"name": "stretch", "room": "kitchen", "payload_kg": 2.0,
              "skills": ["navigate", "pick", "place", "handover"]},
}


def condition(kind: ConditionKind, cid: str, formula: str, action: str | None = None,
              description: str = "") -> ContractCondition:
    return ContractCondition(id=cid, kind=kind, formula=formula,
                             description=description or f"{cid} must hold", action=action,
                             template_id=cid.split(".")[0], template_version=1, bindings={})


INVARIANT, GUARD, ABORT = ConditionKind.INVARIANT, ConditionKind.GUARD, ConditionKind.ABORT

CONTRACT = Contract(
    invariants=(
        condition(INVARIANT, "payload.within_limit", "load_kg(robot) <= payload(robot)"),
    ),
    guards=(
        condition(GUARD, "skill.pick", 'has_skill(robot, "pick")', "PickupObject"),
        condition(GUARD, "skill.toggle", 'has_skill(robot, "toggle")', "ToggleObjectOn"),
        condition(GUARD, "sharp.no_knife_handover", "@object != #knife_1", "HandOver"),
    ),
    aborts=(
        condition(ABORT, "stove.child_at_live_stove",
                  "is_on(#stove_1) and exists p: person . child(p) and near(p, #stove_1)"),
    ),
)


def store_contract(repository: Repository, contract: Contract = CONTRACT,
                   request: dict[str, Any] | None = None) -> str:
    """Store an authorized gate record with `contract`; returns the contract id."""
    record = repository.save_gate_record(GateRecord(
        request=GateRequest.model_validate(request or REQUEST), decision="authorize", rule="R4"))
    assert record.id is not None
    stored = repository.save_contract(ContractRecord(
        request_id=record.id, contract=contract.model_dump(mode="json"), max_attempts=3))
    assert stored.id is not None
    return stored.id


def before(seq: int, action: dict[str, Any], state: dict[str, Any] | None = None
           ) -> dict[str, Any]:
    message: dict[str, Any] = {"type": "before", "seq": seq, "action": action}
    if state is not None:
        message["state"] = state
    return message


def after(seq: int, action: dict[str, Any], state: dict[str, Any] | None = None
          ) -> dict[str, Any]:
    message: dict[str, Any] = {"type": "after", "seq": seq, "action": action}
    if state is not None:
        message["state"] = state
    return message


GO_TO_MUG = {"action": "GoToObject", "object": "mug_1"}
PICK_MUG = {"action": "PickupObject", "object": "mug_1"}
PICK_PARCEL = {"action": "pick", "object": "parcel_1"}
TOGGLE_STOVE = {"action": "ToggleObjectOn", "object": "stove_1"}
HAND_KNIFE = {"action": "HandOver", "object": "knife_1", "target": "p1"}
CHILD_AT_LIVE_STOVE = {"scene": {
    "objects": [{"id": "stove_1", "type": "StoveBurner", "room": "kitchen",
                 "properties": {"on": True}}],
    "people": [{"id": "child_1", "role": "son", "room": "kitchen",
                "properties": {"age_group": "child"}}],
}}


def safe_actions(count: int) -> list[dict[str, Any]]:
    """`count` actions the contract allows: walking back and forth between two objects."""
    return [{"action": "GoToObject", "object": "mug_1" if i % 2 == 0 else "counter_1"}
            for i in range(count)]


# The knife-to-the-block task: the robot fetches the knife from the kitchen counter while the
# owner sits in the living room. Carrying the blade fast near a person breaks the contract, so
# whether step 3 (`CARRY_KNIFE_FAST`) is allowed depends on what steps 1 and 2 left: the robot
# holding the knife. Checked against the initial state (the knife still on the counter) it
# would be allowed twice; that is the forgotten state a monitor must never resume from.
KNIFE_REQUEST: dict[str, Any] = {
    "command": "put the knife back in the block",
    "scene": {
        "layout": {"rooms": ["kitchen", "living_room"],
                   "connections": [["kitchen", "living_room"]]},
        "objects": [
            {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
            {"id": "knife_1", "type": "Knife", "room": "kitchen", "on": "counter_1",
             "properties": {"sharp": True}},
            {"id": "block_1", "type": "KnifeBlock", "room": "kitchen", "on": "counter_1"},
        ],
        "people": [{"id": "p1", "role": "owner", "room": "living_room", "posture": "sitting",
                    "properties": {"age_group": "adult"}}],
    },
    "user": {"person_id": "p1", "age_group": "adult"},
    "robot": {"name": "stretch", "room": "kitchen", "payload_kg": 2.0, "max_speed_mps": 1.0,
              "skills": ["navigate", "pick", "place"]},
}
KNIFE_CONTRACT = Contract(
    invariants=(
        condition(INVARIANT, "sharp.blade_carried_near_person.slow_with_blade_near_people",
                  "forall p: person . holding(robot, #knife_1) and sharp(#knife_1) and "
                  "near(robot, p) -> speed(robot) <= 0.25",
                  description="Move slowly whenever the robot holds the blade near a person"),
    ),
    guards=(
        condition(GUARD, "sharp.blade_carried_near_person.never_throw_blade",
                  "@object != #knife_1 or not sharp(#knife_1)", "ThrowObject"),
    ),
    aborts=(),
)
GO_TO_KNIFE = {"action": "GoToObject", "object": "knife_1"}
PICK_KNIFE = {"action": "PickupObject", "object": "knife_1"}
CARRY_KNIFE_FAST = {"action": "navigate", "target": "living_room", "speed": 1.0}


def store_knife_contract(repository: Repository) -> str:
    """Store the knife-to-the-block task's contract; returns its id."""
    return store_contract(repository, KNIFE_CONTRACT, KNIFE_REQUEST)
