"""Routes through a layout and whether reaching a place means taking the stairs."""

from __future__ import annotations

from typing import Any

from app.domain.models import GateRequest
from app.domain.world import state_from_request

TWO_FLOORS: dict[str, Any] = {
    "layout": {"rooms": ["lounge", "hallway", "stairs", "landing", "bedroom", "kitchen"],
               "connections": [["lounge", "hallway"], ["hallway", "kitchen"],
                               ["hallway", "stairs"], ["stairs", "landing"],
                               ["landing", "bedroom"]]},
    "objects": [{"id": "glasses_1", "type": "Glasses", "room": "bedroom"},
                {"id": "cup_1", "type": "Cup", "room": "kitchen"}],
    "people": [],
}


def _state(skills: list[str], scene: dict[str, Any] = TWO_FLOORS) -> Any:
    return state_from_request(GateRequest.model_validate({
        "command": "wait", "scene": scene,
        "robot": {"room": "lounge", "skills": skills, "payload_kg": 2.0}}))


def test_route_is_the_fewest_connections_and_can_avoid_rooms() -> None:
    state = _state(["navigate"])
    assert state.route("lounge", "bedroom") == (
        "lounge", "hallway", "stairs", "landing", "bedroom")
    assert state.route("lounge", "bedroom", avoiding=frozenset({"stairs"})) is None
    assert state.route("kitchen", "kitchen") == ("kitchen",)


def test_upstairs_is_via_stairs_and_the_kitchen_is_not() -> None:
    state = _state(["navigate"])
    assert state.value("via_stairs", ("glasses_1",)) is True
    assert state.value("via_stairs", ("cup_1",)) is False
    assert state.value("room_via_stairs", ("landing",)) is True


def test_a_lift_makes_the_stairs_unnecessary() -> None:
    scene = {**TWO_FLOORS, "layout": {
        "rooms": [*TWO_FLOORS["layout"]["rooms"], "lift"],
        "connections": [*TWO_FLOORS["layout"]["connections"], ["hallway", "lift"],
                        ["lift", "landing"]]}}
    assert _state(["navigate"], scene).value("via_stairs", ("glasses_1",)) is False


def test_stair_climbing_skill_names_agree() -> None:
    state = _state(["navigate", "stair_climbing"])
    assert state.value("has_skill", ("robot", "climb_stairs")) is True
