"""With Z3, a template's conditions mean something a robot can live with.

In: a template and its parsed conditions; every fact is unknown (`encode_symbolic`), so each check
asks "is there any state in which ...?". Out: errors for invariants that contradict each other
(with a minimal conflicting set), a guard no state satisfies or that cannot pass while the
invariants hold (it would refuse every such action), an abort that always fires (valid, or implied
by the invariants: it would halt every task), and a solver `unknown` (fail closed: what cannot be
established is refused); warnings for conditions that are always true or aborts that can never
fire. `class_conflict` checks a template against the other active templates of its class, which
binding applies together. Fails: never (encoding errors become issues).
"""

from __future__ import annotations

from collections.abc import Sequence

from app.domain.errors import FormulaError
from app.domain.formula import parse
from app.domain.models import ConditionKind, HazardTemplate
from app.domain.smt import Encoding, Outcome, Satisfiability, encode_symbolic, prove, satisfiable
from app.domain.template_validation.conditions import ParsedCondition, variable_types
from app.domain.template_validation.issues import BODY, TemplateIssue


def _defaults(template: HazardTemplate) -> dict[str, object]:
    return {v.name: v.default for v in template.variables if v.default is not None}


def _encode(template: HazardTemplate, parsed: ParsedCondition) -> Encoding:
    return encode_symbolic(parsed.formula, variable_types(template), defaults=_defaults(template))


def _at(parsed: ParsedCondition, message: str, code: str) -> TemplateIssue:
    # A semantic problem concerns the whole condition: point at its start.
    return TemplateIssue(parsed.field, f"{parsed.kind.value} {parsed.condition.id!r} {message}",
                         code, line=1, column=1)


def _unknown(parsed: ParsedCondition, what: str, detail: str) -> TemplateIssue:
    return _at(parsed, f"could not be checked ({what}): the solver gave up ({detail}); "
               "simplify it", "solver_unknown")


def _minimal_conflict(
    invariants: list[tuple[ParsedCondition, Encoding]], timeout_ms: int
) -> list[ParsedCondition]:
    """Drop invariants one by one while the rest stays contradictory."""
    core = list(invariants)
    for item in list(core):
        trial = [entry for entry in core if entry is not item]
        if trial and satisfiable([e for _, e in trial], timeout_ms).outcome is (
            Satisfiability.UNSAT
        ):
            core = trial
    return [parsed for parsed, _ in core]


def _invariant_issues(
    invariants: list[tuple[ParsedCondition, Encoding]], timeout_ms: int
) -> tuple[list[TemplateIssue], list[TemplateIssue]]:
    errors: list[TemplateIssue] = []
    warnings: list[TemplateIssue] = []
    if not invariants:
        return errors, warnings
    joint = satisfiable([e for _, e in invariants], timeout_ms)
    if joint.outcome is Satisfiability.UNSAT:
        core = _minimal_conflict(invariants, timeout_ms)
        if len(core) == 1:
            errors.append(_at(core[0], "is contradictory: no state satisfies it", "contradiction"))
        else:
            names = ", ".join(repr(p.condition.id) for p in core)
            errors.append(_at(core[0], f"contradicts {names.split(', ', 1)[1]}: no state "
                              f"satisfies invariants {names} together", "contradiction"))
    elif joint.outcome is Satisfiability.UNKNOWN:
        errors.append(_unknown(invariants[0][0], "joint satisfiability", joint.detail))
    for parsed, encoding in invariants:
        if prove(encoding, timeout_ms).outcome is Outcome.HOLDS:
            warnings.append(_at(parsed, "is always true: it constrains nothing", "always_true"))
    return errors, warnings


def _guard_issues(
    parsed: ParsedCondition, encoding: Encoding, invariants: list[Encoding], timeout_ms: int
) -> tuple[list[TemplateIssue], list[TemplateIssue]]:
    action = parsed.condition.action
    alone = satisfiable(encoding, timeout_ms)
    if alone.outcome is Satisfiability.UNSAT:
        return [_at(parsed, f"is never satisfiable: it would refuse every {action}",
                    "unsatisfiable_guard")], []
    if alone.outcome is Satisfiability.UNKNOWN:
        return [_unknown(parsed, "satisfiability", alone.detail)], []
    with_invariants = satisfiable([*invariants, encoding], timeout_ms)
    if with_invariants.outcome is Satisfiability.UNSAT:
        return [_at(parsed, f"can never pass while the invariants hold: it would refuse every "
                    f"{action}", "unsatisfiable_guard")], []
    if with_invariants.outcome is Satisfiability.UNKNOWN:
        return [_unknown(parsed, "satisfiability with the invariants", with_invariants.detail)], []
    if prove(encoding, timeout_ms).outcome is Outcome.HOLDS:
        return [], [_at(parsed, "is always true: it guards nothing", "always_true")]
    return [], []


