"""Assembling the Hazard Analysis Matrix from the LLM's answers, level by level.

In: each level's validated `LevelAnswer`, in order (task, deployment, user). Out: the report's
proposals and unknowns. A hazard class (within its category) or an unknown attribute reported
again at a later level is superseded by the later, better-informed entries, which keep the level
where it first appeared; one a later level explicitly dismisses is dropped; any other earlier
item stays, since silence is not evidence of safety. `earlier_summary` renders what the previous
levels found, for the next level's prompt.
Fails: never.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.adapters.llm.schemas import LevelAnswer, MatrixHazard, MatrixUnknown
from app.domain.models import HazardProposal, Level, UnknownFact

HazardKey = tuple[str, str]


@dataclass
class MatrixBuilder:
    """Accumulates level answers into the matrix."""

    source: str
    _hazards: dict[HazardKey, list[HazardProposal]] = field(default_factory=dict)
    _first_level: dict[HazardKey, Level] = field(default_factory=dict)
    _unknowns: dict[str, list[UnknownFact]] = field(default_factory=dict)

    def add(self, level: Level, answer: LevelAnswer) -> None:
        """Fold one level's answer in.

        Args:
            level: the level the answer is for.
            answer: the validated answer.
        """
        for dismissal in answer.dismissed:
            if dismissal.kind == "hazard":
                for key in [k for k in self._hazards if k[1] == dismissal.name]:
                    del self._hazards[key]
            else:
                self._unknowns.pop(dismissal.name, None)
        fresh_hazards: dict[HazardKey, list[HazardProposal]] = {}
        for hazard in answer.hazards:
            key = (hazard.category.value, hazard.hazard_class)
            first = self._first_level.setdefault(key, level)
            fresh_hazards.setdefault(key, []).append(self._proposal(hazard, first, level))
        self._hazards.update(fresh_hazards)
        fresh_unknowns: dict[str, list[UnknownFact]] = {}
        for unknown in answer.unknowns:
            fresh_unknowns.setdefault(unknown.attribute, []).append(_unknown(unknown))
        self._unknowns.update(fresh_unknowns)

    def _proposal(self, hazard: MatrixHazard, first: Level, level: Level) -> HazardProposal:
        # Without a scene there are no ids to bind, whatever the model wrote.
        entities = hazard.entities.as_bindings() if level is not Level.TASK else {}
        return HazardProposal(
            level=first,
            category=hazard.category,
            hazard_class=hazard.hazard_class,
            mechanism=hazard.mechanism,
            entities=entities,
            severity=hazard.severity,
            preventability=hazard.preventability,
            confidence=hazard.confidence,
            source=self.source,
        )

    def proposals(self) -> tuple[HazardProposal, ...]:
        """Every hazard in the matrix, each once."""
        unique: list[HazardProposal] = []
        for group in self._hazards.values():
            unique.extend(p for p in group if p not in unique)
        return tuple(unique)

    def unknowns(self) -> tuple[UnknownFact, ...]:
        """Every unknown in the matrix, each once."""
        unique: list[UnknownFact] = []
        for group in self._unknowns.values():
            unique.extend(u for u in group if u not in unique)
        return tuple(unique)

    def earlier_summary(self) -> tuple[str, str]:
        """The hazards and unknowns found so far, one per line, for the next level's prompt."""
        hazards = [
            f"- {p.category.value}/{p.hazard_class} ({p.severity.value}, "
            f"{p.preventability.value}): {p.mechanism}"
            for p in self.proposals()
        ]
        unknowns = [
            f"- {u.attribute}{f' of {u.entity}' if u.entity else ''}"
            f"{' (critical)' if u.critical else ''}: {u.description}"
            for u in self.unknowns()
        ]
        return "\n".join(hazards) or "- none", "\n".join(unknowns) or "- none"


def _unknown(unknown: MatrixUnknown) -> UnknownFact:
    return UnknownFact(
        attribute=unknown.attribute,
        description=unknown.description,
        critical=unknown.critical,
        why=unknown.why,
        entity=unknown.entity or None,
        question=unknown.question or None,
    )
