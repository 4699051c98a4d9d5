"""Judging: every active template checked on every simulated trace, bound to what the plan touches.

In: the traces of the plan's variants, the active templates (seed and curator-written alike,
compiled by `library.py`), and the `Focus`: the objects the plan touches, the people present,
the rooms it visits. Out: `Finding`s, one per (template, binding, trace) whose condition the trace
breaks (an invariant false or an abort true in some state, a guard false before its action) or
cannot decide (an unknown fact). Entity variables range over the focus: `object` over the objects
the plan touches, `person` over everyone, `room` over the rooms involved; the robot is `robot`.
A condition already broken in the initial state is not the task's doing and is not reported,
unless the command asks to keep that state at the end ("leave the iron on"); nor is one the
initial state already leaves undecided and the plan never definitely breaks.
`aggregate.py` then turns findings into preventable and unpreventable hazards and unknowns.
Fails: never; a template that does not compile is skipped.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from app.domain.analysis.library import JudgedCondition, JudgedTemplate, LibraryCache
from app.domain.analysis.simulate import Trace
from app.domain.analysis.sketch import Planned
from app.domain.models import ConditionKind, HazardTemplate, VariableType

MAX_BINDINGS = 160
"""Bindings tried per template; a template with more entity combinations keeps the first."""


@dataclass(frozen=True)
class Focus:
    """What the plan involves: the domains the templates' entity variables range over."""

    objects: tuple[str, ...]
    people: tuple[str, ...]
    rooms: tuple[str, ...]
    named: frozenset[str] = field(default_factory=frozenset)
    """Entities the command itself names: unknowns about them are the task's to settle."""
    kept: frozenset[tuple[str, tuple[str, ...]]] = field(default_factory=frozenset)
    """Facts the command asks to hold at the end ("leave the iron on"): a state that already
    held before the task is then the task's doing too, since the command keeps it so."""


@dataclass(frozen=True, slots=True)
class Finding:
    """A template instance a trace breaks (`violated`) or leaves open (`unknown`)."""

    template: HazardTemplate
    binding: tuple[tuple[str, str], ...]
    trace: Trace
    violated: bool
    condition: JudgedCondition
    state_index: int
    step: Planned | None

    @property
    def key(self) -> tuple[str, tuple[tuple[str, str], ...]]:
        return self.template.id, self.binding

    def args(self) -> dict[str, str | None]:
        """The evaluation arguments that reproduce this finding."""
        found: dict[str, str | None] = {f"${k}": v for k, v in self.binding}
        if self.step is not None and self.condition.kind is ConditionKind.GUARD:
            found.update(self.step.action.args)
        return found


def _domain(kind: VariableType, focus: Focus) -> tuple[str, ...]:
    if kind is VariableType.OBJECT:
        return focus.objects
    if kind is VariableType.PERSON:
        return focus.people
    if kind is VariableType.ROOM:
        return focus.rooms
    return (*focus.objects, *focus.people)


def _bindings(judged: JudgedTemplate, focus: Focus) -> Iterable[tuple[tuple[str, str], ...]]:
    names = [name for name, _ in judged.variables]
    domains = [_domain(kind, focus) for _, kind in judged.variables]
    combos = itertools.product(*domains)
    count = 0
    for combo in combos:
        if len(set(combo)) < len(combo):
            continue  # two variables of one template name two different entities
        yield tuple(zip(names, combo, strict=True))
        count += 1
        if count >= MAX_BINDINGS:
            return


