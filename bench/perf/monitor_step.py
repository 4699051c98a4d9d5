"""Runtime monitor, in process: the cost of checking one action against a 20-condition contract.

Run: `.venv/bin/python bench/perf/monitor_step.py` (or `make perf`). Prints a table.
Target (issue 5): checking one action (its `before` and its `after`) <= 20 us.

Rows: "check" is the contract evaluation the monitor does for one action: the aborts and the
action's guards in the state before it, the aborts and the invariants in the state after it (facts
already derived, as the formula benchmark measures them); the worst case evaluates every guard.
"step" adds the rest of `Monitor.step` for a `before` and an `after` message given as dicts
(parsing the message and the action, the action model's predicted next state, the verdicts).
"step + delta" also applies a one-object observation in each message, and "step + delta, JSON"
decodes the messages from text.
"""

from __future__ import annotations

import json
import statistics
import time
from collections.abc import Callable
from typing import Any

from rich.console import Console
from rich.table import Table

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.domain.monitor import CompiledContract, Monitor, first_failure
from app.domain.world import parse_action, state_from_request, step

TARGET_US = 20.0
ROUNDS = 7
ACTIONS_PER_ROUND = 2000

SCENE: dict[str, Any] = {
    "command": "tidy the kitchen",
    "scene": {
        "layout": {"rooms": ["kitchen", "living_room", "hallway"],
                   "connections": [["kitchen", "hallway"], ["hallway", "living_room"]]},
        "objects": [
            {"id": f"cup_{i}", "type": "Cup", "room": "kitchen", "on": "counter_1",
             "position": {"x": 1.0 + i / 10, "y": 0.5},
             "properties": {"mass_kg": 0.2, "temperature": "cold", "sharp": False}}
            for i in range(12)
        ] + [
            {"id": "counter_1", "type": "CounterTop", "room": "kitchen",
             "properties": {"wet": False}},
            {"id": "knife_1", "type": "Knife", "room": "kitchen", "properties": {"sharp": True}},
            {"id": "stove_1", "type": "StoveBurner", "room": "kitchen",
             "properties": {"on": False}},
            {"id": "kettle_1", "type": "Kettle", "room": "kitchen",
             "properties": {"temperature": "cold", "mass_kg": 1.0}},
        ],
        "people": [
            {"id": "p1", "role": "owner", "room": "living_room", "position": {"x": 6, "y": 2},
             "properties": {"age_group": "adult"}},
            {"id": "child_1", "role": "son", "room": "hallway", "position": {"x": 4, "y": 1},
             "properties": {"age_group": "child"}},
        ],
    },
    "user": {"person_id": "p1", "age_group": "adult"},
    "robot": {"room": "kitchen", "position": {"x": 1.0, "y": 0.4}, "payload_kg": 2.0,
              "max_speed_mps": 0.5, "skills": ["navigate", "pick", "place", "handover"]},
}

INVARIANTS = [
    "load_kg(robot) <= payload(robot)",
    "load_kg(robot) <= 0.9 * payload(robot)",
    "forall p: person . holding(robot, #kettle_1) and hot(#kettle_1) -> not near(robot, p)",
    "forall p: person . child(p) -> not near(p, #knife_1) or not holding(robot, #knife_1)",
    "holding(robot, #knife_1) -> speed(robot) <= 0.5",
    "not is_on(#stove_1) or near(robot, #stove_1)",
]
GUARDS = [  # (action, formula): spread over action types as in compiled contracts
    ("PickupObject", 'has_skill(robot, "pick")'),
    ("PickupObject", "@object != #knife_1"),
    ("PickupObject", "@object != #kettle_1 or not hot(#kettle_1)"),
    ("PickupObject", "load_kg(robot) + mass_kg(@object) <= payload(robot)"),
    ("PutObject", "forall p: person . child(p) -> not near(p, @object)"),
    ("PutObject", "not hot(@object)"),
    ("HandOver", "not sharp(@object)"),
    ("navigate", "forall p: person . not near(p, robot) or not child(p)"),
    ("ToggleObjectOn", "@object != #stove_1"),
    ("HandOver", "exists o: object . o == @object"),
]
ABORTS = [
    "is_on(#stove_1) and exists p: person . child(p) and near(p, #stove_1)",
    "exists p: person . child(p) and near(p, #knife_1)",
    "wet(#counter_1) and is_on(#stove_1)",
    "hot(#kettle_1) and exists p: person . child(p) and near(p, #kettle_1)",
]


