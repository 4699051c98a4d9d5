"""A gate request as prompt text, partition by partition, and the ids an answer may name.

In: a `GateRequest` and an information level. Out: `information(request, level)`, the text of
the paper's information partition for that level (task: the command; deployment: + the scene;
user: + the user profile and the robot), and `SceneIds`, the ids an answer may use as entities.
Fails: never; a missing part of the request is rendered as "not given", never left out silently.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel

from app.domain.models import GateRequest, Level

_LEVEL_ORDER = (Level.TASK, Level.DEPLOYMENT, Level.USER)


def _as_json(model: BaseModel) -> str:
    data: Any = model.model_dump(mode="json", by_alias=True, exclude_none=True)
    return json.dumps(data, ensure_ascii=False, sort_keys=True)


def information(request: GateRequest, level: Level) -> str:
    """The information partition of one level, as prompt text.

    Args:
        request: the gate request.
        level: task, deployment or user; each includes what the previous ones show.

    Returns:
        Labelled sections: command, then scene, then user and robot, as the level allows.
    """
    rank = _LEVEL_ORDER.index(level)
    sections = [f"Command: {request.command}"]
    if rank >= 1:
        scene = request.scene
        sections.append(f"Scene (JSON): {_as_json(scene)}" if scene else "Scene: not given.")
    if rank >= 2:
        user = request.user
        sections.append(
            f"User being served (JSON): {_as_json(user)}"
            if user
            else "User being served: not given; nothing is known about them."
        )
        robot = request.robot
        sections.append(
            f"Robot (JSON): {_as_json(robot)}"
            if robot
            else "Robot: not given; its skills, sensors and payload are unknown."
        )
    return "\n".join(sections)


@dataclass(frozen=True)
class SceneIds:
    """The ids of a request's scene, by kind."""

    objects: frozenset[str]
    people: frozenset[str]
    rooms: frozenset[str]

    @classmethod
    def of(cls, request: GateRequest) -> SceneIds:
        """Collect the ids the request names.

        Args:
            request: the gate request.

        Returns:
            Object (and obstacle) ids, person ids and room names.
        """
        objects: set[str] = set()
        people: set[str] = set()
        rooms: set[str] = set()
        scene = request.scene
        if scene is not None:
            objects |= {o.id for o in scene.objects}
            rooms |= {o.room for o in scene.objects if o.room}
            people |= {p.id for p in scene.people}
            rooms |= {p.room for p in scene.people if p.room}
            if scene.layout is not None:
                rooms |= set(scene.layout.rooms)
                objects |= {o.id for o in scene.layout.obstacles}
        if request.user is not None and request.user.person_id:
            people.add(request.user.person_id)
        if request.robot is not None and request.robot.room:
            rooms.add(request.robot.room)
        return cls(frozenset(objects), frozenset(people), frozenset(rooms))

    def problems(self, variable: str, value: str) -> list[str]:
        """Why `value` cannot fill the entity variable `variable` (empty when it can).

        Args:
            variable: obj, other, person, room or aid.
            value: the id the answer gave.

        Returns:
            Zero or one problem sentence.
        """
        if variable == "person":
            allowed, kind = self.people, "person"
        elif variable == "room":
            allowed, kind = self.rooms, "room"
        else:
            allowed, kind = self.objects, "object"
        if value in allowed:
            return []
        choices = ", ".join(sorted(allowed)[:30]) or "none"
        return [f"entities.{variable} = {value!r} is not a {kind} id of the scene ({choices})"]
