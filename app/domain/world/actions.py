"""Plan steps as typed actions: parsing the wire shape into a canonical `Action`.

In: one plan step as the planner sent it, e.g. `{"action": "pick", "object": "mug_1"}`, its
index in the plan, and optionally the state it will run in. Out: an `Action` under its
canonical name with `object`/`target` ids and typed parameters. Argument spellings from
AI2-THOR and SMART-LLM are accepted (`objectId`, `receptacleObjectId`, `room`, `person`...).
Fails: `PlanError(step=...)` for an unknown action, a missing or malformed argument, or (with a
state) an id that is not in the state or names the wrong kind of entity.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from app.domain.errors import PlanError
from app.domain.world.action_names import canonical_action
from app.domain.world.action_specs import ACTION_SPECS, ActionSpec
from app.domain.world.state import WorldState

_OBJECT_KEYS = ("object", "objectId", "object_id", "obj", "item")
_TARGET_KEYS = ("target", "receptacle", "receptacleObjectId", "receptacle_id", "recipient",
                "person", "room", "destination", "location", "to", "into", "onto")
_EMPTY: Mapping[str, Any] = MappingProxyType({})
# Actions on the held object, which planners may name by their target alone.
_HELD_ACTIONS = frozenset({"PutObject", "HandOver", "Pour", "DropHandObject", "ThrowObject"})


@dataclass(frozen=True, slots=True)
class Action:
    """One plan step, canonical. `params` holds the typed non-entity arguments."""

    name: str
    object: str | None = None
    target: str | None = None
    params: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    step: int = 0

    @property
    def args(self) -> dict[str, str | None]:
        """The `@object`/`@target` bindings for guards and preconditions."""
        return {"object": self.object, "target": self.target}

    @property
    def spec(self) -> ActionSpec:
        """The action's spec (arguments, preconditions, effects)."""
        return ACTION_SPECS[self.name]

    def to_wire(self) -> dict[str, Any]:
        """The canonical wire shape, e.g. for violation reports."""
        wire: dict[str, Any] = {"action": self.name}
        if self.object is not None:
            wire["object"] = self.object
        if self.target is not None:
            wire["target"] = self.target
        wire.update(self.params)
        return wire


def _first(raw: Mapping[str, object], keys: tuple[str, ...], step: int) -> str | None:
    for key in keys:
        value = raw.get(key)
        if value is None:
            continue
        if not isinstance(value, str) or not value.strip():
            raise PlanError(f"step {step}: '{key}' must be a non-empty id string", step=step,
                            field=f"plan[{step}].{key}")
        return value.strip()
    return None


def _param(raw: Mapping[str, object], name: str, type_name: str, step: int) -> Any:
    value = raw.get(name)
    if value is None:
        return None
    if type_name == "number":
        if isinstance(value, bool) or not isinstance(value, int | float) or value < 0:
            raise PlanError(f"step {step}: '{name}' must be a non-negative number", step=step,
                            field=f"plan[{step}].{name}")
        return float(value)
    if not isinstance(value, str) or not value.strip():
        raise PlanError(f"step {step}: '{name}' must be a non-empty string", step=step,
                        field=f"plan[{step}].{name}")
    return value.strip()


def _check_entity(state: WorldState, entity_id: str, kinds: tuple[str, ...], role: str,
                  action: str, step: int) -> None:
    kind = state.entity_type(entity_id)
    if kind is None:
        raise PlanError(f"step {step}: {action} names '{entity_id}', which is not in the state",
                        step=step, field=f"plan[{step}].{role}")
    if kind not in kinds:
        raise PlanError(
            f"step {step}: {action}'s {role} must be a {' or '.join(kinds)}; "
            f"'{entity_id}' is a {kind}", step=step, field=f"plan[{step}].{role}")


def parse_action(raw: Mapping[str, object], *, step: int, state: WorldState | None) -> Action:
    """Parse one plan step into its canonical `Action`.

    Args:
        raw: the step as sent, with an `action` name and its arguments.
        step: the step's index in the plan, carried by errors.
        state: the state the step runs in; when given, ids must exist and have the right kind.

    Returns:
        The canonical action.

    Raises:
        PlanError: unknown action, missing or malformed argument, or an id not in the state.
    """
    name_value = raw.get("action")
    if not isinstance(name_value, str) or not name_value.strip():
        raise PlanError(f"step {step}: 'action' must name an action", step=step,
                        field=f"plan[{step}].action")
    name = canonical_action(name_value)
    if name is None:
        raise PlanError(f"step {step}: unknown action '{name_value}'", step=step,
                        field=f"plan[{step}].action")
    spec = ACTION_SPECS[name]
    obj = _first(raw, _OBJECT_KEYS, step)
    target = _first(raw, _TARGET_KEYS, step)
    # One-argument moves accept their argument under either key.
    if not spec.target_kinds and obj is None:
        obj, target = target, None
    if not spec.object_kinds and target is None:
        obj, target = None, obj
    if state is not None and name in _HELD_ACTIONS:
        # SMART-LLM style `PutObject(receptacle)` or a bare `DropHandObject`: the held object.
        if spec.target_required and target is None and obj is not None:
            obj, target = state.robot.holding, obj
        elif obj is None:
            obj = state.robot.holding
    for role, value, required in (("object", obj, spec.object_required),
                                  ("target", target, spec.target_required)):
        if required and value is None:
            raise PlanError(f"step {step}: {name} needs an {role}", step=step,
                            field=f"plan[{step}].{role}")
    if state is not None:
        if obj is not None:
            _check_entity(state, obj, spec.object_kinds, "object", name, step)
        if target is not None:
            _check_entity(state, target, spec.target_kinds, "target", name, step)
    params = {p.name: value for p in spec.params
              if (value := _param(raw, p.name, p.type, step)) is not None}
    if "relation" in params and params["relation"] not in ("on", "in"):
        raise PlanError(f"step {step}: 'relation' must be 'on' or 'in'", step=step,
                        field=f"plan[{step}].relation")
    return Action(name, obj if spec.object_kinds else None,
                  target if spec.target_kinds else None,
                  MappingProxyType(params) if params else _EMPTY, step)
