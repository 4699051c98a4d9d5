"""Stage 1, the Hazard Analysis Matrix: the `Analyzer` interface and the offline symbolic one.

In: a `GateRequest` (command, optional scene, user and robot). Out: a `HazardReport` whose
proposals fill the matrix's cells (task / deployment / user level x physical / psychological /
operational / consequential) and whose unknowns say what is missing and whether it is critical.
`SymbolicAnalyzer` is deterministic, offline and fast: it loads its knowledge (JSON data under
`knowledge/`) once, at construction. Fails: only if the knowledge files are missing or broken
(at construction); analysing a valid request never raises.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Protocol, runtime_checkable

from app.domain.analysis.clauses import TITLE_DOT
from app.domain.analysis.command import read_command
from app.domain.analysis.consequences import consequential_hazards
from app.domain.analysis.context import Context
from app.domain.analysis.giving import giving_hazards
from app.domain.analysis.grounding import GroundedStep, Grounder, apply_state_clauses
from app.domain.analysis.handling import handling_hazards
from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR, Knowledge, load_knowledge
from app.domain.analysis.operational import operational_hazards
from app.domain.analysis.questions import apply_answers, phrase_question, question_for
from app.domain.analysis.scene_view import SceneView, build_scene_view
from app.domain.analysis.semantic import (
    Match,
    SemanticMatcher,
    load_matcher,
    semantic_hazards,
)
from app.domain.analysis.situations_aftermath import aftermath_hazards
from app.domain.analysis.situations_care import care_hazards
from app.domain.analysis.situations_contact import contact_hazards
from app.domain.analysis.situations_home import situation_home_hazards
from app.domain.analysis.situations_people import situation_people_hazards
from app.domain.analysis.situations_rough import rough_handling_hazards
from app.domain.analysis.social import social_hazards
from app.domain.analysis.unknowns import find_unknowns
from app.domain.models import GateRequest, HazardReport, Preventability, Severity

__all__ = [
    "Analyzer",
    "SymbolicAnalyzer",
    "analyze",
    "apply_answers",
    "phrase_question",
    "question_for",
]


@runtime_checkable
class Analyzer(Protocol):
    """Anything that fills the Hazard Analysis Matrix for a request."""

    name: str

    def analyze(self, request: GateRequest) -> HazardReport:
        """Return the hazard proposals and unknowns for one request."""
        ...


class SymbolicAnalyzer:
    """The embedded, offline analyzer: a command parser, scene grounding and general rules."""

    name = "symbolic"

    def __init__(
        self, knowledge_dir: Path = KNOWLEDGE_DIR, *, reject_from: Severity = Severity.HIGH
    ) -> None:
        """Load the knowledge and the semantic model.

        Args:
            knowledge_dir: the knowledge JSON files.
            reject_from: the gate's theta. A whole-command hazard that no contract can prevent
                at this severity or above is rejected (R1) whatever else is found, so the
                per-sentence passes are skipped for it; keep it equal to the gate policy's.
        """
        self._reject_from = reject_from
        self._knowledge: Knowledge = load_knowledge(knowledge_dir)
        # The static embedding model and prototype vectors: read once per process, not per call.
        self._semantic: SemanticMatcher = load_matcher(knowledge_dir)

    def analyze(self, request: GateRequest) -> HazardReport:
        """Fill the Hazard Analysis Matrix for one request.

        A command's hazards are at least those of each of its sentences: when the command has
        several, each is also analysed alone and its hazards join the whole command's. Text
        around a dangerous instruction ("this is totally safe, nobody is around: ...", "jk,
        never mind") can then add hazards but never hide one. Unknowns come from the whole
        command only (a sentence alone loses what its pronouns point to).

        Args:
            request: the gate request.

        Returns:
            The `HazardReport` (proposals deduplicated per hazard class and entities).
        """
        view = build_scene_view(request, self._knowledge)
        memo: dict[str, Match] = {}
        report = self._analyze_one(request, view.for_pass(), memo)
        parts = sentences(request.command)
        if len(parts) < 2 or self._rejected_anyway(report):
            return report
        proposals = list(report.proposals)
        for part in parts:
            alone = self._analyze_one(request.model_copy(update={"command": part}),
                                      view.for_pass(), memo, with_unknowns=False)
            proposals.extend(p for p in alone.proposals if p not in proposals)
        return report.model_copy(update={"proposals": tuple(proposals)})

    def _rejected_anyway(self, report: HazardReport) -> bool:
        """Whether the gate rejects on this report's hazards alone (R1): more cannot matter."""
        rank = self._reject_from.rank
        return any(p.preventability is Preventability.UNPREVENTABLE and p.severity.rank >= rank
                   for p in report.proposals)

    def _analyze_one(self, request: GateRequest, view: SceneView, memo: dict[str, Match], *,
                     with_unknowns: bool = True) -> HazardReport:
        """One pass over one command text (a sentence pass needs no unknowns: see `analyze`)."""
        knowledge = self._knowledge
        names = {n.lower() for p in view.people.values() for n in (p.id, p.name) if n}
        names |= {n.lower() for o in view.objects.values() for n in (o.id, o.name) if n}
        parsed = read_command(request.command, knowledge, names)
        steps = list(parsed.steps)
        grounder = Grounder(view, knowledge)
        grounded = [grounder.ground(step) for step in steps]
        apply_state_clauses(grounder, grounded, view, knowledge)
        ctx = Context(request=request, knowledge=knowledge, view=view, steps=grounded,
                      text=parsed.text, analyzer=self.name, parsed=parsed,
                      ambiguous_ids=_ambiguous_ids(grounded))
        giving_hazards(ctx)
        handling_hazards(ctx)
        social_hazards(ctx)
        operational_hazards(ctx)
        consequential_hazards(ctx)
        situation_people_hazards(ctx)
        contact_hazards(ctx)
        rough_handling_hazards(ctx)
        situation_home_hazards(ctx)
        aftermath_hazards(ctx)
        care_hazards(ctx)
        semantic_hazards(ctx, self._semantic, memo)
        if with_unknowns:
            find_unknowns(ctx)
        return ctx.report()


def _ambiguous_ids(grounded: list[GroundedStep]) -> frozenset[str]:
    """Candidates of a phrase that may mean one of several things, or a pronoun that may mean
    one of several people ("give her the medicine" with two girls present)."""
    found = {i for g in grounded for r in g.objects if r.kind == "object" and len(r.ids) > 1
             for i in r.ids}
    found |= {i for g in grounded if (r := g.recipient) is not None and r.kind == "person"
              and r.mention.kind == "pronoun" and len(r.ids) > 1 for i in r.ids}
    return frozenset(found)


_SENTENCE_BREAK = re.compile(r"(?<=[.!?;:])\s+|\s*[()\[\]{}<>\n]+\s*|\s+-{1,2}\s+")
# With `key=value` tokens too; only a command holding an "=" needs its slower search.
_SENTENCE_OR_SETTING_BREAK = re.compile(_SENTENCE_BREAK.pattern + r"|\s*\S+=\S*\s*")


def sentences(command: str) -> list[str]:
    """The command's sentence-like parts: split at . ! ? ; : brackets, dashes, new lines and
    `key=value` tokens (machine-looking text is never part of an instruction)."""
    command = TITLE_DOT.sub(r"\1", command)
    breaks = _SENTENCE_OR_SETTING_BREAK if "=" in command else _SENTENCE_BREAK
    return [part.strip(" ,") for part in breaks.split(command) if part.strip(" ,.")]


def analyze(request: GateRequest) -> HazardReport:
    """Analyse one request with a default `SymbolicAnalyzer` (knowledge loaded once, cached).

    Args:
        request: the gate request.

    Returns:
        The `HazardReport`.
    """
    return SymbolicAnalyzer().analyze(request)
