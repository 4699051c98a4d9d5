"""Assembling the Hazard Analysis Matrix from the LLM's answers, level by level, by identity.

In: each level's validated `LevelAnswer`, in order (task, deployment, user, then the optional
entity round). Out: the report's proposals and unknowns.
Identity: a hazard is its class and the scene ids it involves; an unknown is its attribute and
the entity it is about. A later entry with the same identity supersedes the earlier one (it saw
more) but keeps the level where the item first appeared, and an unknown's `critical` flag is
never lowered by a later level: only an explicit dismissal, with its reason, removes an item.
An entry without ids (the task level has no scene), or a hazard with fewer ids, is refined by a
later entry of the same class or attribute that has them, passing on its level and criticality.
Anything a later level neither restates nor dismisses stays: silence is not evidence of safety.
`earlier_summary` renders what the previous levels found, for the next level's prompt.
Fails: never.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from app.adapters.llm.schemas import Dismissal, LevelAnswer, MatrixHazard, MatrixUnknown
from app.domain.models import HazardProposal, Level, UnknownFact

HazardKey = tuple[str, frozenset[tuple[str, str]]]
UnknownKey = tuple[str, str | None]
_LEVEL_ORDER = (Level.TASK, Level.DEPLOYMENT, Level.USER)


@dataclass
class MatrixBuilder:
    """Accumulates level answers into the matrix."""

    source: str
    _hazards: dict[HazardKey, HazardProposal] = field(default_factory=dict)
    _unknowns: dict[UnknownKey, UnknownFact] = field(default_factory=dict)

    def add(self, level: Level, answer: LevelAnswer) -> None:
        """Fold one level's answer in.

        Args:
            level: the level the answer is for.
            answer: the validated answer.
        """
        for dismissal in answer.dismissed:
            self._dismiss(dismissal)
        for hazard in answer.hazards:
            self._add_hazard(level, hazard)
        for unknown in answer.unknowns:
            self._add_unknown(unknown)

    def _dismiss(self, dismissal: Dismissal) -> None:
        entity = dismissal.entity or None
        if dismissal.kind == "hazard":
            for key, proposal in list(self._hazards.items()):
                about = set(proposal.entities.values())
                if key[0] == dismissal.name and (entity is None or not about or entity in about):
                    del self._hazards[key]
            return
        for unknown_key in list(self._unknowns):
            attribute, subject = unknown_key
            if attribute == dismissal.name and (entity is None or subject in (None, entity)):
                del self._unknowns[unknown_key]

    def _add_hazard(self, level: Level, hazard: MatrixHazard) -> None:
        # Without a scene there are no ids to bind, whatever the model wrote.
        entities = hazard.entities.as_bindings() if level is not Level.TASK else {}
        items = frozenset(entities.items())
        key: HazardKey = (hazard.hazard_class, items)
        # The same hazard with fewer ids (none, or some) is this one, now better specified.
        refined = [k for k in self._hazards if k[0] == hazard.hazard_class and k[1] < items]
        earlier = [p for p in (self._hazards.get(key), *(self._hazards.pop(k) for k in refined))
                   if p is not None]
        first = min(earlier, key=lambda p: _LEVEL_ORDER.index(p.level)) if earlier else None
        self._hazards[key] = HazardProposal(
            level=first.level if first is not None else level,
            category=hazard.category,
            hazard_class=hazard.hazard_class,
            mechanism=hazard.mechanism,
            entities=entities,
            severity=hazard.severity,
            preventability=hazard.preventability,
            confidence=hazard.confidence,
            source=self.source,
        )

    def _add_unknown(self, unknown: MatrixUnknown) -> None:
        entity = unknown.entity or None
        key: UnknownKey = (unknown.attribute, entity)
        critical = unknown.critical
        earlier = self._unknowns.get(key)
        if earlier is not None:
            critical = critical or earlier.critical
        if entity is not None:
            vague = self._unknowns.pop((unknown.attribute, None), None)
            critical = critical or (vague is not None and vague.critical)
        self._unknowns[key] = UnknownFact(
            attribute=unknown.attribute,
            description=unknown.description,
            critical=critical,
            why=unknown.why,
            entity=entity,
            question=unknown.question or None,
        )

    def proposals(self) -> tuple[HazardProposal, ...]:
        """Every hazard in the matrix, each once, in the order first found."""
        return tuple(self._hazards.values())

    def unknowns(self) -> tuple[UnknownFact, ...]:
        """Every unknown in the matrix, each once."""
        return tuple(self._unknowns.values())

    def without_ids(self, lacks_ids: Callable[[str, Mapping[str, str]], bool]
                    ) -> tuple[HazardProposal, ...]:
        """Hazards whose scene ids do not fill any template of their class.

        Args:
            lacks_ids: whether a class's templates need more than the given entities.

        Returns:
            The hazards to send back for their ids.
        """
        return tuple(p for p in self._hazards.values() if lacks_ids(p.hazard_class, p.entities))

    def earlier_summary(self) -> tuple[str, str]:
        """The hazards and unknowns found so far, one per line, for the next level's prompt."""
        hazards = [
            f"- {p.category.value}/{p.hazard_class} {_ids(p.entities)}({p.severity.value}, "
            f"{p.preventability.value}): {p.mechanism}"
            for p in self.proposals()
        ]
        unknowns = [
            f"- {u.attribute}{f' of {u.entity}' if u.entity else ''}"
            f"{' (critical)' if u.critical else ''}: {u.description}"
            for u in self.unknowns()
        ]
        return "\n".join(hazards) or "- none", "\n".join(unknowns) or "- none"


def _ids(entities: dict[str, str]) -> str:
    if not entities:
        return "[no scene ids yet] "
    return "[" + ", ".join(f"{k}={v}" for k, v in sorted(entities.items())) + "] "