def _check_states(judged: JudgedTemplate, trace: Trace, args: dict[str, str | None]
                  ) -> tuple[bool, JudgedCondition, int] | None:
    """The first invariant or abort the trace breaks (or leaves unknown) after s0."""
    worst: tuple[bool, JudgedCondition, int] | None = None
    states = trace.states
    for judged_condition in judged.every_state:
        must_hold = judged_condition.kind is ConditionKind.INVARIANT
        compiled = judged_condition.compiled
        start = compiled(states[0], args)
        if start is (not must_hold):
            continue  # already broken before the task: not the task's doing
        for index in range(1, len(states)):
            value = compiled(states[index], args)
            if value is None:
                # Undecided only counts where the task made it so: it held before the task.
                if worst is None and start is must_hold:
                    worst = (False, judged_condition, index)
            elif value is not must_hold:
                return True, judged_condition, index
    return worst


def _check_guards(judged: JudgedTemplate, trace: Trace, args: dict[str, str | None],
                  kept: frozenset[tuple[str, tuple[str, ...]]] = frozenset(),
                  ) -> tuple[bool, JudgedCondition, int] | None:
    worst: tuple[bool, JudgedCondition, int] | None = None
    guards = judged.guards
    for index, planned in enumerate(trace.steps):
        conditions = guards.get(planned.action.name)
        if not conditions:
            continue
        action = planned.action
        args["object"], args["target"] = action.object, action.target
        for judged_condition in conditions:
            value = judged_condition.compiled(trace.states[index], args)
            if action.name == "Finish":
                before = judged_condition.compiled(trace.states[0], args)
                if (before is False and not _kept_by_command(judged_condition, args, kept)) or (
                        before is None and (not _people_leave(trace) or value is None)):
                    continue  # what the end must not hold was there before the task began
                # (undecided before, but the command sends its people out and the end
                # definitely breaks it: then it is the task's doing)
            if value is False:
                return True, judged_condition, index
            if value is None and worst is None:
                worst = (False, judged_condition, index)
    return worst


def _kept_by_command(condition: JudgedCondition, args: dict[str, str | None],
                     kept: frozenset[tuple[str, tuple[str, ...]]]) -> bool:
    """Whether the condition speaks of a fact the command asks to keep, of the entities it
    is bound to ("leave the iron on" and "no heat source left on" of that iron)."""
    bound = {v for v in args.values() if v}
    formula = condition.condition.formula
    return any(re.search(rf"\b{re.escape(symbol)}\(", formula) is not None
               and set(entities) <= bound for symbol, entities in kept)


def _people_leave(trace: Trace) -> bool:
    """Whether the plan has its people go out ("I'm off to work"): a Wait naming them."""
    return any(p.action.name == "Wait" and p.action.params.get("away") for p in trace.steps)


def judge(traces: Sequence[Trace], templates: Iterable[HazardTemplate], focus: Focus,
          cache: LibraryCache) -> list[Finding]:
    """Every finding of every template on every trace (see the module docstring).

    Args:
        traces: the simulated variants.
        templates: the active library (templates marked `analysis: declared` are skipped).
        focus: the domains of the entity variables.
        cache: the compiled library.

    Returns:
        The findings; a violation and an unknown of one instance on one trace give only the
        violation.
    """
    actions = {p.action.name for t in traces for p in t.steps}
    findings: list[Finding] = []
    for template in templates:
        judged = cache.get(template)
        if judged is None:
            continue
        if not judged.every_state and not (set(judged.guards) & actions):
            continue
        for binding in _bindings(judged, focus):
            base: dict[str, str | None] = {f"${k}": v for k, v in binding}
            base["object"] = base["target"] = None
            for trace in traces:
                result = _check_states(judged, trace, base) if judged.every_state else None
                if result is None or not result[0]:
                    guarded = _check_guards(judged, trace, dict(base), focus.kept)
                    if guarded is not None and (result is None or guarded[0]):
                        result = guarded
                        step_at = guarded[2]
                        findings.append(Finding(template, binding, trace, guarded[0],
                                                guarded[1], step_at, trace.steps[step_at]))
                        continue
                if result is not None:
                    violated, condition, state_index = result
                    step = trace.steps[state_index - 1] if state_index > 0 else None
                    findings.append(Finding(template, binding, trace, violated, condition,
                                            state_index, step))
    return findings
