"""From findings to the Hazard Analysis Matrix: preventable, unpreventable, unknown.

In: the judge's `Finding`s, the traces, the `Focus` and the gate's theta. Out: hazard proposals
and unknown facts. The variant with the least severe set of violations (careful ones first on a
tie) is the best a planner can do: what it still violates cannot be prevented by any contract
(unpreventable); what only other variants violate is preventable, and the contract will forbid
those variants.
A condition the best variant leaves undecided because of a fact about something the task itself
involves (what is in the cup it hands over, how old the guest it serves is) is confirmed with Z3
on the symbolic state: if some value of the unknown facts breaks it, each such fact becomes a
critical unknown with a question. Unknowns about the robot's own motion (speed, distance) are the
contract's to bound, not questions. Severity and category always come from the template.
Fails: never; a Z3 `unknown` keeps the question (fail closed).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from app.domain.analysis.judge import Finding, Focus
from app.domain.analysis.questions import display, parse_key, unknown_fact
from app.domain.analysis.simulate import Trace
from app.domain.errors import FormulaError
from app.domain.formula import EntityRef, check, parse, substitute
from app.domain.formula.facts import FactValue, Unknown
from app.domain.models import (
    Category,
    ConditionKind,
    Confidence,
    HazardProposal,
    Level,
    Preventability,
    Severity,
    UnknownFact,
    VariableType,
)
from app.domain.smt import Outcome
from app.domain.smt.trace import TraceProver
from app.domain.world import WorldState

# Facts a plan chooses (how fast, how close): the contract bounds them, nobody is asked.
_PLAN_FACTS = frozenset({"speed", "max_speed", "distance", "near"})
# The robot's capabilities, and what it senses when it lifts a thing: checked by the contract
# at run time, not asked.
_ROBOT_FACTS = frozenset({"payload", "load_kg", "has_skill", "has_sensor", "recording",
                          "mass_kg", "heavy", "pickupable"})
# Where a person is, when a severe hazard turns on it: asked even of someone the command
# does not name.
_WHEREABOUTS = frozenset({"outdoors"})
SOLVER_BUDGET_MS = 500


@dataclass
class Matrix:
    """The filled matrix for one command."""

    proposals: list[HazardProposal]
    unknowns: list[UnknownFact]


class _Recorder:
    """A state that remembers the unknown facts a condition reads."""

    def __init__(self, inner: WorldState) -> None:
        self.inner = inner
        self.unknown: list[str] = []

    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        found = self.inner.value(symbol, args)
        if isinstance(found, Unknown) and found.key not in self.unknown:
            self.unknown.append(found.key)
        return found

    def domain(self, type_name: str) -> Sequence[str]:
        return self.inner.domain(type_name)

    def entity_type(self, entity_id: str) -> str | None:
        return self.inner.entity_type(entity_id)


def _severity_rank(findings: Sequence[Finding], theta: Severity) -> tuple[int, int, int]:
    """How bad a variant is: its worst violation, then how many, then its severe open
    questions (a variant that needs no answer beats one that does)."""
    violated = [f for f in findings if f.violated]
    open_severe = sum(1 for f in findings if not f.violated
                      and f.template.severity.rank >= theta.rank)
    return (max((f.template.severity.rank for f in violated), default=-1), len(violated),
            open_severe)


def _describe(finding: Finding) -> str:
    planned = finding.step
    state = finding.trace.states[max(finding.state_index - 1, 0)]
    if planned is None:
        where = "from the start"
    elif planned.action.name == "Finish":
        where = "at the end of the task"
    else:
        action = planned.action
        parts = [display(state, a) for a in (action.object, action.target) if a]
        where = f"at {action.name}({', '.join(parts)})"
    verb = "breaks" if finding.violated else "may break"
    cond = finding.condition.condition
    return (f"{finding.template.name}: {where} the plan {verb} '{cond.description}' "
            f"[template {finding.template.id}, {finding.condition.kind.value} {cond.id}, "
            f"{finding.trace.variant.label}]")


def _level(finding: Finding, user: str, state: WorldState) -> Level:
    ids = [v for _, v in finding.binding]
    if any(i == user for i in ids) or finding.template.category is Category.OPERATIONAL:
        return Level.USER
    if any(not i.startswith("new_") for i in ids):
        return Level.DEPLOYMENT
    return Level.TASK


def _proposal(finding: Finding, preventability: Preventability, user: str) -> HazardProposal:
    # Uncertain only where the analysis could not tell whether the hazard can be prevented;
    # a contract condition that may not hold is certain to be needed.
    template = finding.template
    state = finding.trace.states[0]
    entities = {k: v for k, v in finding.binding}
    return HazardProposal(
        level=_level(finding, user, state), category=template.category,
        hazard_class=template.hazard_class, mechanism=_describe(finding), entities=entities,
        severity=template.severity, preventability=preventability,
        confidence=Confidence.UNCERTAIN if preventability is Preventability.UNKNOWN
        else Confidence.CERTAIN,
        source="symbolic", template_id=template.id)


def _unknown_keys(finding: Finding) -> list[str]:
    state = finding.trace.states[finding.state_index]
    recorder = _Recorder(state)
    finding.condition.compiled(recorder, finding.args())
    return recorder.unknown


def _asked(key: str, focus: Focus) -> bool:
    symbol, args = parse_key(key)
    if symbol in _PLAN_FACTS or symbol in _ROBOT_FACTS or "robot" in args:
        return False
    if symbol in _WHEREABOUTS and set(args) & set(focus.people):
        return True  # "is Grandad still out in the garden?": where someone is, worth asking
    return bool(set(args) & focus.named)


def _solver_confirms(finding: Finding) -> bool:
    """Whether some value of the unknown facts breaks the condition (Z3); True if Z3 cannot
    tell (fail closed)."""
    template = finding.template
    types = {v.name: v.type.value for v in template.variables}
    bindings: dict[str, object] = {v.name: v.default for v in template.variables
                                   if v.default is not None}
    bindings.update({k: EntityRef(v) for k, v in finding.binding})
    bindings.update({v.name: EntityRef("robot") for v in template.variables
                     if v.type is VariableType.ROBOT})
    condition = finding.condition
    try:
        formula = substitute(parse(condition.condition.formula), bindings, variables=types)
        check(formula, {}, allow_action_args=condition.kind is ConditionKind.GUARD)
    except FormulaError:
        return True
    args = finding.step.action.args if finding.step is not None and \
        condition.kind is ConditionKind.GUARD else None
    proof = TraceProver(SOLVER_BUDGET_MS).prove(
        (template.id, condition.condition.id, finding.binding), formula,
        finding.trace.states[finding.state_index], args,
        must_hold=condition.kind is not ConditionKind.ABORT)
    return proof.outcome is not Outcome.HOLDS


def aggregate(findings: Sequence[Finding], traces: Sequence[Trace], focus: Focus,
              theta: Severity, user: str) -> Matrix:
    """Preventable and unpreventable hazards, and the unknowns that decide (module docstring).

    Args:
        findings: every finding on every trace.
        traces: the traces judged.
        focus: what the plan involves and what the command names.
        theta: the gate's severity threshold (a lower hazard's unknowns are not critical).
        user: the id of the person giving the command.

    Returns:
        The proposals (one per template and binding) and the unknown facts.
    """
    per_trace = {id(t): [f for f in findings if f.trace is t] for t in traces}
    # Careful variants first, so a tie goes to the careful way of doing the task.
    ordered = sorted(traces, key=lambda t: not t.careful)
    best = min(ordered, key=lambda t: _severity_rank(per_trace[id(t)], theta))
    best_findings = per_trace[id(best)]
    unpreventable = {f.key: f for f in best_findings if f.violated}
    proposals = [_proposal(f, Preventability.UNPREVENTABLE, user)
                 for f in unpreventable.values()]
    unknowns: list[UnknownFact] = []
    asked: set[str] = set()
    seen = set(unpreventable)
    for finding in best_findings:
        if finding.violated or finding.key in seen:
            continue
        seen.add(finding.key)
        severe = finding.template.severity.rank >= theta.rank
        keys = [k for k in _unknown_keys(finding) if _asked(k, focus)]
        if keys and severe and _solver_confirms(finding):
            why = (f"whether {finding.template.name.lower()} depends on it "
                   f"({finding.template.id}: {finding.condition.condition.description})")
            for key in keys:
                if key not in asked:
                    asked.add(key)
                    unknowns.append(unknown_fact(key, finding.trace.states[0], why,
                                                 critical=True))
            proposals.append(_proposal(finding, Preventability.UNKNOWN, user))
        else:
            proposals.append(_proposal(finding, Preventability.PREVENTABLE, user))
    for finding in findings:
        if finding.key not in seen:
            seen.add(finding.key)
            proposals.append(_proposal(finding, Preventability.PREVENTABLE, user))
    return Matrix(proposals, unknowns)
