"""The sizes a deployment allows: a command's length, each scene list, a plan's steps.

In: a validated gate request (also one rebuilt from answers, or read back for re-evaluation),
an initial state or a plan, and the `InputLimits` built from the settings. Out: nothing when
the input is within limits. Every service that takes one of these checks it here, so `/gate`,
`/gate/{id}/answers`, the re-evaluations, `/verify`, `/monitor` and the CLI share one rule.
The models' own caps (`MAX_COMMAND_CHARS`, `MAX_ENTITIES`, `MAX_PLAN_STEPS`) bound what a setting
can allow; the shape of the raw JSON body (depth, numbers, characters) and its size in bytes are
checked at the edge before any model is built (`app/api/limits.py`, `app/api/observability.py`).
Fails: `InvalidInput` naming the field (e.g. `body.scene.objects`), a 422 problem+json.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from app.config import PLAN_STEPS_CAP, Settings
from app.domain.errors import InvalidInput
from app.domain.models import GateRequest, InitialState, Scene
from app.domain.models.request import MAX_COMMAND_CHARS, MAX_ENTITIES

_SCENE_LISTS = ("objects", "people", "relations")
_LAYOUT_LISTS = ("rooms", "connections", "obstacles")


@dataclass(frozen=True, slots=True)
class InputLimits:
    """The configured sizes (see `Settings`); by default the models' own caps."""

    command_chars: int = MAX_COMMAND_CHARS
    scene_entities: int = MAX_ENTITIES
    plan_steps: int = PLAN_STEPS_CAP

    @classmethod
    def from_settings(cls, settings: Settings) -> InputLimits:
        return cls(command_chars=settings.max_command_chars,
                   scene_entities=settings.max_scene_entities,
                   plan_steps=settings.max_plan_steps)

    def check_gate_request(self, request: GateRequest, where: str = "body") -> None:
        """Raises `InvalidInput` when the command or a scene list is too long."""
        if len(request.command) > self.command_chars:
            raise InvalidInput(f"the command has {len(request.command)} characters; at most "
                               f"{self.command_chars} are allowed", field=f"{where}.command",
                               limit=self.command_chars)
        self._check_scene(request.scene, f"{where}.scene")

    def check_initial_state(self, state: InitialState | None) -> None:
        """Raises `InvalidInput` when a list of the initial state's scene is too long."""
        if state is not None:
            self._check_scene(state.scene, "body.initial_state.scene")

    def check_plan(self, plan: Sequence[object]) -> None:
        """Raises `InvalidInput` when the plan has too many steps."""
        if len(plan) > self.plan_steps:
            raise InvalidInput(f"the plan has {len(plan)} steps; at most {self.plan_steps} "
                               "are allowed", field="body.plan", limit=self.plan_steps)

    def _check_scene(self, scene: Scene | None, prefix: str) -> None:
        if scene is None:
            return
        lists: list[tuple[str, Sequence[object]]] = [
            (f"{prefix}.{name}", getattr(scene, name)) for name in _SCENE_LISTS]
        if scene.layout is not None:
            lists += [(f"{prefix}.layout.{name}", getattr(scene.layout, name))
                      for name in _LAYOUT_LISTS]
        for field, items in lists:
            if len(items) > self.scene_entities:
                raise InvalidInput(f"{field} has {len(items)} items; at most "
                                   f"{self.scene_entities} are allowed", field=field,
                                   limit=self.scene_entities)


MODEL_CAPS = InputLimits()
"""No setting narrower than the models' own caps (what a service built without settings uses)."""