def _condition(kind: ConditionKind, index: int, formula: str,
               action: str | None = None) -> ContractCondition:
    return ContractCondition(
        id=f"bench.{kind.value}_{index}", kind=kind, formula=formula, description=formula,
        action=action, template_id="bench", template_version=1, bindings={})


CONTRACT = Contract(
    invariants=tuple(_condition(ConditionKind.INVARIANT, i, f) for i, f in enumerate(INVARIANTS)),
    guards=tuple(_condition(ConditionKind.GUARD, i, f, a) for i, (a, f) in enumerate(GUARDS)),
    aborts=tuple(_condition(ConditionKind.ABORT, i, f) for i, f in enumerate(ABORTS)),
)


def per_action_us(run_one: Callable[[int], None]) -> list[float]:
    """Per-action microseconds of each round (the median round is reported)."""
    rounds = []
    for _ in range(ROUNDS):
        started = time.perf_counter()
        for i in range(ACTIONS_PER_ROUND):
            run_one(i)
        rounds.append((time.perf_counter() - started) / ACTIONS_PER_ROUND * 1e6)
    return rounds


def main() -> None:
    assert len(CONTRACT) == 20
    compiled = CompiledContract(CONTRACT)
    state = state_from_request(GateRequest.model_validate(SCENE))
    pick = parse_action({"action": "PickupObject", "object": "cup_3"}, step=0, state=state)
    picked = step(state, pick)
    guards, args = compiled.guards_for("PickupObject"), pick.args
    every_guard = tuple(g for g in compiled.conditions if g.kind == "guard")

    def check(_: int) -> None:
        failure = (first_failure(compiled.aborts, state, None, must_be=False)
                   or first_failure(guards, state, args, must_be=True)
                   or first_failure(compiled.aborts, picked, None, must_be=False)
                   or first_failure(compiled.invariants, picked, None, must_be=True))
        assert failure is None, failure

    def check_all(_: int) -> None:
        failure = (first_failure(compiled.aborts, state, None, must_be=False)
                   or first_failure(every_guard, state, args, must_be=True)
                   or first_failure(compiled.aborts, picked, None, must_be=False)
                   or first_failure(compiled.invariants, picked, None, must_be=True))
        assert failure is None, failure

    def stepper(delta: bool, as_text: bool) -> Callable[[int], None]:
        monitor = Monitor(compiled, state)
        cup = SCENE["scene"]["objects"][3]
        observation = {"scene": {"objects": [cup]}}

        def one(i: int) -> None:
            action = {"action": "PickupObject" if i % 2 == 0 else "PutObject",
                      "object": "cup_3", **({} if i % 2 == 0 else {"target": "counter_1"})}
            seq = monitor.counters.actions_checked  # 0, 1, 2...: each follows the last
            for kind in ("before", "after"):
                message: dict[str, Any] = {"type": kind, "seq": seq, "action": action}
                if delta:
                    message["state"] = observation
                verdict = monitor.step(json.dumps(message) if as_text else message)
                assert verdict.allowed, verdict.to_wire()

        return one

    rows = [("check: PickupObject (4 aborts, 4 guards; 4 aborts, 6 invariants)",
             per_action_us(check)),
            ("check, worst case: all 20 conditions (aborts twice)", per_action_us(check_all))]
    rows.append(("step: before + after messages", per_action_us(stepper(False, False))))
    rows.append(("step + one-object delta each", per_action_us(stepper(True, False))))
    rows.append(("step + delta, JSON text", per_action_us(stepper(True, True))))

    table = Table(title=f"Monitor, in process: one action, 20-condition contract "
                        f"({ROUNDS} rounds x {ACTIONS_PER_ROUND} actions; median round)")
    for column in ("path", "median us/action", "best round", "worst round", "target"):
        table.add_column(column, justify="left" if column == "path" else "right")
    for name, rounds in rows:
        target = (f"<= {TARGET_US:.0f} us " + ("OK" if statistics.median(rounds) <= TARGET_US
                                                else "MISSED")) if name.startswith("check") else ""
        table.add_row(name, f"{statistics.median(rounds):.1f}", f"{min(rounds):.1f}",
                      f"{max(rounds):.1f}", target)
    Console().print(table)


if __name__ == "__main__":
    main()
