"""The domain's search planner: what it may act on, and which reading of the command it takes."""

from __future__ import annotations

from typing import Any

from app.domain.models import GateRequest
from app.domain.planning import PlanningTask, SearchPlanner
from app.domain.world import state_from_request
from tests.domain.planning.planning_kit import contract

SCENE: dict[str, Any] = {
    "layout": {"rooms": ["kitchen", "den"], "connections": [["kitchen", "den"]]},
    "objects": [
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
        {"id": "pot_1", "type": "Pot", "on": "counter_1", "properties": {"mass_kg": 1.0}},
        {"id": "table_1", "type": "CoffeeTable", "room": "den"},
        {"id": "sofa_1", "type": "Sofa", "room": "den"},
    ],
    "people": [{"id": "mum", "role": "mum", "room": "den",
                "properties": {"age_group": "adult"}}],
}


def _task(command: str, scene: dict[str, Any] | None = None, **rules: Any) -> PlanningTask:
    request = GateRequest.model_validate({"command": command, "scene": scene or SCENE,
                                          "robot": {"room": "kitchen", "max_speed_mps": 0.5}})
    return PlanningTask(request, state_from_request(request), contract(**rules))


def _with_floors(scene: dict[str, Any], *, furnished: bool = True) -> dict[str, Any]:
    """The scene with a floor in each room; without the den's furniture if not `furnished`."""
    objects = [o for o in scene["objects"] if furnished or o.get("room") != "den"]
    floors = [{"id": f"floor_{room}", "type": "Floor", "room": room}
              for room in scene["layout"]["rooms"]]
    return {**scene, "objects": [*objects, *floors]}


class TestSearchPlanner:
    def test_taken_to_a_room_it_is_set_down_on_a_surface_there_when_dropping_is_forbidden(
            self) -> None:
        outcome = SearchPlanner().plan(_task("Take the pot to the den",
                                            guards=(("DropHandObject", "false"),)))
        assert outcome.plan is not None, outcome.reason
        last = outcome.plan[-1]
        assert last["action"] == "PutObject" and last["target"] in ("table_1", "sofa_1")

    def test_taken_to_a_room_with_furniture_it_is_not_set_down_on_the_floor(self) -> None:
        outcome = SearchPlanner().plan(_task("Take the pot to the den", _with_floors(SCENE),
                                             guards=(("DropHandObject", "false"),)))
        assert outcome.plan is not None, outcome.reason
        assert outcome.plan[-1]["target"] in ("table_1", "sofa_1")

    def test_taken_to_a_room_without_furniture_it_is_set_down_on_its_floor_not_dropped(
            self) -> None:
        outcome = SearchPlanner().plan(_task(
            "Take the pot to the den", _with_floors(SCENE, furnished=False),
            guards=(("DropHandObject", "false"),)))
        assert outcome.plan is not None, outcome.reason
        last = outcome.plan[-1]
        assert last == {"action": "PutObject", "object": "pot_1", "target": "floor_den"}
        assert not any(s["target"] == "floor_kitchen" for s in outcome.plan if "target" in s)

    def test_brought_to_a_person_it_is_handed_over_rather_than_set_down_near_them(
            self) -> None:
        outcome = SearchPlanner().plan(_task("Bring the pot to mum"))
        assert outcome.plan is not None, outcome.reason
        assert outcome.plan[-1]["action"] == "HandOver" and outcome.plan[-1]["target"] == "mum"

    def test_with_no_way_left_the_reason_names_the_contract(self) -> None:
        outcome = SearchPlanner().plan(_task("Take the pot to the den",
                                             guards=(("PickupObject", "false"),)))
        assert outcome.plan is None and "within the contract" in outcome.reason
