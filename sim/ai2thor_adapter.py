"""The same action API over real AI2-THOR, for users who have it (optional; not exercised here).

In: an `ai2thor.controller.Controller` (package `ai2thor`, which downloads a Unity build at run
time: that cannot happen on this project's machines, so no test runs this module) and actions in
the plan wire shape. Out: the same `StepResult` the symbolic simulator gives, plus the scene as a
gate-request `InitialState` built from the controller's metadata (so the runtime monitor can be
fed real observations). Hazard events are not produced here: AI2-THOR has no hazard layer; run
`sim.hazards` on `observe()` states if wanted.
Mapping: `GoToObject` teleports next to the object (AI2-THOR's `GetInteractablePoses`), `navigate`
to a room is unsupported (iTHOR scenes are single rooms), `HandOver` to a person is unsupported
(AI2-THOR has no people), the other actions map one to one onto AI2-THOR actions with `objectId`.
Fails: `ImportError` naming the extra when `ai2thor` is not installed; an action AI2-THOR refuses
is a failed step with its `errorMessage`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from app.domain.models import InitialState, RobotProfile, Scene
from sim.simulator import StepResult

_DIRECT = {
    "PickupObject": "PickupObject", "OpenObject": "OpenObject", "CloseObject": "CloseObject",
    "ToggleObjectOn": "ToggleObjectOn", "ToggleObjectOff": "ToggleObjectOff",
    "SliceObject": "SliceObject", "BreakObject": "BreakObject", "CleanObject": "CleanObject",
    "DirtyObject": "DirtyObject", "EmptyLiquid": "EmptyLiquidFromObject",
    "Cook": "CookObject", "PushObject": "PushObject",
}


class Ai2ThorAdapter:
    """Executes plan actions on a live AI2-THOR controller."""

    def __init__(self, controller: Any) -> None:
        """Wrap a started controller (`ai2thor.controller.Controller(scene="FloorPlan1")`)."""
        self.controller = controller

    @classmethod
    def start(cls, scene: str, **settings: Any) -> Ai2ThorAdapter:
        """Start AI2-THOR on an iTHOR scene.

        Raises:
            ImportError: the optional `ai2thor` package is not installed.
        """
        try:
            from ai2thor.controller import Controller  # type: ignore[import-not-found]
        except ImportError as error:
            raise ImportError("install the optional extra: pip install ai2thor") from error
        return cls(Controller(scene=scene, **settings))

    def _event(self, **action: Any) -> tuple[bool, str | None]:
        event = self.controller.step(**action)
        ok = bool(event.metadata.get("lastActionSuccess"))
        return ok, None if ok else str(event.metadata.get("errorMessage") or "refused")

    def execute(self, raw: Mapping[str, Any]) -> StepResult:
        """Run one action in the plan wire shape.

        Returns:
            `ok`, or `failed` with AI2-THOR's error message (or why it cannot be mapped).
        """
        name = str(raw.get("action", ""))
        obj, target = raw.get("object"), raw.get("target")
        if name == "GoToObject" and isinstance(obj, str):
            poses = self.controller.step(action="GetInteractablePoses", objectId=obj)
            found = poses.metadata.get("actionReturn") or []
            if not found:
                return StepResult(raw, "failed", f"no pose from which {obj} is interactable")
            ok, why = self._event(action="Teleport", **found[0])
        elif name == "PutObject" and isinstance(target, str):
            ok, why = self._event(action="PutObject", objectId=target)
        elif name == "Pour" and isinstance(target, str):
            ok, why = self._event(action="PourObject", objectId=target)  # pragma: no cover
        elif name == "FillWithLiquid" and isinstance(obj, str):
            ok, why = self._event(action="FillObjectWithLiquid", objectId=obj,
                                  fillLiquid=raw.get("liquid", "water"))
        elif name in ("ThrowObject", "DropHandObject"):
            ok, why = self._event(action="ThrowObject" if name == "ThrowObject"
                                  else "DropHandObject", moveMagnitude=150.0)
        elif name == "Wait":
            ok, why = True, None
        elif name in _DIRECT and isinstance(obj, str):
            ok, why = self._event(action=_DIRECT[name], objectId=obj)
        else:
            return StepResult(raw, "failed", f"{name} has no AI2-THOR counterpart here")
        return StepResult(raw, "ok" if ok else "failed", why)

    def observe(self, room: str) -> InitialState:
        """The controller's current object metadata as a gate-request initial state."""
        from sim.floorplans import scene_objects

        metadata = self.controller.last_event.metadata
        objects, relations = scene_objects(metadata["objects"], room)
        agent = metadata.get("agent", {}).get("position", {})
        held = [o["objectId"] for o in metadata["objects"] if o.get("isPickedUp")]
        return InitialState(
            scene=Scene(objects=list(objects), relations=list(relations)),
            robot=RobotProfile(room=room, position={"x": agent.get("x", 0.0),
                                                    "y": agent.get("z", 0.0)},
                               holding=held[0] if held else None))
