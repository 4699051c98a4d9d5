"""Scenarios: a command on a real iTHOR floor plan with people, hidden truths and scene events.

In: one YAML file under `sim/scenarios/` (schema in `sim/scenarios/README.md`). Out: a frozen
`Scenario`, and from it two gate requests: `true_request()` (the world as it is, which the
simulator runs) and `observed_request()` (what the robot's caller knows: every property a
scenario lists under `hidden` is removed, so it is unknown to the gate, the planner, the verifier
and the monitor). People are placed by position or next to an object (`at`). A room the scenario
adds beside the floor plan's own (`extra_rooms`) has a floor (`Floor|<room>`, like every iTHOR
room) and whatever the scenario lists in it. Fails:
`ScenarioError` naming the file and the problem (bad YAML, a field that fails validation, an
object or person id that is not in the scene).
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from app.domain.errors import InvalidInput
from app.domain.models import (
    GateRequest,
    InitialState,
    Layout,
    Person,
    Position,
    Relation,
    RobotProfile,
    Scene,
    SceneObject,
    UserProfile,
)
from sim.floorplans import FloorPlan, load_floor_plan
from sim.simulator import ScriptedEvent, compile_goal

SCENARIOS_DIR = Path(__file__).with_name("scenarios")
Category = Literal["compositional", "incomplete_information", "consequential_state",
                   "safe_control"]
HAZARD_CATEGORIES: tuple[Category, ...] = ("compositional", "incomplete_information",
                                           "consequential_state")
DecisionName = Literal["authorize", "defer", "reject"]
DEFAULT_SKILLS = ("navigate", "pick", "place", "open", "close", "toggle", "pour", "fill",
                  "handover", "clean", "slice", "throw", "drop", "push")
PERSON_OFFSET_M = 0.5


class ScenarioError(ValueError):
    """A scenario file that cannot be loaded."""


class _Strict(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid", populate_by_name=True)


class PersonSpec(_Strict):
    """A person added to the floor plan. `at` places them next to an object."""

    id: str
    role: str | None = None
    name: str | None = None
    room: str | None = None
    posture: str | None = None
    position: Position | None = None
    at: str | None = None
    properties: dict[str, Any] = Field(default_factory=dict)
    hidden: tuple[str, ...] = ()


class ObjectSpec(_Strict):
    """An object changed (same id as a floor-plan object) or added (a new id with a type)."""

    id: str
    type: str | None = None
    name: str | None = None
    on: str | None = None
    inside: str | None = Field(default=None, alias="in")
    room: str | None = None
    position: Position | None = None
    properties: dict[str, Any] = Field(default_factory=dict)
    hidden: tuple[str, ...] = ()


class RobotSpec(_Strict):
    """Where the robot starts and what it can do (defaults: a capable household robot)."""

    at: str | None = None
    position: Position | None = None
    skills: tuple[str, ...] = DEFAULT_SKILLS
    sensors: tuple[str, ...] = ("rgbd_camera", "lidar")
    payload_kg: float = 3.0
    max_speed_mps: float = 0.8
    holding: str | None = None


class SceneEvent(_Strict):
    """Something that happens in the scene after the robot's `after_step`-th action."""

    after_step: int = Field(ge=0)
    description: str
    people: tuple[PersonSpec, ...] = ()
    objects: tuple[ObjectSpec, ...] = ()


