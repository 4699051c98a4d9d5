"""Stage 1's output: hazard proposals and unknowns, the Hazard Analysis Matrix.

In: produced by an analyzer (symbolic or LLM). Out: frozen models consumed by binding and the
gate. The matrix is three information levels crossed with four categories.
"""

from __future__ import annotations

from enum import StrEnum

from pydantic import BaseModel, ConfigDict, Field


class Level(StrEnum):
    """Information level: task (command only), deployment (+ scene), user (+ user, robot)."""

    TASK = "task"
    DEPLOYMENT = "deployment"
    USER = "user"


class Category(StrEnum):
    PHYSICAL = "physical"
    PSYCHOLOGICAL = "psychological"
    OPERATIONAL = "operational"
    CONSEQUENTIAL = "consequential"


class Severity(StrEnum):
    CRITICAL = "critical"
    HIGH = "high"
    MODERATE = "moderate"
    LOW = "low"
    NEGLIGIBLE = "negligible"

    @property
    def rank(self) -> int:
        """Larger is worse: negligible 0 ... critical 4."""
        return _SEVERITY_RANK[self]


_SEVERITY_RANK = {
    Severity.NEGLIGIBLE: 0,
    Severity.LOW: 1,
    Severity.MODERATE: 2,
    Severity.HIGH: 3,
    Severity.CRITICAL: 4,
}


class Preventability(StrEnum):
    PREVENTABLE = "preventable"
    UNPREVENTABLE = "unpreventable"
    UNKNOWN = "unknown"


class Confidence(StrEnum):
    CERTAIN = "certain"
    UNCERTAIN = "uncertain"


class HazardProposal(BaseModel):
    """One cell entry of the matrix: a hazard the analyzer believes the task carries.

    `entities` maps template variable names (without `$`) to scene ids, e.g.
    {"obj": "mug_1", "person": "person_1"}; binding uses them to instantiate a template.
    """

    model_config = ConfigDict(frozen=True)

    level: Level
    category: Category
    hazard_class: str = Field(min_length=1)
    mechanism: str = Field(min_length=1)
    entities: dict[str, str] = Field(default_factory=dict)
    severity: Severity
    preventability: Preventability
    confidence: Confidence
    source: str = "symbolic"
    template_id: str | None = None
    """The template whose condition the analysis found broken, when it judged one; binding
    lists it first among the class's templates."""


class UnknownFact(BaseModel):
    """Something the gate does not know that may matter; critical ones block authorization."""

    model_config = ConfigDict(frozen=True)

    attribute: str = Field(min_length=1)
    description: str = Field(min_length=1)
    critical: bool
    why: str = Field(min_length=1)
    entity: str | None = None
    question: str | None = None


class HazardReport(BaseModel):
    """The filled Hazard Analysis Matrix plus the unknowns found on the way."""

    model_config = ConfigDict(frozen=True)

    proposals: tuple[HazardProposal, ...] = ()
    unknowns: tuple[UnknownFact, ...] = ()
    analyzer: str = "symbolic"
