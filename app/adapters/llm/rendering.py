"""A gate request as prompt text, partition by partition, and the ids an answer may name.

In: a `GateRequest` and an information level. Out: `information(request, level)`, the text of
the paper's information partition for that level (task: the command; deployment: + the scene;
user: + the user profile and the robot), `visible(request)`, the part of a request the model may
see, and `SceneIds`, the ids an answer may use as entities.
Everything the caller wrote is data, never instructions: each part is JSON-encoded (so a new line
or a quote in a command cannot start a line of the prompt) and put between `<data id=N>` markers
whose N is a digest of the data itself, so text inside cannot forge the closing marker. Keys the
request schema does not declare are dropped before the prompt (the free `properties` maps stay:
they are the scene's facts).
Fails: never; a missing part of the request is rendered as "not given", never left out silently.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel

from app.domain.models import GateRequest, Level

_LEVEL_ORDER = (Level.TASK, Level.DEPLOYMENT, Level.USER)
DATA_OPEN = '<data id="{nonce}">'
DATA_CLOSE = '</data id="{nonce}">'


def _declared(value: Any) -> Any:
    """A model's declared fields only, recursively: extra keys a caller sent are not data."""
    if isinstance(value, BaseModel):
        out: dict[str, Any] = {}
        for name, info in type(value).model_fields.items():
            item = getattr(value, name)
            if item is None or item == {}:
                continue
            out[info.alias or name] = _declared(item)
        return out
    if isinstance(value, list | tuple):
        return [_declared(item) for item in value]
    if isinstance(value, dict):
        return {str(k): _declared(v) for k, v in value.items()}
    return value


def visible(request: GateRequest) -> dict[str, Any]:
    """What the model may see of a request: its declared fields, without extras or nulls.

    Args:
        request: the gate request.

    Returns:
        A JSON-ready dict (also what the analysis cache key is computed from).
    """
    seen: dict[str, Any] = _declared(request)
    return seen


def _encoded(data: Any) -> str:
    return json.dumps(data, ensure_ascii=False, sort_keys=True, separators=(",", ":"))


_PARTS: tuple[tuple[int, str, str, str], ...] = (
    (0, "Command", "command", ""),
    (1, "Scene", "scene", "Scene: not given."),
    (2, "User being served", "user", "User being served: not given; nothing is known about them."),
    (2, "Robot", "robot", "Robot: not given; its skills, sensors and payload are unknown."),
)


def information(request: GateRequest, level: Level, *, with_command: bool = True,
                only_new: bool = False) -> str:
    """The information partition of one level, as prompt text with the request as data.

    Args:
        request: the gate request.
        level: task, deployment or user; each includes what the previous ones show.
        with_command: False leaves the command out (a caller that shows it on its own).
        only_new: only what this level adds to the previous one (the batched prompt shows the
            partition level by level: the command, then the scene, then the user and robot).

    Returns:
        Labelled sections: command, then scene, then user and robot, as the level allows, each
        given part JSON-encoded between data markers.
    """
    rank = _LEVEL_ORDER.index(level)
    seen = visible(request)
    parts = [(label, key, missing) for part_rank, label, key, missing in _PARTS
             if (part_rank == rank if only_new else part_rank <= rank)
             and (with_command or key != "command")]
    given = "\n".join(_encoded(seen[key]) for _, key, _ in parts if key in seen)
    nonce = hashlib.sha256(given.encode()).hexdigest()[:12]
    opening, closing = DATA_OPEN.format(nonce=nonce), DATA_CLOSE.format(nonce=nonce)
    sections: list[str] = []
    for label, key, missing in parts:
        if key in seen:
            sections.append(f"{label} (JSON data):\n{opening}\n{_encoded(seen[key])}\n{closing}")
        else:
            sections.append(missing)
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