class Scenario(_Strict):
    """One simulated task: the command, the scene, the right decision and the goal."""

    id: str
    category: Category
    floor_plan: str
    command: str
    why: str
    right_decision: DecisionName
    goal: str
    extra_rooms: tuple[str, ...] = ()
    people: tuple[PersonSpec, ...] = ()
    user: UserProfile | None = None
    objects: tuple[ObjectSpec, ...] = ()
    relations: tuple[Relation, ...] = ()
    robot: RobotSpec = RobotSpec()
    events: tuple[SceneEvent, ...] = ()
    note: str | None = None

    @property
    def plan_room(self) -> str:
        """The floor plan's own room (kitchen, living_room, bedroom or bathroom)."""
        return load_floor_plan(self.floor_plan).room

    def true_request(self) -> GateRequest:
        """The world as it is: what the simulator executes in."""
        return _request(self, observed=False)

    def observed_request(self) -> GateRequest:
        """What the caller knows: the gate request, with every hidden property removed."""
        return _request(self, observed=True)

    def hidden_keys(self) -> dict[str, frozenset[str]]:
        """For each entity id, the properties the robot's caller does not know."""
        hidden: dict[str, frozenset[str]] = {}
        specs: list[PersonSpec | ObjectSpec] = [*self.people, *self.objects]
        for event in self.events:
            specs.extend((*event.people, *event.objects))
        for spec in specs:
            if spec.hidden:
                hidden[spec.id] = hidden.get(spec.id, frozenset()) | frozenset(spec.hidden)
        return hidden


def _floor_point(plan: FloorPlan, object_id: str, offset: float) -> Position:
    anchor = plan.object(object_id).position
    assert anchor is not None  # every floor-plan object has a position
    return Position(x=round(anchor.x + offset, 3), y=anchor.y)


def _centre(plan: FloorPlan) -> Position:
    points = [o.position for o in plan.objects if o.position is not None]
    return Position(x=round(sum(p.x for p in points) / len(points), 3),
                    y=round(sum(p.y for p in points) / len(points), 3))


def build_person(plan: FloorPlan, spec: PersonSpec, *, observed: bool) -> Person:
    """The gate-request person a spec describes (hidden properties removed when observed)."""
    position = spec.position
    room = spec.room
    if spec.at is not None:
        position = _floor_point(plan, spec.at, PERSON_OFFSET_M)
        room = room or plan.room
    properties = {k: v for k, v in spec.properties.items()
                  if not (observed and k in spec.hidden)}
    return Person(id=spec.id, role=spec.role, name=spec.name, room=room, posture=spec.posture,
                  position=position, properties=properties)


def _merge_object(plan: FloorPlan, base: SceneObject | None, spec: ObjectSpec,
                  observed: bool) -> SceneObject:
    fields: dict[str, Any] = {} if base is None else base.model_dump(by_alias=True)
    fields["id"] = spec.id
    for key in ("type", "name", "room"):
        if getattr(spec, key) is not None:
            fields[key] = getattr(spec, key)
    fields.setdefault("room", plan.room)
    if spec.position is not None:
        fields["position"] = spec.position.model_dump()
    if spec.on is not None or spec.inside is not None:
        fields["on"], fields["in"] = spec.on, spec.inside
        if spec.position is None:
            fields["position"] = None  # it rests where its receptacle is
    properties = {**fields.get("properties", {}), **spec.properties}
    if observed:
        properties = {k: v for k, v in properties.items() if k not in spec.hidden}
    fields["properties"] = properties
    if "type" not in fields:
        raise ScenarioError(f"object {spec.id!r} is new but has no type")
    return SceneObject.model_validate(fields)


def apply_object_specs(plan: FloorPlan, objects: Iterable[SceneObject],
                       specs: Iterable[ObjectSpec], *, observed: bool) -> list[SceneObject]:
    """The objects with each spec applied: changes to existing ids, additions for new ones."""
    merged = {o.id: o for o in objects}
    for spec in specs:
        merged[spec.id] = _merge_object(plan, merged.get(spec.id), spec, observed)
    return list(merged.values())


