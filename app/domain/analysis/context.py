"""The shared working state of one analysis: views, grounded steps, and the matrix being filled.

In: a request, the knowledge, the scene view and the grounded steps. Out: `Context`, which the
rule modules read and append proposals and unknowns to; `report()` deduplicates (one proposal
per hazard class and entities, the worst kept) and freezes the result. Never fails.
"""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import lru_cache

from app.domain.analysis.command import ParsedCommand
from app.domain.analysis.grounding import GroundedStep, Referent
from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.mentions import Mention
from app.domain.analysis.scene_view import ObjectView, PersonView, SceneView
from app.domain.analysis.word_filter import candidates
from app.domain.models import (
    Category,
    Confidence,
    GateRequest,
    HazardProposal,
    HazardReport,
    Level,
    Preventability,
    Severity,
    UnknownFact,
)

LEVEL_ORDER = (Level.TASK, Level.DEPLOYMENT, Level.USER)
_PREVENT_RANK = {Preventability.PREVENTABLE: 0, Preventability.UNKNOWN: 1,
                 Preventability.UNPREVENTABLE: 2}


def latest(*levels: Level) -> Level:
    """The level at which all the given facts are known (the latest of them)."""
    return max(levels, key=LEVEL_ORDER.index) if levels else Level.TASK


@dataclass(slots=True)
class Context:
    """Everything a rule needs, and the proposals and unknowns found so far."""

    request: GateRequest
    knowledge: Knowledge
    view: SceneView
    steps: list[GroundedStep]
    text: str
    analyzer: str
    proposals: list[HazardProposal] = field(default_factory=list)
    ambiguous_ids: frozenset[str] = frozenset()
    unknowns: list[UnknownFact] = field(default_factory=list)
    # The reader's whole result: temporal facts (`parsed.facts`), comprehension gaps
    # (`parsed.not_understood`) and implied devices (`parsed.devices`); None when built by hand.
    parsed: ParsedCommand | None = None
    # Which people a text names, asked by many rules of one pass (the people are settled
    # before the rules run; see `situation_base.named_people`).
    named_in: dict[str, list[PersonView]] = field(default_factory=dict)

    def add(self, level: Level, category: Category, hazard_class: str, mechanism: str,
            entities: Mapping[str, str | None], severity: Severity,
            preventability: Preventability, confidence: Confidence = Confidence.CERTAIN) -> None:
        """Record one hazard proposal (entities with a None value are left out).

        A hazard of an object the command may not even mean (one of several candidates for
        an ambiguous phrase) cannot be certain: it is kept, as uncertain with unknown
        preventability, so the gate asks instead of rejecting on a guess.
        """
        if preventability == Preventability.UNPREVENTABLE and any(
                v in self.ambiguous_ids for v in entities.values() if v):
            preventability, confidence = Preventability.UNKNOWN, Confidence.UNCERTAIN
        self.proposals.append(HazardProposal(
            level=level, category=category, hazard_class=hazard_class,
            mechanism=mechanism[:1].upper() + mechanism[1:],
            entities={k: v for k, v in entities.items() if v}, severity=severity,
            preventability=preventability, confidence=confidence, source=self.analyzer))

    def unknown(self, attribute: str, description: str, *, critical: bool, why: str,
                entity: str | None, question: str | None) -> None:
        """Record one unknown fact."""
        self.unknowns.append(UnknownFact(attribute=attribute, description=description,
                                         critical=critical, why=why, entity=entity,
                                         question=question))

    def cue(self, name: str) -> bool:
        """Whether the command contains any phrase of a cue group (whole words)."""
        phrases = candidates(self.text, self.knowledge.cues.get(name, ()))
        return any(_contains(self.text, phrase) for phrase in phrases)

    def place_in(self, mention: Mention | None, group: str) -> bool:
        """Whether a place phrase (with its own location) names a place of a group."""
        if mention is None:
            return False
        words = mention.text
        if mention.location:
            words += " " + mention.location[1].text
        return any(_contains(words, phrase)
                   for phrase in candidates(words, self.knowledge.places[group]))

    def objects(self, referent: Referent | None) -> list[ObjectView]:
        if referent is None or referent.kind != "object":
            return []
        return [self.view.objects[i] for i in referent.ids if i in self.view.objects]

    def people(self, referent: Referent | None) -> list[PersonView]:
        if referent is None or referent.kind != "person":
            return []
        return [self.view.people[i] for i in referent.ids if i in self.view.people]

    def room_of(self, entity_id: str | None) -> str | None:
        if entity_id in self.view.objects:
            return self.view.objects[entity_id].room
        if entity_id in self.view.people:
            return self.view.people[entity_id].room
        return None

    def rooms_between(self, start: str | None, end: str | None) -> list[str]:
        """Rooms on the shortest known route (both ends included); just the ends if unknown."""
        if not start or not end or start == end:
            return [r for r in (start, end) if r]
        # Neighbours in scene order (dicts, not sets): when two routes are equally short, the
        # same one is taken in every process, whatever the hash seed.
        graph: dict[str, dict[str, None]] = {}
        for a, b in self.view.connections:
            graph.setdefault(a, {})[b] = None
            graph.setdefault(b, {})[a] = None
        previous: dict[str, str | None] = {start: None}
        queue = deque([start])
        while queue:
            room = queue.popleft()
            for nxt in graph.get(room, ()):
                if nxt not in previous:
                    previous[nxt] = room
                    queue.append(nxt)
        if end not in previous:
            return [start, end]
        route: list[str] = []
        node: str | None = end
        while node is not None:
            route.append(node)
            node = previous[node]
        return route[::-1]

    def report(self) -> HazardReport:
        """The deduplicated, frozen Hazard Analysis Matrix."""
        best: dict[tuple[str, tuple[tuple[str, str], ...]], HazardProposal] = {}
        for proposal in self.proposals:
            key = (proposal.hazard_class, tuple(sorted(proposal.entities.items())))
            kept = best.get(key)
            if kept is None or _worse(proposal, kept):
                best[key] = proposal
        unknowns: dict[tuple[str, str | None], UnknownFact] = {}
        for unknown in self.unknowns:
            about = (unknown.attribute, unknown.entity)
            if about not in unknowns or (unknown.critical and not unknowns[about].critical):
                unknowns[about] = unknown
        return HazardReport(proposals=tuple(best.values()), unknowns=tuple(unknowns.values()),
                            analyzer=self.analyzer)


def _worse(new: HazardProposal, old: HazardProposal) -> bool:
    return (new.severity.rank, _PREVENT_RANK[new.preventability],
            -LEVEL_ORDER.index(new.level)) > (
        old.severity.rank, _PREVENT_RANK[old.preventability], -LEVEL_ORDER.index(old.level))


def _contains(text: str, phrase: str) -> bool:
    # The substring test rules most phrases out before any regex runs; patterns are compiled
    # once per phrase (the `re` module's own cache is too small for the cue tables).
    return phrase in text and _whole_words(phrase).search(text) is not None


@lru_cache(maxsize=8192)
def _whole_words(phrase: str) -> re.Pattern[str]:
    return re.compile(rf"(?<![\w']){re.escape(phrase)}(?![\w'])")
