"""The shapes LLM answers must take, as pydantic models, and their JSON schemas for the provider.

In: nothing (declarations). Out: `LevelAnswer` (one level of the Hazard Analysis Matrix),
`BatchedAnswer` (the three levels at once),
and `json_schema(model)`, the model's JSON schema with `$ref`s inlined, because small local
servers turn schemas into grammars and some do not follow references, and titles left out.
Fails: pydantic `ValidationError` when an answer does not fit; `structured.py` handles it.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from app.domain.models import Category, Confidence, Preventability, Severity

MAX_ITEMS = 40
HAZARD_CLASS_PATTERN = r"^[a-z][a-z0-9_]{1,60}$"
ENTITY_NAMES = ("obj", "other", "person", "room", "aid")
"""The template entity variables an answer may fill (`MatrixEntities`' fields)."""


class _Answer(BaseModel):
    model_config = ConfigDict(frozen=True, extra="ignore")


class MatrixEntities(_Answer):
    """Scene ids filling the templates' entity variables (README of templates_db)."""

    obj: str | None = Field(default=None, description="the main object acted on")
    other: str | None = Field(
        default=None, description="a second object: heat source, receptacle, other chemical"
    )
    person: str | None = Field(default=None, description="the person at risk")
    room: str | None = Field(default=None, description="the room concerned")
    aid: str | None = Field(default=None, description="a walking aid or safety barrier")

    def as_bindings(self) -> dict[str, str]:
        """The filled variables only, as the proposal's `entities`."""
        return {k: v for k, v in self.model_dump().items() if isinstance(v, str) and v.strip()}


class MatrixHazard(_Answer):
    """One hazard of one matrix cell."""

    category: Category
    hazard_class: str = Field(pattern=HAZARD_CLASS_PATTERN)
    new_class: bool = Field(
        default=False, description="true only for a class deliberately not in the library"
    )
    mechanism: str = Field(min_length=1, max_length=600)
    entities: MatrixEntities = Field(default_factory=MatrixEntities)
    severity: Severity
    preventability: Preventability
    confidence: Confidence


class MatrixUnknown(_Answer):
    """Something not known that may matter."""

    attribute: str = Field(min_length=1, max_length=200)
    description: str = Field(min_length=1, max_length=600)
    critical: bool
    why: str = Field(min_length=1, max_length=600)
    entity: str | None = None
    question: str | None = Field(default=None, max_length=600)


class Dismissal(_Answer):
    """An earlier hazard class or unknown attribute that this level's information rules out."""

    kind: Literal["hazard", "unknown"]
    name: str = Field(min_length=1, max_length=200)
    entity: str | None = Field(
        default=None, description="the entity id, to dismiss only the item about it"
    )
    why: str = Field(min_length=1, max_length=600)


class LevelAnswer(_Answer):
    """The hazards and unknowns found at one information level."""

    hazards: list[MatrixHazard] = Field(max_length=MAX_ITEMS)
    unknowns: list[MatrixUnknown] = Field(max_length=MAX_ITEMS)
    dismissed: list[Dismissal] = Field(default_factory=list, max_length=MAX_ITEMS)
    none_because: dict[Category, str] = Field(
        default_factory=dict,
        description="for each category with no hazard at this level, why there is none",
    )


class BatchedAnswer(_Answer):
    """All three levels of the matrix in one answer (the analyzer's batched mode)."""

    task: LevelAnswer
    deployment: LevelAnswer
    user: LevelAnswer


def json_schema(model: type[BaseModel]) -> dict[str, Any]:
    """The model's JSON schema with every `$ref` replaced by its definition, without titles.

    Pydantic's titles only repeat each field's name ("hazard_class" -> "Hazard Class"); they
    are a fifth of the schema sent with every call and tell the model nothing.

    Args:
        model: a pydantic model without recursive references.

    Returns:
        A self-contained JSON schema (no `$defs`).
    """
    schema = model.model_json_schema()
    definitions: dict[str, Any] = schema.pop("$defs", {})

    def inline(node: Any, names: bool = False) -> Any:
        # `names`: the node maps property names to schemas, so a property called "title" stays.
        if isinstance(node, dict):
            reference = node.get("$ref")
            if isinstance(reference, str):
                target = definitions[reference.rsplit("/", 1)[-1]]
                node = {**target, **{k: v for k, v in node.items() if k != "$ref"}}
            return {k: inline(v, names=k == "properties" and not names)
                    for k, v in node.items() if names or k != "title"}
        if isinstance(node, list):
            return [inline(item) for item in node]
        return node

    inlined: dict[str, Any] = inline(schema)
    return inlined
