"""Benchmark: Stage 5 static verification of plans of 10, 50 and 200 steps, 30-condition contract.

In: nothing (builds a three-room household with 3 people and 22 objects, eight of them of a
type the knowledge base does not know, so many of their facts are unknown; a contract of 12
invariants, 12 guards and 6 aborts over them, 9 quantified (8 over people, like the library's
templates, one over objects, which none of them uses), several reading unknown facts; the task's
scope ("tidy up the widgets": picking up the eight widgets, everything else only moved aside,
so every step is checked against the scope and half the pickups by the aside rule); and a
plan that fetches and puts away objects in a loop, every step's preconditions satisfied).
Out: a Rich table per plan length: median, p90, per-step cost and Z3 calls; the target is a
median of <= 50 ms for 50 steps, and the per-step cost should stay about flat (linear growth).
Every plan must pass; a failing one means the benchmark measures the wrong thing (exit 1).
Then, in the same run, the same plans with one fault (the put nearest the middle thrown instead,
which a guard forbids): Stage 5 alone (what a failing /verify cost before repairs, the baseline)
and Stage 5 followed by the repair search (`app.domain.planning.repair_plan`) as a failing
/verify now runs it, against the same 50 ms target; the repair must be found and must pass
Stage 5 again (exit 1 otherwise; a missed time target is printed, as above).
Run: `.venv/bin/python bench/perf/verify_plan.py`.
"""

from __future__ import annotations

import statistics
import sys
import time
from typing import Any

from rich.console import Console
from rich.table import Table

from app.domain.contracts import Contract, ContractCondition
from app.domain.models import ConditionKind, GateRequest
from app.domain.planning import repair_plan
from app.domain.scope import ScopeStep, TaskScope
from app.domain.verify import verify_plan
from app.domain.world import WorldState, state_from_request

TARGET_MS = 50.0
LENGTHS = (10, 50, 200)
SAMPLES = 25
ITEMS = [f"gizmo_{i}" for i in range(8)]
KNOWN = ["mug_1", "plate_1", "bowl_1", "apple_1", "book_1", "cup_1"]

INVARIANTS = (
    "forall p: person . holding(robot, #mug_1) and hot(#mug_1) and near(robot, p) "
    "-> speed(robot) <= 0.3",
    "forall p: person . child(p) -> not reachable_by(#knife_1, p)",
    "not holding(robot, #knife_1)",
    "forall o: object . holding(robot, o) -> not (sharp(o) and not lidded(o)) or not toxic(o)",
    "holding(robot, #gizmo_0) -> load_kg(robot) == mass_kg(#gizmo_0)",
    "not (is_on(#stove_1) and (forall p: person . not same_room(p, #stove_1)))",
    "forall p: person . vulnerable(p) and near(robot, p) -> speed(robot) <= 0.3",
    "not (holding(#tom, #bleach_1))",
    "forall p: person . near(robot, p) -> speed(robot) <= 1.0",
    "toxic(#gizmo_3) or not toxic(#gizmo_3)",
    "not broken(#vase_1)",
    "forall p: person . not holding(p, #knife_1)",
)
GUARDS = (
    ("PickupObject", "@object != #knife_1"),
    ("PickupObject", "@object != #bleach_1 or not near(robot, #tom)"),
    # Only the solver settles this one for the widgets, whose lids are unknown.
    ("PickupObject", "lidded(@object) or not lidded(@object)"),
    ("PutObject", "not hot(@object) or not flammable(@target)"),
    ("PutObject", "not toxic(@object) or not food(@target)"),
    ("PutObject", "@target != #stove_1"),
    ("HandOver", "not sharp(@object)"),
    ("ThrowObject", "false"),
    ("DropHandObject", "not breakable(@object)"),
    ("ToggleObjectOn", "@object != #stove_1 or exists p: person . same_room(p, #stove_1)"),
    ("GoToObject", "forall p: person . not asleep(p) or not near(@object, p)"),
    ("navigate", "not holding(robot, #knife_1)"),
)
ABORTS = (
    "holding(#tom, #knife_1)",
    "wet(#floor_1) and exists p: person . near(p, #floor_1) and vulnerable(p)",
    "broken(#vase_1) and exists p: person . near(p, #vase_1)",
    "is_on(#stove_1) and flammable(#book_1) and on(#book_1, #stove_1)",
    "holding(robot, #bleach_1) and open(#bleach_1)",
    "exists p: person . holding(p, #bleach_1) and child(p)",
)


