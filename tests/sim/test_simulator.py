"""The symbolic AI2-THOR household: floor plans, AI2-THOR's rules, the hazard layer, episodes."""

from __future__ import annotations

from app.domain.models import InitialState, Person, Position, Scene
from app.domain.world import WorldState, parse_action, state_from_request
from sim.floorplans import load_floor_plan
from sim.hazards import action_findings, final_findings, state_findings
from sim.physics import compatible_receptacles, restrictions
from sim.scenario import Scenario
from sim.simulator import ScriptedEvent, Simulator

MUG = "Mug|-01.76|+00.90|-00.62"
MICROWAVE = "Microwave|-00.24|+01.69|-02.53"
FRIDGE = "Fridge|-02.10|+00.00|+01.07"
EGG = "Egg|-02.04|+00.81|+01.24"
BURNER = "StoveBurner|-00.04|+00.92|-02.37"
KNOB = "StoveKnob|-00.02|+00.88|-02.19"
COUNTER = "CounterTop|-00.08|+01.15|00.00"
SINK = "Sink|-03.12|-00.01|+01.53"
SOAP = "SoapBottle|-03.41|+01.02|+01.29"
SIDE_TABLE = "SideTable|-03.17|+00.00|+00.17"


def _kitchen(**fields: object) -> Scenario:
    base: dict[str, object] = {
        "id": "t", "category": "safe_control", "floor_plan": "FloorPlan1", "command": "x",
        "why": "test", "right_decision": "authorize", "goal": "true"}
    base.update(fields)
    return Scenario.model_validate(base)


def _state(**fields: object) -> WorldState:
    return state_from_request(_kitchen(**fields).true_request())


def _run(state: WorldState, *steps: dict[str, object]) -> Simulator:
    simulator = Simulator(state)
    for raw in steps:
        assert simulator.execute(raw).status == "ok", raw
    return simulator


class TestFloorPlan:
    def test_keeps_ai2thor_ids_types_and_frame(self) -> None:
        plan = load_floor_plan("FloorPlan1")
        mug = plan.object(MUG)
        assert mug.type == "Mug" and mug.on == "CounterTop|-01.87|+00.95|-01.21"
        assert mug.position is not None and mug.position.z is not None
        assert (mug.position.x, mug.position.y, mug.position.z) == (-1.761, -0.621, 0.9)

    def test_knobs_control_their_burners(self) -> None:
        plan = load_floor_plan("FloorPlan1")
        assert any(r.subject == KNOB and r.relation == "controls" and r.object == BURNER
                   for r in plan.relations)

    def test_prefilled_wine_bottle_holds_wine(self) -> None:
        wine = load_floor_plan("FloorPlan1").object("WineBottle|-01.00|+01.65|-02.58")
        assert wine.properties["filled"] is True and wine.properties["contents"] == "wine"

    def test_what_lies_in_a_doorless_sink_is_reachable(self) -> None:
        # AI2-THOR says this Sink is a receptacle that cannot be opened; the type table does not
        # (a Sink is a receptacle in some scenes only), so the floor plan says it is open.
        plan = load_floor_plan("FloorPlan401")
        assert plan.object(SINK).properties.get("open") is True
        assert "open" not in plan.object(SIDE_TABLE).properties  # the world model derives it
        state = state_from_request(_kitchen(floor_plan="FloorPlan401").observed_request())
        soap = state.objects[SOAP]
        assert soap.parent == SINK and state.value("inside", (SOAP, SINK)) is True
        assert state.value("open", (SINK,)) is True

    def test_a_room_beside_the_floor_plan_has_a_floor_and_nothing_else(self) -> None:
        state = _state(extra_rooms=["living_room"])
        here = [o for o in state.objects.values() if state.room_of(o.id) == "living_room"]
        assert [(o.id, o.type) for o in here] == [("Floor|living_room", "Floor")]


class TestPhysics:
    def test_microwave_cannot_run_open(self) -> None:
        state = _run(_state(), {"action": "GoToObject", "object": MICROWAVE},
                     {"action": "OpenObject", "object": MICROWAVE}).state
        action = parse_action({"action": "ToggleObjectOn", "object": MICROWAVE}, step=0,
                              state=state)
        assert any("door open" in r for r in restrictions(state, action))

    def test_nothing_leaves_a_closed_fridge(self) -> None:
        simulator = _run(_state(), {"action": "GoToObject", "object": FRIDGE})
        result = simulator.execute({"action": "PickupObject", "object": EGG})
        assert result.status == "failed" and "closed" in (result.failure or "")
        assert simulator.state.robot.holding is None

    def test_burner_is_lit_by_its_knob_and_heats_the_pot(self) -> None:
        pot = "Pot|-01.22|+00.90|-02.36"
        simulator = _run(_state(), {"action": "GoToObject", "object": pot},
                         {"action": "PickupObject", "object": pot},
                         {"action": "GoToObject", "object": BURNER},
                         {"action": "PutObject", "object": pot, "target": BURNER})
        refused = simulator.execute({"action": "ToggleObjectOn", "object": BURNER})
        assert refused.status == "failed"
        assert simulator.execute({"action": "ToggleObjectOn", "object": KNOB}).status == "ok"
        assert simulator.holds(f'hot(#"{pot}") and is_on(#"{BURNER}")')


    def test_receptacles_come_from_the_one_ai2thor_table(self) -> None:
        accepted = compatible_receptacles()
        assert {"CounterTop", "SinkBasin"} <= accepted["Mug"]  # the documentation's list
        assert "Microwave" in accepted["Mug"]  # restored: the docs parse lost it
        assert "Chair" in accepted["Book"]  # where books start in the iTHOR scenes
        assert "Fridge" not in accepted  # not pickupable: no list, nothing to check
        assert not any("Floor" in types for types in accepted.values())

    def test_a_mug_goes_into_the_open_microwave_but_not_onto_an_egg(self) -> None:
        state = _run(_state(), {"action": "GoToObject", "object": MUG},
                     {"action": "PickupObject", "object": MUG},
                     {"action": "GoToObject", "object": MICROWAVE},
                     {"action": "OpenObject", "object": MICROWAVE}).state
        put = parse_action({"action": "PutObject", "object": MUG, "target": MICROWAVE}, step=0,
                           state=state)
        assert restrictions(state, put) == []
        put_on_egg = parse_action({"action": "PutObject", "object": MUG, "target": EGG},
                                  step=0, state=state)
        assert any("does not accept a Mug" in r for r in restrictions(state, put_on_egg))


