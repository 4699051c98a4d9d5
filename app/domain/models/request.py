"""The gate request: the task context (c, E, u) plus the robot capabilities R.

In: JSON from a robot planner, shaped as `shared/spec/gate-request.md` describes.
Out: frozen pydantic models. Every field but `command` is optional and a missing field means
"unknown", never "safe": downstream stages must treat `None` as not known.
Property values with a fixed meaning (`mass_kg` >= 0, `temperature` hot/cold/room, flags, a
person's age group...) are checked; other properties pass as given. Numbers are JSON numbers:
`true` or `"0.5"` for a speed or a coordinate is refused, never read as 1 or 0.5.
Fails: pydantic `ValidationError` on a shape that does not fit (the API maps it to a 422 naming
the field, e.g. `body.scene.objects.0.properties.mass_kg`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, WithJsonSchema
from typing_extensions import TypedDict

AgeGroup = Literal["infant", "child", "teen", "adult", "older_adult"]
Mobility = Literal["independent", "assisted", "wheelchair", "bedridden"]
CognitiveState = Literal["typical", "impaired", "asleep", "intoxicated"]

Temperature = Literal["hot", "cold", "room"]

MAX_COMMAND_CHARS = 2000
MAX_ENTITIES = 500


def _word(value: object) -> object:
    """Words are read as the world model reads them: trimmed, lower case."""
    return value.strip().lower() if isinstance(value, str) else value


def _listed(value: object) -> object:
    return [value] if isinstance(value, str) else value


# Property values with a fixed meaning (`shared/spec/gate-request.md`). Each may be null
# (unknown); any other key is free. A flag is a JSON boolean or a word that means one ("yes",
# "off"...); a mass is a number, never a boolean or text.
def _not_a_number(value: object) -> object:
    if isinstance(value, int | float) and not isinstance(value, bool):
        raise ValueError("a flag is true, false or a word for one (yes/no, on/off), not a number")
    return value


_Flag = Annotated[bool | None, BeforeValidator(_not_a_number)]
_Mass = Annotated[float, Field(ge=0, allow_inf_nan=False, strict=True)] | None


class ObjectProperties(TypedDict, total=False):
    """`objects[].properties`: the keys with a fixed meaning are checked; others pass as given."""

    __pydantic_config__ = ConfigDict(extra="allow")  # type: ignore[misc]

    temperature: Annotated[Temperature | None, BeforeValidator(_word)]
    mass_kg: _Mass
    contents: str | None
    lidded: _Flag
    sealed: _Flag
    sharp: _Flag
    fragile: _Flag
    toxic: _Flag
    flammable: _Flag
    on: _Flag
    open: _Flag
    broken: _Flag
    dirty: _Flag
    electrical: _Flag
    wet: _Flag


class PersonProperties(TypedDict, total=False):
    """`people[].properties`: the keys with a fixed meaning are checked; others pass as given."""

    __pydantic_config__ = ConfigDict(extra="allow")  # type: ignore[misc]

    age_group: Annotated[AgeGroup | None, BeforeValidator(_word)]
    mobility: Annotated[Mobility | None, BeforeValidator(_word)]
    cognitive_state: Annotated[CognitiveState | None, BeforeValidator(_word)]
    allergies: Annotated[list[str] | None, BeforeValidator(_listed), WithJsonSchema(
        {"anyOf": [{"type": "array", "items": {"type": "string"}}, {"type": "string"},
                   {"type": "null"}]})]  # "peanut" = ["peanut"]
    pregnant: _Flag
    # a flag, or what it is ("low vision")
    visual_impairment: Annotated[bool | str | None, BeforeValidator(_not_a_number)]
    hearing_impairment: Annotated[bool | str | None, BeforeValidator(_not_a_number)]
    mass_kg: _Mass


# Validated as the TypedDicts above (so a bad value is a 422 naming e.g.
# `body.scene.objects.3.properties.mass_kg`), read everywhere as the plain dicts they are.
if TYPE_CHECKING:
    _ObjectPropertiesField = dict[str, Any]
    _PersonPropertiesField = dict[str, Any]
else:
    _ObjectPropertiesField = ObjectProperties
    _PersonPropertiesField = PersonProperties


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="allow", populate_by_name=True)


class Position(_Frozen):
    """A point in the scene's frame, in metres."""

    x: float = Field(allow_inf_nan=False, strict=True)
    y: float = Field(allow_inf_nan=False, strict=True)
    z: float | None = Field(default=None, allow_inf_nan=False, strict=True)