def build_state() -> WorldState:
    objects: list[dict[str, Any]] = [
        {"id": "counter_1", "type": "CounterTop", "room": "kitchen"},
        {"id": "table_1", "type": "DiningTable", "room": "kitchen"},
        {"id": "shelf_1", "type": "Shelf", "room": "den"},
        {"id": "floor_1", "type": "Floor", "room": "kitchen", "properties": {"wet": False}},
        {"id": "stove_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": False}},
        {"id": "knife_1", "type": "Knife", "room": "kitchen", "on": "counter_1"},
        {"id": "bleach_1", "type": "SprayBottle", "room": "den", "on": "shelf_1",
         "properties": {"contents": "bleach"}},
        {"id": "vase_1", "type": "Vase", "room": "den", "on": "shelf_1",
         "properties": {"broken": False}},
        *({"id": item, "type": "Widget", "room": "kitchen", "on": "counter_1",
           "properties": {"pickupable": True, "broken": False, "sharp": False,
                          "temperature": "room"}}
          for item in ITEMS),
        *({"id": obj, "type": obj.split("_")[0].capitalize(), "room": "kitchen",
           "on": "counter_1", "properties": {"temperature": "room"}} for obj in KNOWN),
    ]
    scene = {
        "layout": {"rooms": ["kitchen", "den", "hall"],
                   "connections": [["kitchen", "hall"], ["hall", "den"]]},
        "objects": objects,
        "people": [
            {"id": "ann", "room": "kitchen",
             "properties": {"age_group": "adult", "cognitive_state": "typical"}},
            {"id": "tom", "room": "den",
             "properties": {"age_group": "child", "cognitive_state": "typical"}},
            {"id": "gus", "room": "hall"},
        ],
    }
    request = {"command": "tidy up", "scene": scene,
               "robot": {"room": "kitchen", "payload_kg": 3.0, "max_speed_mps": 0.3}}
    return state_from_request(GateRequest.model_validate(request))


def build_contract() -> Contract:
    def condition(kind: ConditionKind, index: int, formula: str,
                  action: str | None = None) -> ContractCondition:
        return ContractCondition(
            id=f"bench.{kind.value}{index}", kind=kind, formula=formula,
            description=formula, action=action, template_id="bench", template_version=1,
            bindings={})

    return Contract(
        invariants=tuple(condition(ConditionKind.INVARIANT, i, f)
                         for i, f in enumerate(INVARIANTS)),
        guards=tuple(condition(ConditionKind.GUARD, i, f, a) for i, (a, f) in enumerate(GUARDS)),
        aborts=tuple(condition(ConditionKind.ABORT, i, f) for i, f in enumerate(ABORTS)),
        scope=TaskScope(command="tidy up the widgets", steps=tuple(
            ScopeStep(action="PickupObject", object=item, words="tidy up the widgets")
            for item in ITEMS)),
    )


def build_plan(length: int) -> list[dict[str, Any]]:
    """Fetch each object in turn and put it on the table or back on the counter."""
    plan: list[dict[str, Any]] = []
    round_trip = 0
    while len(plan) < length:
        item = (ITEMS + KNOWN)[round_trip % (len(ITEMS) + len(KNOWN))]
        target = "table_1" if round_trip % 2 == 0 else "counter_1"
        plan += [{"action": "GoToObject", "object": item},
                 {"action": "pick", "object": item},
                 {"action": "GoToObject", "object": target},
                 {"action": "put", "object": item, "target": target},
                 {"action": "Wait", "seconds": 1}]
        round_trip += 1
    return plan[:length]


