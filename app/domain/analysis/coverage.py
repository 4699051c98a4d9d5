"""Library coverage: a hazard class the task puts in play but no active template speaks for.

In: the simulated traces, the `Focus`, and the active library. Out: unbound `HazardProposal`s,
one per class in `knowledge/in_play.yaml` whose cue a trace makes true (for an object the plan
touches) while the library holds no template of that class. The judge can only find what the
library's conditions describe; without this, a curator deleting the blade templates would make
every knife task pass unexamined. With it the gate defers and asks for the library to be
extended (R2), which is the paper's loop. Classes the library covers are left to their templates.
Fails: never; a cue that does not compile is a defect of the knowledge file, caught by its test.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cache

from app.domain.analysis.judge import Focus
from app.domain.analysis.lexicon import KNOWLEDGE_DIR
from app.domain.analysis.simulate import Trace
from app.domain.formula import ActionArg, CompiledFormula, compile_formula, parse, substitute
from app.domain.models import (
    Category,
    Confidence,
    HazardProposal,
    HazardTemplate,
    Level,
    Preventability,
    Severity,
)

_VARIABLES = {"obj": "object", "person": "person"}


@dataclass(frozen=True, slots=True)
class Cue:
    """What puts one hazard class in play."""

    hazard_class: str
    category: Category
    words: str
    compiled: CompiledFormula
    uses_person: bool


@cache
def cues() -> tuple[Cue, ...]:
    """The cues of `knowledge/in_play.yaml`, compiled once per process."""
    import yaml

    raw = yaml.safe_load((KNOWLEDGE_DIR / "in_play.yaml").read_text())["classes"]
    bindings: dict[str, object] = {name: ActionArg(f"${name}") for name in _VARIABLES}
    compiled = []
    for hazard_class, row in raw.items():
        formula = substitute(parse(row["when"]), bindings, variables=_VARIABLES)
        compiled.append(Cue(hazard_class, Category(row["category"]), row["when"],
                            compile_formula(formula), "$person" in row["when"]))
    return tuple(compiled)


def uncovered(traces: Sequence[Trace], focus: Focus,
              library: Iterable[HazardTemplate]) -> list[HazardProposal]:
    """The unbound hazards of classes the task puts in play and the library does not cover.

    Args:
        traces: the simulated variants of the plan.
        focus: the objects the plan touches and the people present.
        library: the active templates (any analysis use counts as covering its class).

    Returns:
        One proposal per uncovered class in play, naming the entities that put it there.
    """
    covered = {t.hazard_class for t in library}
    found: list[HazardProposal] = []
    for cue in cues():
        if cue.hazard_class in covered:
            continue
        entities = _first_in_play(cue, traces, focus)
        if entities is None:
            continue
        named = ", ".join(entities.values())
        found.append(HazardProposal(
            level=Level.TASK, category=cue.category, hazard_class=cue.hazard_class,
            mechanism=(f"the plan puts {cue.hazard_class} in play ({cue.words}, for {named}) "
                       "and the library holds no template of that class"),
            entities=entities, severity=Severity.MODERATE,
            preventability=Preventability.UNKNOWN, confidence=Confidence.CERTAIN,
            source="symbolic"))
    return found


def _first_in_play(cue: Cue, traces: Sequence[Trace], focus: Focus) -> dict[str, str] | None:
    people: tuple[str | None, ...] = focus.people if cue.uses_person else (None,)
    for obj, person in itertools.product(focus.objects, people):
        args: dict[str, str | None] = {"$obj": obj, "$person": person}
        for trace in traces:
            if cue.compiled(trace.states[0], args) is True:
                continue  # so before the task began: not the task's doing
            if any(cue.compiled(state, args) is True for state in trace.states[1:]):
                return {"obj": obj} | ({"person": person} if person else {})
    return None
