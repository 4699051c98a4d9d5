"""Domain values shared by every stage: requests, hazard reports, templates.

Decisions and contracts live beside the stages that make them (`gate.py`, `contracts.py`).
"""

from app.domain.models.hazards import (
    Category,
    Confidence,
    HazardProposal,
    HazardReport,
    Level,
    Preventability,
    Severity,
    UnknownFact,
)
from app.domain.models.request import (
    GateRequest,
    InitialState,
    Layout,
    Obstacle,
    Person,
    Position,
    Relation,
    RobotProfile,
    Scene,
    SceneObject,
    UserProfile,
)
from app.domain.models.templates import (
    ConditionKind,
    HazardTemplate,
    TemplateCondition,
    TemplateSource,
    TemplateStatus,
    TemplateVariable,
    VariableType,
)

__all__ = [
    "Category",
    "ConditionKind",
    "Confidence",
    "GateRequest",
    "HazardProposal",
    "HazardReport",
    "HazardTemplate",
    "InitialState",
    "Layout",
    "Level",
    "Obstacle",
    "Person",
    "Position",
    "Preventability",
    "Relation",
    "RobotProfile",
    "Scene",
    "SceneObject",
    "Severity",
    "TemplateCondition",
    "TemplateSource",
    "TemplateStatus",
    "TemplateVariable",
    "UnknownFact",
    "UserProfile",
    "VariableType",
]