def _request(scenario: Scenario, *, observed: bool) -> GateRequest:
    plan = load_floor_plan(scenario.floor_plan)
    rooms = [plan.room, *scenario.extra_rooms]
    # Every iTHOR room has a Floor object; the rooms a scenario adds beside the floor plan have
    # nothing else the scenario does not list, but they have a floor to set things down on.
    floors = [SceneObject(id=f"Floor|{room}", type="Floor", room=room)
              for room in scenario.extra_rooms]
    objects = apply_object_specs(plan, [*plan.objects, *floors], scenario.objects,
                                 observed=observed)
    people = [build_person(plan, p, observed=observed) for p in scenario.people]
    robot = scenario.robot
    position = robot.position or (
        _floor_point(plan, robot.at, 0.0) if robot.at else _centre(plan))
    user = scenario.user
    if user is not None and observed:
        hidden = {k for p in scenario.people if p.id == user.person_id for k in p.hidden}
        user = user.model_copy(update={k: None for k in hidden if k in type(user).model_fields})
    return GateRequest(
        command=scenario.command,
        scene=Scene(
            layout=Layout(rooms=rooms, connections=[(plan.room, r) for r in rooms[1:]]),
            objects=objects, relations=[*plan.relations, *scenario.relations], people=people),
        user=user,
        robot=RobotProfile(name="sim-robot", room=plan.room, position=position,
                           skills=list(robot.skills), sensors=list(robot.sensors),
                           payload_kg=robot.payload_kg, max_speed_mps=robot.max_speed_mps,
                           holding=robot.holding),
    )


def load_scenario(path: Path) -> Scenario:
    """Load and check one scenario file.

    Args:
        path: a `.yaml` file.

    Returns:
        The scenario; its goal formula parses and type-checks, and every id it names exists.

    Raises:
        ScenarioError: anything malformed, naming the file.
    """
    try:
        raw = yaml.safe_load(path.read_text(encoding="utf-8"))
        scenario = Scenario.model_validate(raw)
        compile_goal(scenario.goal)
        plan = load_floor_plan(scenario.floor_plan)
        ids = {o.id for o in plan.objects} | {o.id for o in scenario.objects}
        for name in (*(p.at for p in scenario.people), scenario.robot.at,
                     *(p.at for e in scenario.events for p in e.people)):
            if name is not None and name not in ids:
                raise ScenarioError(f"{name!r} is not an object of {scenario.floor_plan}")
        scenario.true_request()
    except ScenarioError as error:
        raise ScenarioError(f"{path.name}: {error}") from error
    except (yaml.YAMLError, ValidationError, ValueError, KeyError, OSError, InvalidInput) as error:
        raise ScenarioError(f"{path.name}: {error}") from error
    return scenario


def load_scenarios(directory: Path = SCENARIOS_DIR) -> list[Scenario]:
    """Every scenario under a directory, in file-name order.

    Raises:
        ScenarioError: a malformed file, or two scenarios with one id.
    """
    scenarios = [load_scenario(p) for p in sorted(directory.glob("*.yaml"))]
    seen: set[str] = set()
    for scenario in scenarios:
        if scenario.id in seen:
            raise ScenarioError(f"scenario id {scenario.id!r} is used twice")
        seen.add(scenario.id)
    return scenarios


def event_change(scenario: Scenario, event: SceneEvent, *, observed: bool) -> InitialState:
    """A scene event as a partial snapshot: the people and objects it adds or changes.

    Args:
        scenario: the scenario the event belongs to.
        event: the event.
        observed: drop hidden properties (what the robot perceives) or keep them (the truth).

    Returns:
        An `InitialState` to apply with `apply_snapshot`.
    """
    plan = load_floor_plan(scenario.floor_plan)
    base = {o.id: o for o in apply_object_specs(plan, plan.objects, scenario.objects,
                                                observed=observed)}
    changed = [_merge_object(plan, base.get(s.id), s, observed) for s in event.objects]
    people = [build_person(plan, p, observed=observed) for p in event.people]
    return InitialState(scene=Scene(objects=changed, people=people))


def scripted_events(scenario: Scenario) -> list[ScriptedEvent]:
    """The scenario's scene events, with the ground truth of what changes."""
    return [ScriptedEvent(e.after_step, e.description, event_change(scenario, e, observed=False))
            for e in scenario.events]
