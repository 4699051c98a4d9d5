"""Hazard templates: the Hazard Template Library's entries as domain values.

A template names a hazard class and the prevention conditions that keep it from happening, in
the condition language (`app.domain.formula`) with typed `$variables`. Binding fills the
variables with scene entities; contract compilation substitutes them on the parsed formulas.
"""

from __future__ import annotations

from datetime import datetime
from enum import StrEnum
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from app.domain.models.hazards import Category, Preventability, Severity


class VariableType(StrEnum):
    OBJECT = "object"
    PERSON = "person"
    ROOM = "room"
    ROBOT = "robot"
    ENTITY = "entity"
    NUMBER = "number"
    STRING = "string"
    BOOL = "bool"


_ENTITY_VARIABLES = frozenset({"object", "person", "room", "entity"})


class TemplateStatus(StrEnum):
    DRAFT = "draft"
    ACTIVE = "active"
    DEPRECATED = "deprecated"


class TemplateSource(StrEnum):
    SEED = "seed"
    USER = "user"


class AnalysisUse(StrEnum):
    """How Stage 1 uses a template: checked on every simulated plan, or only when a declared
    rule (intent, consent, a person's profile) proposes its hazard class."""

    SIMULATE = "simulate"
    DECLARED = "declared"


class TemplateScope(StrEnum):
    """Which contracts a template's conditions join: those of tasks where Stage 1 found its
    hazard (`matched`), or every contract (`always`: the baseline envelope)."""

    MATCHED = "matched"
    ALWAYS = "always"


class ConditionKind(StrEnum):
    INVARIANT = "invariant"
    GUARD = "guard"
    ABORT = "abort"


class TemplateVariable(BaseModel):
    """A typed `$name` a template's conditions use; entity variables are bound from the scene."""

    model_config = ConfigDict(frozen=True)

    name: str = Field(pattern=r"^[a-z][a-z0-9_]*$")
    type: VariableType
    default: Any = None
    description: str = ""


class TemplateCondition(BaseModel):
    """One prevention condition. Guards name the action (canonical name) they guard."""

    model_config = ConfigDict(frozen=True)

    id: str = Field(pattern=r"^[a-z][a-z0-9_]*$")
    formula: str = Field(min_length=1, max_length=4000)
    description: str = Field(min_length=1)
    action: str | None = None


class HazardTemplate(BaseModel):
    """One entry of the Hazard Template Library, at one version."""

    model_config = ConfigDict(frozen=True)

    id: str = Field(pattern=r"^[a-z][a-z0-9_.\-]*$", max_length=120)
    name: str = Field(min_length=1, max_length=200)
    category: Category
    hazard_class: str = Field(pattern=r"^[a-z][a-z0-9_]*$", max_length=120)
    description: str = Field(min_length=1)
    iso_clause: str = ""
    variables: tuple[TemplateVariable, ...] = ()
    severity: Severity
    preventability: Preventability
    invariants: tuple[TemplateCondition, ...] = ()
    guards: tuple[TemplateCondition, ...] = ()
    aborts: tuple[TemplateCondition, ...] = ()
    analysis: AnalysisUse = AnalysisUse.SIMULATE
    applies: TemplateScope = TemplateScope.MATCHED
    version: int = 1
    status: TemplateStatus = TemplateStatus.ACTIVE
    source: TemplateSource = TemplateSource.SEED
    author: str = "safegate"
    created_at: datetime | None = None

    @model_validator(mode="after")
    def _baseline_binds_itself(self) -> HazardTemplate:
        if self.applies is TemplateScope.ALWAYS:
            unbound = [v.name for v in self.variables if v.type in _ENTITY_VARIABLES
                       and v.default is None]
            if unbound:
                raise ValueError("a template that applies always cannot have entity variables "
                                 f"without a default: {', '.join('$' + n for n in unbound)}")
        return self

    @field_validator("guards")
    @classmethod
    def _guards_name_their_action(
        cls, guards: tuple[TemplateCondition, ...]
    ) -> tuple[TemplateCondition, ...]:
        for guard in guards:
            if not guard.action:
                raise ValueError(f"guard {guard.id!r} must name the action it guards")
        return guards

    def conditions(self) -> list[tuple[ConditionKind, TemplateCondition]]:
        """All conditions with their kind, invariants first."""
        return (
            [(ConditionKind.INVARIANT, c) for c in self.invariants]
            + [(ConditionKind.GUARD, c) for c in self.guards]
            + [(ConditionKind.ABORT, c) for c in self.aborts]
        )

    def variable(self, name: str) -> TemplateVariable | None:
        return next((v for v in self.variables if v.name == name), None)
