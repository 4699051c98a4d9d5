"""The wire models of SafeGate, generated from the service's own descriptions.

`api` is generated from the OpenAPI document (`GET /openapi.json`), `monitor` from the
monitor's AsyncAPI document (`docs/api/asyncapi.yaml`), both by `make client-models`; a test
fails when either drifts from what the server says. Answers keep any field a newer server adds
(`model_extra`). `MonitorAnswer` and `MonitorEvent` are the websockets' answers and events,
told apart by their `type`; `parse_answer` and `parse_event` read them.
Fails: `pydantic.ValidationError` for JSON that is none of them.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field, TypeAdapter

from safegate_client.models.api import (
    ContractConditionOut,
    ContractResponse,
    GateRequest,
    GateResponse,
    HazardOut,
    InitialState,
    Layout,
    MonitorOpenResponse,
    MonitorSummaryResponse,
    MonitorViolation,
    Person,
    PlanViolation,
    Problem,
    ProblemField,
    ReferencePlanOut,
    RepairOut,
    RobotProfile,
    Scene,
    SceneObject,
    ScopeOut,
    UnknownOut,
    UserProfile,
    VerifyResponse,
)
from safegate_client.models.monitor import (
    Action,
    After,
    Allow,
    Before,
    ErrorAnswer,
    HaltedAnswer,
    HaltedEvent,
    Resync,
    State,
    Status,
    Sync,
    Violation,
    ViolationAnswer,
    ViolationEvent,
)

MonitorAnswer = Annotated[Allow | ViolationAnswer | HaltedAnswer | ErrorAnswer,
                          Field(discriminator="type")]
MonitorEvent = Annotated[Status | ViolationEvent | HaltedEvent, Field(discriminator="type")]
_ANSWER: TypeAdapter[MonitorAnswer] = TypeAdapter(MonitorAnswer)
_EVENT: TypeAdapter[MonitorEvent] = TypeAdapter(MonitorEvent)


def parse_answer(answer: Any) -> Allow | ViolationAnswer | HaltedAnswer | ErrorAnswer:
    """The runtime channel's answer (`allow`, `violation`, `halted` or `error`) as a model."""
    return _ANSWER.validate_python(answer)


def parse_event(event: Any) -> Status | ViolationEvent | HaltedEvent:
    """A listener channel's event (`status`, `violation` or `halted`) as a model."""
    return _EVENT.validate_python(event)


__all__ = [
    "Action",
    "After",
    "Allow",
    "Before",
    "ContractConditionOut",
    "ContractResponse",
    "ErrorAnswer",
    "GateRequest",
    "GateResponse",
    "HaltedAnswer",
    "HaltedEvent",
    "HazardOut",
    "InitialState",
    "Layout",
    "MonitorAnswer",
    "MonitorEvent",
    "MonitorOpenResponse",
    "MonitorSummaryResponse",
    "MonitorViolation",
    "Person",
    "PlanViolation",
    "Problem",
    "ProblemField",
    "ReferencePlanOut",
    "RepairOut",
    "Resync",
    "RobotProfile",
    "Scene",
    "SceneObject",
    "ScopeOut",
    "State",
    "Status",
    "Sync",
    "UnknownOut",
    "UserProfile",
    "VerifyResponse",
    "Violation",
    "ViolationAnswer",
    "ViolationEvent",
    "parse_answer",
    "parse_event",
]