def failing_plan(plan: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The plan with the put nearest its middle replaced by a throw (a guard forbids throws)."""
    puts = [i for i, s in enumerate(plan) if s["action"] == "put"]
    middle = min(puts, key=lambda i: abs(i - len(plan) // 2))
    return [*plan[:middle], {"action": "ThrowObject", "object": plan[middle]["object"]},
            *plan[middle + 1:]]


def _interleaved_ms(*runs: Any) -> list[tuple[float, float]]:
    """Median and p90 of each run, sampled in turn so a load change on the shared VM hits
    them alike."""
    timings: list[list[float]] = [[] for _ in runs]
    for _ in range(SAMPLES):
        for run, samples in zip(runs, timings, strict=True):
            start = time.perf_counter()
            run()
            samples.append((time.perf_counter() - start) * 1000)
    return [(statistics.median(t), sorted(t)[int(0.9 * (len(t) - 1))]) for t in timings]


def failing_table(state: WorldState, contract: Contract, console: Console) -> bool:
    """Failing plans: Stage 5 alone (the baseline) and Stage 5 with the repair search; False
    when a repair is missing or does not pass Stage 5 again."""
    table = Table(title="The same plans with one fault: failing /verify, without and with the "
                        "repair")
    for column in ("steps", "verify only: median ms", "verify + repair: median ms", "p90 ms",
                   "repair", "target"):
        table.add_column(column)
    fine = True
    for length in LENGTHS:
        plan = failing_plan(build_plan(length))
        if verify_plan(plan, contract, state, timeout_ms=10_000).ok:
            console.print(f"the faulty {length}-step plan passes; fix the benchmark")
            return False
        repair = repair_plan(plan, contract, state, timeout_ms=10_000)
        proved = repair.plan is not None and verify_plan(
            list(repair.plan), contract, state, timeout_ms=10_000).ok
        fine = fine and proved
        def both(p: list[dict[str, Any]] = plan) -> None:
            verdict = verify_plan(p, contract, state, timeout_ms=10_000)
            repair_plan(p, contract, state, timeout_ms=10_000, failed=verdict)

        (alone, _), (median, p90) = _interleaved_ms(
            lambda p=plan: verify_plan(p, contract, state, timeout_ms=10_000), both)
        edits = ", ".join(e.kind for e in repair.edits) if proved else f"NONE: {repair.reason}"
        table.add_row(str(length), f"{alone:.1f}", f"{median:.1f}", f"{p90:.1f}", edits,
                      f"<= {TARGET_MS:.0f}" if length == 50 else "")
        if length == 50:
            console.print(f"failing 50-step plan with its repair: median {median:.1f} ms, "
                          + ("target met" if median <= TARGET_MS else "TARGET MISSED"))
    console.print(table)
    return fine


def main() -> int:
    state, contract = build_state(), build_contract()
    assert len(contract) == 30
    console = Console()
    table = Table(title="Static plan verification (Z3): 30-condition contract with a task "
                        "scope, unknown facts")
    for column in ("steps", "median ms", "p90 ms", "µs per step", "Z3 calls", "target"):
        table.add_column(column)
    medians: dict[int, float] = {}
    for length in LENGTHS:
        plan = build_plan(length)
        result = verify_plan(plan, contract, state, timeout_ms=10_000)  # warm-up, and a check
        if not result.ok:
            console.print(f"the {length}-step plan fails: {result.reason}; fix the benchmark")
            return 1
        timings = []
        for _ in range(SAMPLES):
            start = time.perf_counter()
            verify_plan(plan, contract, state, timeout_ms=10_000)
            timings.append((time.perf_counter() - start) * 1000)
        timings.sort()
        medians[length] = statistics.median(timings)
        table.add_row(str(length), f"{medians[length]:.1f}",
                      f"{timings[int(0.9 * (len(timings) - 1))]:.1f}",
                      f"{medians[length] / length * 1000:.0f}", str(result.solver_calls),
                      f"<= {TARGET_MS:.0f}" if length == 50 else "")
    console.print(table)
    # Linear growth: the marginal cost of a step is the same for short and long plans (the
    # per-step average falls with length because of the fixed start-up cost).
    short = (medians[50] - medians[10]) / 40 * 1000
    long = (medians[200] - medians[50]) / 150 * 1000
    console.print(f"marginal cost per step: {short:.0f} µs (10->50 steps), {long:.0f} µs "
                  f"(50->200 steps), ratio x{long / short:.2f} (about 1 = linear); "
                  f"state: 3 people, {len(state.objects)} objects, 3 rooms; "
                  f"Python {sys.version.split()[0]}")
    met = medians[50] <= TARGET_MS
    console.print("target met" if met else "TARGET MISSED (50-step median above 50 ms)")
    repaired = failing_table(state, contract, console)
    console.print("failing plans: every repair found and proved again" if repaired
                  else "FAILING PLANS: a repair is missing or does not pass Stage 5 again")
    return 0 if repaired else 1


if __name__ == "__main__":
    raise SystemExit(main())
