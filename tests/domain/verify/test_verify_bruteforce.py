"""Property: on small states, Z3's verdict equals brute force over every value of the unknowns.

The reference below shares nothing with the verifier but the action model: for each assignment
of the unknown object flags it builds a fully known state, runs the plan step by step and checks
each condition with the evaluator (which is then two-valued). The plan is safe iff it passes
under every assignment; the verifier must say exactly that, and when it fails, its counterexample
must pick out assignments under which the reference fails too.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from verify_kit import KITCHEN, contract

from app.domain.contracts import Contract
from app.domain.errors import PlanError
from app.domain.formula import CompiledFormula, Unknown, check, compile_formula, parse
from app.domain.models import GateRequest
from app.domain.verify import verify_plan
from app.domain.world import WorldState, evaluate_preconditions, parse_action, state_from_request
from app.domain.world import step as apply_step

FLAGS = ("lidded", "fragile", "toxic", "sharp", "breakable")
ITEMS = ("vase_1", "box_1")
INVARIANTS = (
    "holding(robot, #vase_1) -> lidded(#vase_1)",
    "not (holding(robot, #box_1) and toxic(#box_1))",
    "broken(#vase_1) -> not sharp(#vase_1)",
    "forall o: object . holding(robot, o) -> not sharp(o) or lidded(o)",
)
GUARDS = (
    ("PickupObject", "@object != #vase_1 or not fragile(#vase_1)"),
    ("DropHandObject", "not breakable(@object)"),
    ("PutObject", "not toxic(@object) or @target != #table_1"),
    ("HandOver", "not sharp(@object)"),
    ("ThrowObject", "not (fragile(@object) or breakable(@object))"),
)
ABORTS = (
    "broken(#vase_1) and same_room(robot, #ann)",
    "holding(#ann, #box_1) and toxic(#box_1)",
)
STEPS: tuple[dict[str, Any], ...] = (
    *({"action": "GoToObject", "object": o} for o in (*ITEMS, "table_1", "ann")),
    *({"action": "PickupObject", "object": o} for o in ITEMS),
    *({"action": "PutObject", "object": o, "target": t}
      for o in ITEMS for t in ("table_1", "counter_1")),
    *({"action": "HandOver", "object": o, "target": "ann"} for o in ITEMS),
    {"action": "DropHandObject"}, {"action": "ThrowObject"}, {"action": "Wait"},
)
Flags = Mapping[tuple[str, str], bool | None]


def scene_state(flags: Flags) -> WorldState:
    """The kitchen with two flag-bearing widgets; a None flag is left unknown."""
    scene = {**KITCHEN, "objects": [
        *KITCHEN["objects"][:2],
        *({"id": item, "type": "Widget", "on": "counter_1",
           "properties": {"pickupable": True, "broken": False, "filled": False, "contents": "",
                          **{flag: value for (i, flag), value in flags.items()
                             if i == item and value is not None}}}
          for item in ITEMS)]}
    request = {"command": "test", "scene": scene, "robot": {"room": "kitchen"}}
    return state_from_request(GateRequest.model_validate(request))


def _holds(formula: CompiledFormula, state: WorldState, args: Any = None) -> bool:
    return formula(state, args) is True


def reference_ok(plan: Sequence[dict[str, Any]], rules: Contract, state: WorldState) -> bool:
    """Run the plan in a fully known state; fail closed on anything not definitely fine."""
    def compiled(text: str, guard: bool = False) -> CompiledFormula:
        formula = parse(text)
        check(formula, {}, allow_action_args=guard)
        return compile_formula(formula)

    invariants = [compiled(c.formula) for c in rules.invariants]
    aborts = [compiled(c.formula) for c in rules.aborts]
    guards = [(c.action, compiled(c.formula, True)) for c in rules.guards]

    def state_ok(s: WorldState) -> bool:
        return (all(_holds(f, s) for f in invariants)
                and all(f(s) is False for f in aborts))

    if not state_ok(state):
        return False
    for index, raw in enumerate(plan):
        try:
            action = parse_action(raw, step=index, state=state)
        except PlanError:
            return False  # only the empty-handed SMART-LLM form can get here
        if not all(_holds(f, state, action.args) for name, f in guards if name == action.name):
            return False
        if not all(r.holds is True for r in evaluate_preconditions(state, action)):
            return False
        state = apply_step(state, action)
        if not state_ok(state):
            return False
    return True


def assignments(unknown: Sequence[tuple[str, str]], known: Flags) -> list[dict[tuple[str, str],
                                                                               bool | None]]:
    return [{**known, **dict(zip(unknown, values, strict=True))}
            for values in itertools.product((False, True), repeat=len(unknown))]


@st.composite
def cases(draw: st.DrawFn) -> tuple[Flags, list[dict[str, Any]], Contract]:
    flags = {(item, flag): draw(st.sampled_from((None, None, True, False)))
             for item in ITEMS for flag in FLAGS}
    for key in [k for k, v in flags.items() if v is None][5:]:
        flags[key] = draw(st.booleans())  # at most five unknowns: 32 worlds to enumerate
    plan = draw(st.lists(st.sampled_from(STEPS), max_size=5))
    rules = contract(
        invariants=tuple(draw(st.lists(st.sampled_from(INVARIANTS), max_size=2, unique=True))),
        guards=tuple(draw(st.lists(st.sampled_from(GUARDS), max_size=3, unique=True))),
        aborts=tuple(draw(st.lists(st.sampled_from(ABORTS), max_size=1))))
    return flags, plan, rules


class TestZ3AgreesWithBruteForce:
    @settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(cases())
    def test_verdict_equals_enumeration_over_the_unknowns(
        self, case: tuple[Flags, list[dict[str, Any]], Contract]
    ) -> None:
        flags, plan, rules = case
        start = scene_state(flags)
        # A flag left out may still be decided by the world (no contents: not toxic).
        unknown = [(item, flag) for (item, flag), value in flags.items()
                   if value is None and isinstance(start.value(flag, (item,)), Unknown)]
        worlds = assignments(unknown, flags)
        failing = [w for w in worlds if not reference_ok(plan, rules, scene_state(w))]
        result = verify_plan(plan, rules, start, timeout_ms=10_000)
        assert result.undecided == ()
        assert result.ok == (not failing), (result, failing)
        if result.violations:
            chosen = result.violations[0].counterexample
            named = {(i, f): chosen[f"{f}({i})"] for i, f in unknown if f"{f}({i})" in chosen}
            matching = [w for w in failing if all(w[k] == v for k, v in named.items())]
            assert matching, (result.violations[0], failing)
