"""The entities of a symbolic world state: objects, people and the robot, as frozen records.

In: values taken from a gate request or produced by an action's effect. Out: immutable
records; a change is a new record (`dataclasses.replace`). `facts` on an object holds values an
effect established (e.g. `hot` after heating), which take precedence over the request's
`properties` and may be `Unknown` objects shared with the fact they were copied from.
Fails: never.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, NamedTuple

from app.domain.formula.facts import FactValue
from app.domain.world.object_types import TypeInfo, type_info

ROBOT_ID = "robot"
_EMPTY: Mapping[str, Any] = MappingProxyType({})


class Point(NamedTuple):
    """A position in metres; `z` (height) when given."""

    x: float
    y: float
    z: float | None = None


@dataclass(frozen=True, slots=True)
class ObjectState:
    """An object: where it is, what rests under it, and what is known about it."""

    id: str
    type: str
    room: str | None = None
    parent: str | None = None
    relation: str | None = None
    position: Point | None = None
    properties: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    facts: Mapping[str, FactValue] = field(default_factory=lambda: _EMPTY)
    name: str | None = None
    obstacle: bool = False
    kind: TypeInfo = field(init=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "kind", type_info(self.type))


AWAY = "away"
"""Where people are once they have left the home (a room of no layout)."""


@dataclass(frozen=True, slots=True)
class PersonState:
    """A person; `properties` merges the scene's and the user profile's attributes."""

    id: str
    role: str | None = None
    name: str | None = None
    room: str | None = None
    posture: str | None = None
    position: Point | None = None
    properties: Mapping[str, Any] = field(default_factory=lambda: _EMPTY)
    holding: frozenset[str] = frozenset()
    ate: frozenset[str] = frozenset()
    """Objects whose food or contents the person was fed or has eaten during the plan."""


@dataclass(frozen=True, slots=True)
class RobotState:
    """The robot. `skills`/`sensors` None means not stated (facts about them are unknown)."""

    name: str | None = None
    room: str | None = None
    position: Point | None = None
    holding: str | None = None
    speed: float | None = 0.0
    """m/s; None while moving at a top speed the request did not give (unknown)."""
    skills: frozenset[str] | None = None
    sensors: frozenset[str] | None = None
    payload_kg: float | None = None
    max_speed: float | None = None
    recording: bool = False
    noisy: bool = False
    """Running something loud (a vacuum cleaner) in this state."""
    beside: str | None = None
    """The object or person the robot last moved next to (kept until it moves again)."""
    hours_waited: float = 0.0
    """How long the task has so far left its result standing by itself (its `Wait` steps):
    "leave it on overnight" is not "leave it on while I fetch a shirt"."""


def frozen_mapping(values: Mapping[str, Any]) -> Mapping[str, Any]:
    """A read-only copy, so no one can change a state after it is built."""
    return MappingProxyType(dict(values)) if values else _EMPTY
