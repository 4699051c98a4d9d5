"""Plans to measure reference planning and repair on: authorized cases and plans written to fail.

In: a case file (`bench/cases/*.jsonl`). Out: `authorized(path)`: each case the gate authorizes
(Stages 1-4 in process with the seed library and the symbolic analyzer, as `POST /gate` runs
them) with its contract; `mutants(plan, state, contract)`: plans written to fail from a good
plan, each by one rule that breaks what contracts commonly forbid, never by looking at the
contract's conditions:
- `top_speed`: every move at the robot's top speed (the speed arguments removed);
- `throw`: the first put or hand-over replaced by throwing the thing at its target;
- `left_on`: a heat source or appliance switched on at the start and left running;
- `carried_off`: something the task does not name picked up first and never put down;
- `swapped`: the first two steps that differ exchanged.
Fails: `BenchmarkError`/`ValidationError` on a malformed case file.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract
from app.domain.gate import Decision
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.domain.world import WorldState
from app.store.seed import load_library
from bench.score import load_cases

ROOT = Path(__file__).resolve().parent.parent
BENCHMARK = ROOT / "bench" / "cases" / "benchmark.jsonl"
TEMPLATES = ROOT / "templates_db"
SOLVER_TIMEOUT_MS = 2000
Step = Mapping[str, Any]
_APPLIANCES = ("StoveBurner", "StoveKnob", "Microwave", "Toaster", "CoffeeMachine", "Faucet",
               "Television", "Laptop", "DeskLamp", "FloorLamp")


@dataclass(frozen=True)
class Authorized:
    """An authorized case with its contract."""

    case_id: str
    request: GateRequest
    contract: Contract


def authorized(path: Path, analyzer: SymbolicAnalyzer, *, limit: int | None = None
               ) -> Iterator[Authorized]:
    """Every case of the file (or of its first `limit` cases) that the gate authorizes, with
    its contract."""
    templates = TemplateIndex(load_library(TEMPLATES))
    for case in load_cases(path)[:limit]:
        result = run_gate(case.request, templates=templates, analyzer=analyzer)
        if result.decision.decision is Decision.AUTHORIZE and result.contract is not None:
            yield Authorized(case.id, case.request, result.contract)


def _top_speed(plan: Sequence[Step], state: WorldState) -> list[Step] | None:
    moved = [{k: v for k, v in s.items() if k != "speed"} for s in plan]
    return moved if moved != [dict(s) for s in plan] else None


def _throw(plan: Sequence[Step], state: WorldState) -> list[Step] | None:
    for index, step in enumerate(plan):
        if step.get("action") in ("PutObject", "HandOver"):
            thrown = {"action": "ThrowObject", "object": step["object"],
                      "target": step["target"]}
            return [*plan[:index], thrown, *plan[index + 1:]]
    return None


def _left_on(plan: Sequence[Step], state: WorldState) -> list[Step] | None:
    for obj in sorted(state.objects.values(), key=lambda o: o.id):
        if obj.type in _APPLIANCES and state.value("is_on", (obj.id,)) is False:
            return [{"action": "GoToObject", "object": obj.id},
                    {"action": "ToggleObjectOn", "object": obj.id}, *plan]
    return None


def _carried_off(plan: Sequence[Step], state: WorldState, contract: Contract
                 ) -> list[Step] | None:
    named = set(contract.scope.objects()) if contract.scope is not None else set()
    named |= {str(s.get("object")) for s in plan}
    for obj in sorted(state.objects.values(), key=lambda o: o.id):
        if obj.id not in named and obj.kind.flag("pickupable") is True and obj.parent:
            return [{"action": "GoToObject", "object": obj.id},
                    {"action": "PickupObject", "object": obj.id}, *plan]
    return None


def _swapped(plan: Sequence[Step], state: WorldState) -> list[Step] | None:
    for index in range(len(plan) - 1):
        if plan[index] != plan[index + 1]:
            return [*plan[:index], plan[index + 1], plan[index], *plan[index + 2:]]
    return None


def mutants(plan: Sequence[Step], state: WorldState, contract: Contract
            ) -> Iterator[tuple[str, list[Step]]]:
    """The plans written to fail from one good plan, by rule (rules that do not apply are
    skipped; whether a mutant does fail is for Stage 5 to say)."""
    made = {"top_speed": _top_speed(plan, state), "throw": _throw(plan, state),
            "left_on": _left_on(plan, state),
            "carried_off": _carried_off(plan, state, contract),
            "swapped": _swapped(plan, state)}
    for rule, mutant in made.items():
        if mutant is not None:
            yield rule, mutant