def _abort_issues(
    parsed: ParsedCondition, encoding: Encoding, invariants: list[Encoding], timeout_ms: int
) -> tuple[list[TemplateIssue], list[TemplateIssue]]:
    always = prove(encoding, timeout_ms)
    if always.outcome is Outcome.HOLDS:
        return [_at(parsed, "is always true: it would halt every task at once",
                    "valid_abort")], []
    if always.outcome is Outcome.UNKNOWN:
        return [_unknown(parsed, "validity", always.detail)], []
    if invariants:
        implied = prove(encoding, timeout_ms, assumptions=invariants)
        if implied.outcome is Outcome.HOLDS:
            return [_at(parsed, "follows from the invariants: since they hold in every state, "
                        "it would halt every task at once", "valid_abort")], []
        if implied.outcome is Outcome.UNKNOWN:
            return [_unknown(parsed, "validity under the invariants", implied.detail)], []
    fires = satisfiable([*invariants, encoding], timeout_ms)
    if fires.outcome is Satisfiability.UNSAT:
        return [], [_at(parsed, "can never fire while the invariants hold", "never_fires")]
    return [], []


def meaning_issues(
    template: HazardTemplate, parsed: Sequence[ParsedCondition], timeout_ms: int
) -> tuple[list[TemplateIssue], list[TemplateIssue]]:
    """Check, with Z3, that the well-formed conditions of a template make sense together.

    Args:
        template: the template.
        parsed: its conditions, all of which parsed and type-checked.
        timeout_ms: the solver's budget per check.

    Returns:
        Errors and warnings.
    """
    errors: list[TemplateIssue] = []
    warnings: list[TemplateIssue] = []
    encoded: list[tuple[ParsedCondition, Encoding]] = []
    for item in parsed:
        try:
            encoded.append((item, _encode(template, item)))
        except (FormulaError, ValueError) as error:
            errors.append(TemplateIssue(item.field, f"cannot be encoded for Z3: {error}",
                                        "encoding", line=1, column=1))
    if errors:
        return errors, warnings
    invariants = [(p, e) for p, e in encoded if p.kind is ConditionKind.INVARIANT]
    found, noted = _invariant_issues(invariants, timeout_ms)
    errors += found
    warnings += noted
    if found:
        return errors, warnings  # guards and aborts are judged against consistent invariants
    invariant_claims = [e for _, e in invariants]
    for item, encoding in encoded:
        if item.kind is ConditionKind.GUARD:
            found, noted = _guard_issues(item, encoding, invariant_claims, timeout_ms)
        elif item.kind is ConditionKind.ABORT:
            found, noted = _abort_issues(item, encoding, invariant_claims, timeout_ms)
        else:
            continue
        errors += found
        warnings += noted
    return errors, warnings


def _invariant_claims(template: HazardTemplate) -> list[Encoding]:
    variables = variable_types(template)
    return [
        encode_symbolic(parse(c.formula), variables, defaults=_defaults(template))
        for c in template.invariants
    ]


def class_conflict(
    template: HazardTemplate, others: Sequence[HazardTemplate], timeout_ms: int
) -> TemplateIssue | None:
    """Whether the template's invariants contradict those of the other templates of its class.

    Binding applies every template of a class together, so a contradiction would make every
    contract for that class unsatisfiable.

    Args:
        template: the template to add or activate.
        others: the other active templates of the same hazard class.
        timeout_ms: the solver's budget.

    Returns:
        An issue naming the conflicting templates (also when the solver gives up), or None.
    """
    if not template.invariants or not others:
        return None
    try:
        own = _invariant_claims(template)
        theirs = [claim for other in others for claim in _invariant_claims(other)]
    except (FormulaError, ValueError) as error:
        return TemplateIssue(f"{BODY}.invariants", f"cannot be encoded for Z3: {error}",
                             "encoding")
    if not theirs:
        return None
    result = satisfiable([*own, *theirs], timeout_ms)
    if result.outcome is Satisfiability.SAT:
        return None
    names = ", ".join(other.id for other in others)
    verdict = ("contradict" if result.outcome is Satisfiability.UNSAT
               else "could not be shown compatible with")
    return TemplateIssue(
        f"{BODY}.invariants",
        f"the invariants {verdict} those of the active templates of class "
        f"{template.hazard_class!r} ({names}); binding applies them together, so every "
        "contract for this class would be unsatisfiable", "class_conflict")
