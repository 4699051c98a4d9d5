"""Stage 1, the Hazard Analysis Matrix, on the world model: read, simulate, judge.

In: a `GateRequest` and the active Hazard Template Library. Out: a `HazardReport`. How:
1. Read (`reader.py`, `arguments.py`, `schemas.py`, `handlers.py`, `carrying.py`): each clause
   becomes steps of the shared action model on the request's `WorldState`; what cannot be read
   (an unknown verb or noun, a pronoun with nothing to point to, a goal with no task, several
   readings that differ in safety) becomes a critical `comprehension` unknown quoting the words.
2. Simulate (`sketch.py`, `simulate.py`): the literal plan and the variants a planner may choose.
3. Judge (`judge.py`, `aggregate.py`): every active template on every trace; what the best
   careful variant still breaks is unpreventable, what only others break is preventable, and a
   condition that depends on an unknown fact about the task's own entities makes that fact a
   critical unknown with a question.
4. Coverage (`coverage.py`): a hazard class the traces put in play (a blade in hand, something
   flammable heated) with no active template of its class stays unbound, so the gate asks for
   the library to be extended instead of authorizing what nothing judged.
5. Declared rules (`declared.py`) for what no trace shows: intent, covert recording, deception.
Fails: never for a valid request (the pipeline turns any exception into a deferral anyway).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Protocol, runtime_checkable

from app.domain.analysis.aggregate import aggregate
from app.domain.analysis.answers import apply_answers
from app.domain.analysis.coverage import uncovered
from app.domain.analysis.declared import RULES, Declared
from app.domain.analysis.judge import Focus, judge
from app.domain.analysis.lexicon import Lexicon, load_lexicon
from app.domain.analysis.library import LibraryCache, judged_in_analysis
from app.domain.analysis.questions import not_understood
from app.domain.analysis.referents import USER_ID
from app.domain.analysis.simulate import Trace, simulate
from app.domain.analysis.sketch import variants
from app.domain.analysis.understanding import Understanding, understand
from app.domain.models import (
    Category,
    Confidence,
    GateRequest,
    HazardProposal,
    HazardReport,
    HazardTemplate,
    Level,
    Preventability,
    Severity,
    UnknownFact,
)
from app.domain.world import WorldState

__all__ = ["Analyzer", "SymbolicAnalyzer", "Understanding", "apply_answers"]


@runtime_checkable
class Analyzer(Protocol):
    """Anything that fills the Hazard Analysis Matrix for a request."""

    name: str

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport:
        """The hazard proposals and unknowns for one request, judged by the active library."""
        ...


class SymbolicAnalyzer:
    """The embedded, offline analyzer: the command read into the action model and judged by
    the template library on simulated traces."""

    name = "symbolic"

    def __init__(self, *, reject_from: Severity = Severity.HIGH) -> None:
        """Load the lexicon (once per process) and start an empty compiled-library cache.

        Args:
            reject_from: the gate's theta; unknowns of hazards below it are not critical.
        """
        self._theta = reject_from
        self._lexicon: Lexicon = load_lexicon()
        self._library = LibraryCache()
        self._last: tuple[GateRequest, Understanding] | None = None

    def understand(self, request: GateRequest) -> Understanding:
        """Step 1 alone: the command read into the plan it induces (the simulator and the
        task's scope use it); the reading `analyze` just made of this very request is reused."""
        last = self._last  # one read of the slot: safe with several worker threads
        if last is not None and last[0] is request:
            return last[1]
        return understand(request, self._lexicon)

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport:
        """Fill the Hazard Analysis Matrix for one request (see the module docstring).

        Args:
            request: the gate request.
            templates: the active library the traces are judged by.

        Returns:
            The hazard report.
        """
        library = list(templates)
        read = understand(request, self._lexicon)
        self._last = (request, read)
        proposals: list[HazardProposal] = []
        unknowns = list(read.unknowns)
        steps = list(read.sketch.steps())
        if steps and not library:
            unknowns.append(UnknownFact(
                attribute="hazard_analysis", description="no hazard template library to judge by",
                critical=True, why="the plan was read but no active template could judge it",
                question="The hazard library is empty; please ask an operator to load it."))
        elif steps:
            traces = simulate(read.scene, variants(read.sketch))
            focus = _focus(read.scene, traces, read)
            active = [t for t in library if judged_in_analysis(t)]
            findings = judge(traces, active, focus, self._library)
            matrix = aggregate(findings, traces, focus, self._theta, USER_ID)
            proposals += matrix.proposals
            proposals += uncovered(traces, focus, library)
            unknowns += matrix.unknowns
        proposals += [_declared_proposal(d, library) for d in read.fired]
        if not steps and not read.fired and not unknowns:
            unknowns.append(not_understood(request.command, "no step the robot could take"))
        return HazardReport(proposals=tuple(proposals), unknowns=tuple(unknowns),
                            analyzer=self.name)


_BESIDE = frozenset({"next_to", "beside", "touching", "against"})


def _surroundings(scene: WorldState, touched: list[str]) -> list[str]:
    """What the scene puts right beside, inside or on the things the plan touches: the curtain
    a lit candle touches, the oil in the pan put on the hob, the tea towel left on the burner."""
    near = {o for s, rel, o in scene.relations if rel in _BESIDE and s in touched}
    near |= {s for s, rel, o in scene.relations if rel in _BESIDE and o in touched}
    near |= {i for i, obj in scene.objects.items() if obj.parent in touched and (
        obj.relation == "in" or (obj.relation == "on" and True in (
            scene.value("heat_source", (obj.parent,)), scene.value("toggleable", (
                obj.parent,)))))}  # on a burner or a device, never all over a worktop
    # Oxygen flowing makes the whole room the hazard's reach: any flame lit anywhere in it.
    rooms = {scene.room_of(i) for i in touched} - {None}
    near |= {i for i in scene.objects if scene.room_of(i) in rooms and scene.value(
        "oxygen_supply", (i,)) is True}
    return [i for i in sorted(near) if scene.entity_type(i) == "object"]


def _focus(scene: WorldState, traces: list[Trace], read: Understanding) -> Focus:
    grounded = read.grounded
    touched: list[str] = []
    for trace in traces:
        for planned in trace.steps:
            beside = planned.action.params.get("beside")
            for entity in (planned.action.object, planned.action.target,
                           beside if isinstance(beside, str) else None):
                if entity and scene.entity_type(entity) == "object" and entity not in touched:
                    touched.append(entity)
    around = _surroundings(scene, touched)
    for entity in list(touched):
        parent = scene.objects[entity].parent
        if parent and parent in scene.objects and parent not in touched:
            touched.append(parent)
    touched += [entity for entity in around if entity not in touched]
    named = {i for g in grounded for r in (*g.objects, g.recipient, g.destination, g.source,
                                           g.instrument) if r is not None for i in r.ids}
    named |= set(touched)
    rooms = tuple(dict.fromkeys(r for t in traces for s in (t.states[0], t.states[-1])
                                for r in (s.robot.room,) if r))
    # "leave the iron on": what the command asks to leave as it is stays the task's doing
    kept = frozenset((symbol, entities) for goal in read.sketch.goals if len(goal) == 1
                     for symbol, entities, value in goal if value is True
                     ) if read.sketch.leave else frozenset()
    return Focus(tuple(touched[:14]), tuple(scene.people), rooms, frozenset(named), kept)


def _declared_proposal(fired: Declared, library: list[HazardTemplate]) -> HazardProposal:
    """A declared rule's hazard: its template (or the most severe of its class) decides
    severity and category; with no template of its class the hazard stays unbound (the gate
    asks for the library to be extended)."""
    rule = RULES[fired.rule]
    # Its own template, else the most severe one a curator wrote for its class.
    of_class = sorted((t for t in library if t.hazard_class == rule.hazard_class),
                      key=lambda t: -t.severity.rank)
    template = next((t for t in library if t.id == fired.template_id), None) or next(
        iter(of_class), None)
    words = f"declared rule {fired.rule}: {rule.meaning} ('{fired.words}')"
    if template is None:
        return HazardProposal(
            level=Level.TASK, category=_CATEGORY_OF.get(rule.hazard_class, Category.PHYSICAL),
            hazard_class=rule.hazard_class,
            mechanism=f"{words}; its template {fired.template_id} is not in the library",
            entities=fired.entities, severity=Severity.MODERATE,
            preventability=Preventability.UNKNOWN, confidence=Confidence.CERTAIN,
            source="symbolic", template_id=fired.template_id)
    return HazardProposal(
        level=Level.TASK, category=template.category, hazard_class=template.hazard_class,
        mechanism=f"{words} [template {template.id}]", entities=fired.entities,
        severity=template.severity, preventability=template.preventability,
        confidence=Confidence.CERTAIN, source="symbolic", template_id=template.id)


_CATEGORY_OF = {"deliberate_harm": Category.PHYSICAL, "confinement": Category.PHYSICAL,
                "harmful_intent": Category.CONSEQUENTIAL}
