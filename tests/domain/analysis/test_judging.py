"""Variants, simulation and judging: what a careful plan avoids, what no plan can."""

from __future__ import annotations

from types import MappingProxyType

from app.domain.analysis.judge import Focus, judge
from app.domain.analysis.library import LibraryCache
from app.domain.analysis.simulate import simulate
from app.domain.analysis.sketch import CAREFUL_SPEED, Choice, Planned, Sketch, variants
from app.domain.models import GateRequest, HazardTemplate
from app.domain.world import Action, state_from_request

BURNER = HazardTemplate.model_validate({
    "id": "t.heat_left_on", "name": "Heat left on", "category": "consequential",
    "hazard_class": "appliance_left_on", "description": "d", "severity": "high",
    "preventability": "preventable",
    "variables": [{"name": "obj", "type": "object", "description": "the heat source"}],
    "guards": [{"id": "off_at_the_end", "action": "Finish", "formula": "not is_on($obj)",
                "description": "Nothing is left on at the end."}],
})
SCENE = {"objects": [{"id": "stove_1", "type": "StoveBurner", "room": "kitchen",
                      "properties": {"on": False}},
                     {"id": "oven_1", "type": "Oven", "room": "kitchen",
                      "properties": {"on": True}}],
         "people": []}


def trace_of(*actions: Action, cleanup: tuple[Action, ...] = (), leave: bool = False):  # type: ignore[no-untyped-def]
    sketch = Sketch(literal=[Planned(a, 0) for a in actions],
                    cleanup=[Planned(a, 0, "cleanup") for a in cleanup], leave=leave)
    state = state_from_request(GateRequest.model_validate({"command": "x", "scene": SCENE}))
    return simulate(state, variants(sketch))


def findings(traces):  # type: ignore[no-untyped-def]
    focus = Focus(("stove_1", "oven_1"), (), ("kitchen",))
    return judge(traces, [BURNER], focus, LibraryCache())


class TestVariants:
    def test_careful_plans_move_slowly_and_clean_up_careless_ones_do_not(self) -> None:
        sketch = Sketch(literal=[Planned(Action("navigate", target="hall"), 0)],
                        cleanup=[Planned(Action("CloseObject", "door_1"), 0, "cleanup")])
        careful, careless = variants(sketch)
        assert careful.careful and careful.steps[0].action.params["speed"] == CAREFUL_SPEED
        assert [s.action.name for s in careful.steps] == ["navigate", "CloseObject"]
        assert "speed" not in careless.steps[0].action.params and len(careless.steps) == 1

    def test_every_option_of_a_choice_gets_its_own_plans(self) -> None:
        give = (Planned(Action("HandOver", "mug", "dad"), 0),)
        put = (Planned(Action("PutObject", "mug", "table"), 0),)
        sketch = Sketch(literal=[Choice((give, put), "hand over or set down")])
        assert len(variants(sketch)) == 4

    def test_a_switch_off_follows_its_own_clause_not_the_whole_task(self) -> None:
        sketch = Sketch(literal=[Planned(Action("ToggleObjectOn", "stove_1"), 0),
                                 Planned(Action("navigate", target="hall",
                                                params=MappingProxyType({})), 1)],
                        cleanup=[Planned(Action("ToggleObjectOff", "stove_1"), 0, "cleanup")])
        careful = variants(sketch)[0]
        assert [s.action.name for s in careful.steps] == [
            "ToggleObjectOn", "ToggleObjectOff", "navigate"]


class TestJudge:
    def test_what_only_the_careless_plan_leaves_on_is_found_there(self) -> None:
        traces = trace_of(Action("ToggleObjectOn", "stove_1"),
                          cleanup=(Action("ToggleObjectOff", "stove_1"),))
        found = findings(traces)
        assert [(f.trace.careful, f.violated) for f in found] == [(False, True)]
        assert found[0].step is not None and found[0].step.action.name == "Finish"

    def test_leaving_it_on_breaks_it_in_every_plan(self) -> None:
        traces = trace_of(Action("ToggleObjectOn", "stove_1"),
                          cleanup=(Action("ToggleObjectOff", "stove_1"),), leave=True)
        assert {f.trace.careful for f in findings(traces)} == {True, False}

    def test_what_was_already_so_before_the_task_is_not_its_doing(self) -> None:
        traces = trace_of(Action("Wait", params=MappingProxyType({"seconds": 5.0})))
        assert findings(traces) == []  # the oven was on before the task began
