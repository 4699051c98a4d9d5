"""AI2-THOR iTHOR floor plans as gate-request scene objects.

In: the name of an iTHOR scene (`FloorPlan1`...) whose initial metadata is shipped in
`sim/data/scenes/` (a dump of `controller.reset(scene).metadata["objects"]`, see the README there).
Out: a `FloorPlan`: its room type, the room name the simulator uses for it (`kitchen`,
`living_room`, `bedroom`, `bathroom`), and its objects as `SceneObject`s that keep AI2-THOR's
objectIds, object types and state flags. AI2-THOR's frame has `y` up; the gate request's frame has
`z` up, so a position (x, y, z) becomes (x, z, y). A stove knob's `controlledObjects` become
`controls` relations. A receptacle without a door or lid whose type the type table does not
settle as a receptacle (a Sink, a Bathtub) is stated `open`, as the world model derives it for
receptacle types, so what lies in it can be taken out. Fails: `FileNotFoundError` for a scene
that is not shipped; `KeyError` or `ValueError` for a file that is not an AI2-THOR metadata dump.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

from app.domain.models import Position, Relation, SceneObject
from app.domain.world.object_types import CONTAINER_TYPES, type_info

SCENES_DIR = Path(__file__).with_name("data") / "scenes"

ROOM_NAMES = {"Kitchen": "kitchen", "LivingRoom": "living_room", "Bedroom": "bedroom",
              "Bathroom": "bathroom"}
_TEMPERATURES = {"Hot": "hot", "Cold": "cold", "RoomTemp": "room"}
# AI2-THOR leaves `fillLiquid` null in every initial dump; what a pre-filled bottle holds is
# the liquid its type is made for.
_DEFAULT_LIQUID = {"WineBottle": "wine"}
# (AI2-THOR capability flag, its state flag, the request property that carries it)
_STATE_FLAGS = (
    ("toggleable", "isToggled", "on"),
    ("openable", "isOpen", "open"),
    ("breakable", "isBroken", "broken"),
    ("dirtyable", "isDirty", "dirty"),
)


@dataclass(frozen=True)
class FloorPlan:
    """One iTHOR scene: its room and its objects, ready for a gate request."""

    name: str
    room_type: str
    room: str
    objects: tuple[SceneObject, ...]
    relations: tuple[Relation, ...]

    def object(self, object_id: str) -> SceneObject:
        """The object with this AI2-THOR objectId.

        Raises:
            KeyError: no such object in the scene.
        """
        for obj in self.objects:
            if obj.id == object_id:
                return obj
        raise KeyError(f"{self.name} has no object {object_id!r}")

    def ids_of_type(self, object_type: str) -> list[str]:
        """The objectIds of every object of an AI2-THOR type, in objectId order."""
        return [o.id for o in self.objects if o.type == object_type]


def _position(raw: dict[str, Any]) -> Position:
    return Position(x=float(raw["x"]), y=float(raw["z"]), z=float(raw["y"]))


def _parent(raw: dict[str, Any], types: dict[str, str]) -> str | None:
    parents = [str(p) for p in raw.get("parentReceptacles") or () if p in types]
    if not parents:
        return None
    # Several parents: the most specific is one that is not the floor.
    specific = [p for p in parents if types[p] != "Floor"]
    return (specific or parents)[0]


def _properties(raw: dict[str, Any]) -> dict[str, Any]:
    properties: dict[str, Any] = {}
    temperature = _TEMPERATURES.get(str(raw.get("temperature")))
    if temperature is not None:
        properties["temperature"] = temperature
    for capability, flag, key in _STATE_FLAGS:
        if raw.get(capability) or (key == "on" and raw["objectType"] == "StoveBurner"):
            properties[key] = bool(raw.get(flag))
    if (raw.get("receptacle") and not raw.get("openable") and not raw.get("pickupable")
            and type_info(raw["objectType"]).flag("receptacle") is not True):
        # AI2-THOR says per instance what the type table cannot (a Sink or a Bathtub is a
        # receptacle in some scenes, not in others): this one holds things and has no door or
        # lid, so what lies in it is as reachable as in an open box. Said as its state, as
        # the world model says it for a receptacle type.
        properties["open"] = True
    if raw.get("canFillWithLiquid"):
        filled = bool(raw.get("isFilledWithLiquid"))
        properties["filled"] = filled  # not filled: empty, so no `contents` to state
        if filled:
            properties["contents"] = raw.get("fillLiquid") or _DEFAULT_LIQUID.get(
                raw["objectType"], "water")
    mass = raw.get("mass")
    if isinstance(mass, int | float) and mass > 0:
        properties["mass_kg"] = float(mass)
    return properties


def _scene_object(raw: dict[str, Any], room: str, types: dict[str, str]) -> SceneObject:
    parent = _parent(raw, types)
    placing: dict[str, str] = {}
    if parent is not None:
        placing["in" if types[parent] in CONTAINER_TYPES else "on"] = parent
    return SceneObject.model_validate({
        "id": raw["objectId"], "type": raw["objectType"], "room": room,
        "position": _position(raw["position"]).model_dump(), "properties": _properties(raw),
        **placing,
    })


@cache
def load_floor_plan(name: str) -> FloorPlan:
    """Load a shipped iTHOR scene.

    Args:
        name: the scene name, e.g. `FloorPlan1`.

    Returns:
        The floor plan with every object of the scene's initial metadata.

    Raises:
        FileNotFoundError: the scene is not in `sim/data/scenes/`.
    """
    raw = json.loads((SCENES_DIR / f"{name}.json").read_text(encoding="utf-8"))
    room_type = str(raw["roomType"])
    room = ROOM_NAMES[room_type]
    objects, relations = scene_objects(raw["objects"], room)
    return FloorPlan(name=str(raw["scene"]), room_type=room_type, room=room, objects=objects,
                     relations=relations)


def scene_objects(entries: list[dict[str, Any]], room: str
                  ) -> tuple[tuple[SceneObject, ...], tuple[Relation, ...]]:
    """AI2-THOR object metadata (`event.metadata["objects"]`) as scene objects and relations.

    Args:
        entries: one metadata dict per object.
        room: the room every object is in.

    Returns:
        The objects, and the `controls` relations of knobs to burners.
    """
    types = {o["objectId"]: o["objectType"] for o in entries}
    objects = tuple(_scene_object(o, room, types) for o in entries)
    relations = tuple(
        Relation(subject=o["objectId"], relation="controls", object=controlled)
        for o in entries for controlled in o.get("controlledObjects") or ()
        if controlled in types)
    return objects, relations
