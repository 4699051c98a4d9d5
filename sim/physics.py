"""AI2-THOR's own rules on top of the shared action model: what fails, and what happens by itself.

In: a `WorldState` and a parsed `Action` (`restrictions`), or the states before and after an
action (`automatic_effects`). Out: the reasons AI2-THOR would refuse the action (empty when it
runs), and the state after AI2-THOR's automatic effects that the shared model does not apply:
a container put under a running faucet fills and is rinsed, opening a running microwave stops it.
The shared model (`app.domain.world.step`) already heats what rests on an active heat source,
fills the cups of a running coffee machine and breaks thrown or dropped breakables.
Refusals: only toggleable objects toggle (a stove burner is lit by its knob), only openable ones
open, a microwave cannot run open, what is inside a closed receptacle cannot be taken out, nothing
goes into a closed receptacle, and an object only goes into receptacles AI2-THOR accepts for its
type: the documented receptacles, those instances start in and those the docs parse lost, from
the one AI2-THOR type table (`app/domain/world/ai2thor_table.py`). Fails: never.
"""

from __future__ import annotations

from dataclasses import replace
from functools import cache

from app.domain.formula.facts import FactValue
from app.domain.world import Action, WorldState
from app.domain.world.ai2thor_table import ai2thor_types
from app.domain.world.entities import ObjectState, frozen_mapping

_SINKS = frozenset({"Sink", "SinkBasin", "Bathtub", "BathtubBasin"})


@cache
def compatible_receptacles() -> dict[str, frozenset[str]]:
    """Receptacle types AI2-THOR accepts, by pickupable object type (the Floor always does)."""
    return {
        name: frozenset(
            {*row["receptacles"], *row["receptacles_start"], *row["receptacles_restored"]}
        ) - {"Floor"}
        for name, row in ai2thor_types().items()
        if row["flags"].get("pickupable") is True
    }


def _true(value: FactValue) -> bool:
    return value is True


def _closed_container(state: WorldState, obj: ObjectState | None) -> ObjectState | None:
    """The closed openable receptacle the object is inside, if any (up the receptacle chain)."""
    for _ in range(16):
        if obj is None or obj.parent is None or state.holder_of(obj.id) is not None:
            return None
        parent = state.objects.get(obj.parent)
        if parent is None:
            return None
        if parent.kind.flag("openable") and state.value("open", (parent.id,)) is not True:
            return parent
        obj = parent
    return None


def restrictions(state: WorldState, action: Action) -> list[str]:
    """Why AI2-THOR would refuse the action in this state; empty when it would run.

    Args:
        state: the state just before the action.
        action: the parsed action.

    Returns:
        Plain-word reasons.
    """
    name, obj = action.name, state.objects.get(action.object or "")
    target = state.objects.get(action.target or "")
    reasons: list[str] = []
    if name in ("ToggleObjectOn", "ToggleObjectOff") and obj is not None:
        if obj.kind.flag("toggleable") is False:
            reasons.append(f"{obj.type} cannot be toggled directly")
        if (name == "ToggleObjectOn" and obj.type == "Microwave"
                and _true(state.value("open", (obj.id,)))):
            reasons.append("a microwave cannot run with its door open")
    if name in ("OpenObject", "CloseObject") and obj is not None and (
            obj.kind.flag("openable") is False):
        reasons.append(f"{obj.type} cannot be opened or closed")
    if name == "PickupObject" and obj is not None:
        closed = _closed_container(state, obj)
        if closed is not None:
            reasons.append(f"it is inside {closed.id}, which is closed")
    if name == "PutObject" and obj is not None and target is not None:
        reasons.extend(_put_refusals(state, obj, target))
    if name in ("SliceObject",) and obj is not None and obj.kind.flag("sliceable") is False:
        reasons.append(f"{obj.type} cannot be sliced")
    if name == "FillWithLiquid" and obj is not None and obj.kind.flag("can_fill") is False:
        reasons.append(f"{obj.type} cannot hold a liquid")
    return reasons


def _put_refusals(state: WorldState, obj: ObjectState, target: ObjectState) -> list[str]:
    reasons: list[str] = []
    if target.kind.flag("receptacle") is False:
        reasons.append(f"{target.type} is not a receptacle")
    if target.kind.flag("openable") and state.value("open", (target.id,)) is not True:
        reasons.append(f"{target.id} is closed")
    allowed = compatible_receptacles().get(obj.type)
    if allowed is not None and target.type not in allowed and target.type != "Floor":
        reasons.append(f"AI2-THOR does not accept a {obj.type} in or on a {target.type}")
    return reasons


def _running_faucet_by(state: WorldState, sink: ObjectState) -> bool:
    room = state.room_of(sink.id)
    return any(o.type == "Faucet" and state.room_of(o.id) == room
               and state.value("is_on", (o.id,)) is True for o in state.objects.values())


def automatic_effects(before: WorldState, action: Action, after: WorldState) -> WorldState:
    """AI2-THOR's automatic effects that the shared action model leaves out.

    Args:
        before: the state before the action.
        action: the action that ran.
        after: the shared model's state after it.

    Returns:
        `after`, corrected.
    """
    state = after
    if action.name == "PutObject":
        obj, sink = state.objects.get(action.object or ""), state.objects.get(
            action.target or "")
        if obj is not None and sink is not None and sink.type in _SINKS and (
                _running_faucet_by(state, sink)):
            facts: dict[str, FactValue] = {"dirty": False, "wet": True}
            if obj.kind.flag("can_fill") and state.value("filled", (obj.id,)) is not True:
                facts.update(filled=True, contents="water")
            state = state.with_object(_with_facts(obj, facts))
    if action.name == "OpenObject":
        obj = state.objects.get(action.object or "")
        if obj is not None and obj.type == "Microwave" and _true(
                before.value("is_on", (obj.id,))):
            state = state.with_object(_with_facts(obj, {"is_on": False}))
    return state


def _with_facts(obj: ObjectState, facts: dict[str, FactValue]) -> ObjectState:
    return replace(obj, facts=frozen_mapping({**obj.facts, **facts}))
