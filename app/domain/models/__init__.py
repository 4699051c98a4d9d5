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
    AnalysisUse,
    ConditionKind,
    HazardTemplate,
    TemplateCondition,
    TemplateScope,
    TemplateSource,
    TemplateStatus,
    TemplateVariable,
    VariableType,
)

__all__ = [
    "AnalysisUse",
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
    "TemplateScope",
    "TemplateSource",
    "TemplateStatus",
    "TemplateVariable",
    "UnknownFact",
    "UserProfile",
    "VariableType",
]
