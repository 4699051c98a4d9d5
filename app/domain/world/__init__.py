"""The symbolic world: states built from gate requests, and the AI2-THOR-style action model.

In: a `GateRequest`/`InitialState`, plan steps in the wire shape, runtime snapshots. Out: an
immutable `WorldState` (a `Facts` for the condition language), parsed `Action`s, next states
(`step`), precondition checks, and `describe_actions()` for `GET /vocabulary`.
Fails: `PlanError` for a plan step that cannot be parsed or applied; nothing else raises.
"""

from app.domain.world.action_names import CANONICAL_ACTIONS, canonical_action, canonical_skill
from app.domain.world.action_specs import ACTION_SPECS, ActionSpec, Param, Precondition
from app.domain.world.actions import Action, parse_action
from app.domain.world.build import apply_snapshot, state_from_request
from app.domain.world.describe import describe_actions
from app.domain.world.effects import step
from app.domain.world.entities import ROBOT_ID, ObjectState, PersonState, Point, RobotState
from app.domain.world.object_types import TypeInfo, type_info
from app.domain.world.preconditions import (
    PreconditionResult,
    check_preconditions,
    evaluate_preconditions,
)
from app.domain.world.state import WorldState

__all__ = [
    "ACTION_SPECS",
    "CANONICAL_ACTIONS",
    "ROBOT_ID",
    "Action",
    "ActionSpec",
    "ObjectState",
    "Param",
    "PersonState",
    "Point",
    "Precondition",
    "PreconditionResult",
    "RobotState",
    "TypeInfo",
    "WorldState",
    "apply_snapshot",
    "canonical_action",
    "canonical_skill",
    "check_preconditions",
    "describe_actions",
    "evaluate_preconditions",
    "parse_action",
    "state_from_request",
    "step",
    "type_info",
]
