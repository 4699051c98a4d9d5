"""One episode end to end: gate -> contract -> plan -> verify -> execute under the monitor.

In: a `Scenario`, a method (`sim.methods`), a planner (`sim.planner.SimPlanner`: the domain's
search planner over the simulator's dynamics). Out: an `EpisodeResult`:
the decision, the plan, the verification, every executed step with its monitor verdict, the
hazard events, whether the simulator refused a step, whether the monitor halted, and whether the
scenario's goal holds at the end.

The gate, the planner, the verifier and the monitor see what the caller knows (the scenario's
`observed_request`); the simulator runs the ground truth (`true_request`) and fires the scene
events. Before each action the runtime sends the monitor a `before` message with what it
perceives (every person as they are now, and the objects a scene event changed, hidden
properties left out); after it, an `after` message with the same. A blocked task never runs; a
task without a plan, or whose plan fails verification, never runs either.
Fails: never; an exception inside the planner or verifier is recorded as the episode's error and
the task does not run (fail closed).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from app.domain.contracts import Contract
from app.domain.models import InitialState, Person, Scene
from app.domain.monitor import CompiledContract, Monitor
from app.domain.verify import verify_plan
from app.domain.world import WorldState, state_from_request
from sim.methods import SimMethod
from sim.planner import Planner, PlanningTask
from sim.scenario import Scenario, event_change, scripted_events
from sim.simulator import HazardEvent, Simulator

VERIFY_TIMEOUT_MS = 10_000


@dataclass
class StepRecord:
    """One executed (or refused) step."""

    index: int
    action: Mapping[str, Any]
    status: str
    monitor: str | None = None
    detail: str | None = None
    events: tuple[str, ...] = ()


@dataclass
class EpisodeResult:
    """Everything one method did on one scenario."""

    scenario: str
    category: str
    method: str
    decision: str
    right_decision: str
    reason: str = ""
    planner_goal: str | None = None
    plan: tuple[Mapping[str, Any], ...] | None = None
    planner_reason: str = ""
    verified: bool | None = None
    verify_reason: str | None = None
    executed: bool = False
    steps: list[StepRecord] = field(default_factory=list)
    hazards: list[HazardEvent] = field(default_factory=list)
    failure: str | None = None
    halted: bool = False
    halt: dict[str, Any] | None = None
    goal_reached: bool = False
    error: str | None = None

    @property
    def crashed(self) -> bool:
        """A hazard event happened or the simulator refused a step."""
        return bool(self.hazards) or self.failure is not None

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict."""
        return {
            "scenario": self.scenario, "category": self.category, "method": self.method,
            "decision": self.decision, "right_decision": self.right_decision,
            "reason": self.reason, "planner_goal": self.planner_goal,
            "plan": None if self.plan is None else [dict(a) for a in self.plan],
            "planner_reason": self.planner_reason, "verified": self.verified,
            "verify_reason": self.verify_reason, "executed": self.executed,
            "steps": [vars(s) | {"action": dict(s.action), "events": list(s.events)}
                      for s in self.steps],
            "hazards": [h.to_json() for h in self.hazards], "failure": self.failure,
            "halted": self.halted, "halt": self.halt, "goal_reached": self.goal_reached,
            "crashed": self.crashed, "error": self.error,
        }


def _observation(state: WorldState, hidden: Mapping[str, frozenset[str]],
                 changed: list[InitialState]) -> dict[str, Any]:
    people = [Person(id=p.id, role=p.role, name=p.name, room=p.room, posture=p.posture,
                     position=None if p.position is None else {
                         "x": p.position.x, "y": p.position.y},
                     properties={k: v for k, v in p.properties.items()
                                 if k not in hidden.get(p.id, frozenset())})
              for p in state.people.values()]
    objects = [o for change in changed for o in (change.scene.objects if change.scene else [])]
    scene = Scene(people=people, objects=objects)
    return InitialState(scene=scene).model_dump(mode="json", by_alias=True, exclude_none=True)


def _execute(result: EpisodeResult, scenario: Scenario, plan: tuple[Mapping[str, Any], ...],
             contract: Contract | None, observed: WorldState) -> None:
    simulator = Simulator(state_from_request(scenario.true_request()), scripted_events(scenario))
    monitor = Monitor(CompiledContract(contract), observed) if contract is not None else None
    hidden = scenario.hidden_keys()
    by_description = {e.description: e for e in scenario.events}
    result.executed = True
    for index, raw in enumerate(plan):
        fired = simulator.fire_events()
        seen = [event_change(scenario, by_description[e.description], observed=True)
                for e in fired]
        record = StepRecord(index, raw, "pending", events=tuple(e.description for e in fired))
        result.steps.append(record)
        if monitor is not None:
            verdict = monitor.step({"type": "before", "seq": index, "action": dict(raw),
                                    "state": _observation(simulator.state, hidden, seen)})
            record.monitor = verdict.type
            if verdict.type != "allow":
                record.status = "not run"
                _halt(result, verdict)
                break
        outcome = simulator.execute(raw)
        record.status = outcome.status
        if outcome.status == "failed":
            record.detail = result.failure = outcome.failure
            break
        if monitor is not None:
            verdict = monitor.step({"type": "after", "seq": index, "action": dict(raw),
                                    "state": _observation(simulator.state, hidden, [])})
            record.monitor = verdict.type
            if verdict.type != "allow":
                _halt(result, verdict)
                break
    else:
        simulator.fire_events()
    simulator.finish()
    result.hazards = list(simulator.hazards)
    result.goal_reached = simulator.holds(scenario.goal)


def _halt(result: EpisodeResult, verdict: Any) -> None:
    result.halted = True
    violation = verdict.violation
    result.halt = {"verdict": verdict.type, "detail": verdict.detail} if violation is None else {
        "verdict": verdict.type, "kind": violation.kind, "condition_id": violation.condition_id,
        "formula": violation.formula, "description": violation.description,
        "action": dict(violation.action)}


def run_episode(scenario: Scenario, method: SimMethod, planner: Planner) -> EpisodeResult:
    """Run one scenario with one method.

    Args:
        scenario: the scenario.
        method: who decides (and whether its plans run under contract and monitor).
        planner: who plans an authorized task.

    Returns:
        The episode's record.
    """
    request = scenario.observed_request()
    decision = method.decide(request)
    result = EpisodeResult(scenario.id, scenario.category, method.name, decision.decision,
                           scenario.right_decision, decision.reason)
    if decision.decision != "authorize":
        return result
    contract = decision.contract if method.guarded else None
    if method.guarded and contract is None:
        result.error = "authorized without a contract: nothing runs (fail closed)"
        return result
    observed = state_from_request(request)
    try:
        outcome = planner.plan(PlanningTask(request, observed, contract))
        result.planner_goal, result.plan = outcome.goal, outcome.plan
        result.planner_reason = outcome.reason
        if outcome.plan is None:
            return result
        if contract is not None:
            verdict = verify_plan(list(outcome.plan), contract, observed,
                                  timeout_ms=VERIFY_TIMEOUT_MS)
            result.verified, result.verify_reason = verdict.ok, verdict.reason
            if not verdict.ok:
                return result
    except Exception as error:
        result.error = f"{type(error).__name__}: {error}"
        return result
    _execute(result, scenario, outcome.plan, contract, observed)
    return result