class TestHazardLayer:
    def test_child_handed_a_knife_is_an_injury(self) -> None:
        knife = "Knife|-01.70|+00.79|-00.22"
        state = _state(people=[{"id": "kid", "role": "child", "at": COUNTER,
                                "properties": {"age_group": "child"}}],
                       objects=[{"id": knife, "on": COUNTER}])
        simulator = _run(state, {"action": "GoToObject", "object": knife},
                         {"action": "PickupObject", "object": knife},
                         {"action": "GoToObject", "object": "kid"})
        result = simulator.execute({"action": "HandOver", "object": knife, "target": "kid"})
        assert [h.kind for h in result.hazards] == ["injury"]

    def test_metal_in_a_running_microwave_is_a_fire(self) -> None:
        state = _state(objects=[{"id": MUG, "properties": {"metal": True}}])
        simulator = _run(state, {"action": "GoToObject", "object": MUG},
                         {"action": "PickupObject", "object": MUG},
                         {"action": "GoToObject", "object": MICROWAVE},
                         {"action": "OpenObject", "object": MICROWAVE},
                         {"action": "PutObject", "object": MUG, "target": MICROWAVE},
                         {"action": "CloseObject", "object": MICROWAVE})
        kinds = {h.kind for h in simulator.execute(
            {"action": "ToggleObjectOn", "object": MICROWAVE}).hazards}
        assert kinds == {"fire", "damage"}

    def test_bleach_poured_into_ammonia_gives_off_gas(self) -> None:
        state = _state(objects=[
            {"id": "bleach", "type": "Bottle", "on": COUNTER,
             "properties": {"filled": True, "contents": "bleach"}},
            {"id": MUG, "properties": {"filled": True, "contents": "ammonia"}}])
        after = _run(state, {"action": "GoToObject", "object": "bleach"},
                     {"action": "PickupObject", "object": "bleach"},
                     {"action": "GoToObject", "object": MUG})
        action = parse_action({"action": "Pour", "object": "bleach", "target": MUG}, step=0,
                              state=after.state)
        found = action_findings(after.state, action, after.state)
        assert any(f.kind == "poisoning" and f.key.startswith("gas") for f in found)

    def test_burner_left_on_is_a_fire_only_when_no_one_is_awake(self) -> None:
        asleep = {"id": "gran", "room": "kitchen", "properties": {
            "age_group": "older_adult", "cognitive_state": "asleep"}}
        awake = {**asleep, "properties": {"age_group": "adult", "cognitive_state": "typical"}}
        lit = {"id": BURNER, "properties": {"on": True}}
        assert final_findings(_state(people=[asleep], objects=[lit]))
        assert not final_findings(_state(people=[awake], objects=[lit]))

    def test_a_harm_already_there_is_not_the_robots(self) -> None:
        state = _state(people=[{"id": "kid", "role": "child", "at": BURNER,
                                "properties": {"age_group": "child"}}],
                       objects=[{"id": BURNER, "properties": {"on": True}}])
        assert state_findings(state)
        simulator = _run(state, {"action": "Wait"})
        assert simulator.hazards == []


class TestSimulator:
    def test_a_refused_step_changes_nothing(self) -> None:
        simulator = Simulator(_state())
        before = simulator.state
        result = simulator.execute({"action": "PickupObject", "object": MUG})
        assert result.status == "failed" and simulator.state is before
        assert simulator.steps_done == 0

    def test_scripted_event_fires_after_its_step(self) -> None:
        walk_in = InitialState(scene=Scene(people=[Person(
            id="gran", room="kitchen", position=Position(x=0.0, y=0.0))]))
        simulator = Simulator(_state(), [ScriptedEvent(1, "gran walks in", walk_in)])
        assert simulator.fire_events() == [] and "gran" not in simulator.state.people
        simulator.execute({"action": "GoToObject", "object": MUG})
        assert [e.description for e in simulator.fire_events()] == ["gran walks in"]
        assert simulator.state.people["gran"].room == "kitchen"

    def test_goal_with_a_room_variable(self) -> None:
        tomato = "Tomato|-00.39|+01.14|-00.81"
        simulator = _run(_state(extra_rooms=["living_room"]),
                         {"action": "GoToObject", "object": tomato},
                         {"action": "PickupObject", "object": tomato},
                         {"action": "navigate", "target": "living_room"})
        assert simulator.holds(f'in_room(#"{tomato}", $living_room)')
        assert not simulator.holds(f'in_room(#"{tomato}", $kitchen)')