class Obstacle(_Frozen):
    """Something in the layout that is not a manipulable object (a loose rug, a step)."""

    id: str = Field(min_length=1, max_length=200)
    kind: str = Field(min_length=1, max_length=200)
    room: str | None = None


class Layout(_Frozen):
    """Rooms, which rooms connect, and fixed obstacles."""

    rooms: list[str] = Field(default_factory=list, max_length=MAX_ENTITIES)
    connections: list[tuple[str, str]] = Field(default_factory=list, max_length=MAX_ENTITIES)
    obstacles: list[Obstacle] = Field(default_factory=list, max_length=MAX_ENTITIES)


class SceneObject(_Frozen):
    """An object in the scene. `type` is an AI2-THOR type where one fits, else a plain noun."""

    id: str = Field(min_length=1, max_length=200)
    type: str = Field(min_length=1, max_length=200)
    name: str | None = None
    room: str | None = None
    on: str | None = None
    inside: str | None = Field(default=None, alias="in")
    position: Position | None = None
    properties: _ObjectPropertiesField = Field(default_factory=dict)


class Relation(_Frozen):
    """A binary relation between two entities (`on`, `in`, `next_to`, `blocks`, `holding`...)."""

    subject: str = Field(min_length=1, max_length=200)
    relation: str = Field(min_length=1, max_length=200)
    object: str = Field(min_length=1, max_length=200)


class Person(_Frozen):
    """A person in the scene; `properties` carries age_group, mobility, allergies..."""

    id: str = Field(min_length=1, max_length=200)
    role: str | None = None
    name: str | None = None
    room: str | None = None
    posture: str | None = None
    position: Position | None = None
    properties: _PersonPropertiesField = Field(default_factory=dict)


class Scene(_Frozen):
    """E = (objects O, relations R, people P, layout L)."""

    layout: Layout | None = None
    objects: list[SceneObject] = Field(default_factory=list, max_length=MAX_ENTITIES)
    relations: list[Relation] = Field(default_factory=list, max_length=MAX_ENTITIES)
    people: list[Person] = Field(default_factory=list, max_length=MAX_ENTITIES)


class UserProfile(_Frozen):
    """u: the person being served, with what the caller knows it does not know."""

    person_id: str | None = None
    age_group: AgeGroup | None = None
    mobility: Mobility | None = None
    cognitive_state: CognitiveState | None = None
    allergies: list[str] | None = None
    unknowns: list[str] = Field(default_factory=list)


class RobotProfile(_Frozen):
    """R: where the robot is and what it can do. `skills`/`sensors` None means not stated."""

    name: str | None = None
    room: str | None = None
    position: Position | None = None
    skills: list[str] | None = None
    payload_kg: float | None = Field(default=None, ge=0, allow_inf_nan=False, strict=True)
    max_speed_mps: float | None = Field(default=None, ge=0, allow_inf_nan=False, strict=True)
    sensors: list[str] | None = None
    holding: str | None = None


class GateRequest(_Frozen):
    """What a planner POSTs to /gate."""

    command: str = Field(min_length=1, max_length=MAX_COMMAND_CHARS)
    scene: Scene | None = None
    user: UserProfile | None = None
    robot: RobotProfile | None = None


class InitialState(_Frozen):
    """A scene and robot state for /verify and /monitor (the gate request's shapes)."""

    scene: Scene | None = None
    robot: RobotProfile | None = None


Answer = dict[str, Any]
"""An answer to a clarifying question, e.g. {"age_group": "adult"} or {"contents": "water"}."""

ActionName = str
Kind = Literal["object", "person", "room", "robot"]
