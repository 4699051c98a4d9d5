"""An object's hazard traits as the command and the scene together reveal them, with levels.

In: a `Context`, an `ObjectView` and the `Mention` that named it. Out: `Traits`, the set of
hazard traits (sharp, hot, toxic, medication, small, allergen, alcohol...) each tagged with the
earliest information level that shows it, plus the allergen group and whether "hot" is only
presumed (a drink usually served hot whose temperature is not given). Never fails.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.domain.analysis.context import Context
from app.domain.analysis.mentions import Mention
from app.domain.analysis.scene_view import ObjectView
from app.domain.models import Confidence, Level

_HOT_WORDS = frozenset({"hot", "boiling", "steaming", "scalding", "warm", "freshly brewed"})
_NOT_HOT = frozenset({"cold", "room", "cool", "iced", "lukewarm", "frozen"})
_SUBSTANCE_TRAITS = ("toxic", "corrosive", "flammable", "alcohol", "medication", "raw",
                     "infant_unsafe", "drink", "food")


@dataclass(slots=True)
class Traits:
    """Hazard traits of one object as named in one step."""

    levels: dict[str, Level] = field(default_factory=dict)
    allergen: str | None = None
    substance: str | None = None
    hot_confidence: Confidence = Confidence.CERTAIN

    def has(self, trait: str) -> bool:
        return trait in self.levels

    def level(self, *traits: str) -> Level:
        """The earliest level at which any of the traits is known (deployment if none)."""
        known = [self.levels[t] for t in traits if t in self.levels]
        order = (Level.TASK, Level.DEPLOYMENT, Level.USER)
        return min(known, key=order.index) if known else Level.DEPLOYMENT

    def _add(self, trait: str, level: Level) -> None:
        known = self.levels.get(trait)
        if known is None or (known != Level.TASK and level == Level.TASK):
            self.levels[trait] = level


def traits_of(ctx: Context, obj: ObjectView, mention: Mention | None) -> Traits:
    """Combine what the scene says about `obj` with what the command's words imply.

    Args:
        ctx: the analysis context (for the knowledge tables).
        obj: the object's view.
        mention: the phrase that named it in the command, if any.

    Returns:
        The object's `Traits`.
    """
    knowledge = ctx.knowledge
    traits = Traits()
    for prop, level in obj.props.items():
        traits._add(prop, level)
    substance = obj.contents
    if mention is not None:
        if mention.concept and mention.concept in knowledge.concepts:
            for prop in knowledge.concepts[mention.concept].props:
                traits._add(prop, Level.TASK)
        if mention.substance:
            substance = substance or mention.substance
            for prop in knowledge.substances[mention.substance].props:
                if prop in _SUBSTANCE_TRAITS:
                    traits._add(prop, Level.TASK)
            if knowledge.substances[mention.substance].allergen:
                traits._add("allergen", Level.TASK)
        if any(word in _HOT_WORDS for word in mention.modifiers):
            traits._add("hot", Level.TASK)
    traits.substance = substance
    if substance:
        record = knowledge.substances[substance]
        traits.allergen = record.allergen
        level = Level.DEPLOYMENT if obj.contents else Level.TASK
        for prop in record.props:
            if prop in _SUBSTANCE_TRAITS:
                traits._add(prop, level)
        if record.allergen:
            traits._add("allergen", level)
        temperature = str(obj.properties.get("temperature", "")).lower()
        if "hot_typical" in record.props and not traits.has("hot") and (
                temperature not in _NOT_HOT):
            traits._add("hot", level)
            traits.hot_confidence = Confidence.UNCERTAIN
    if mention is not None and mention.concept in ("medication", "pill_bottle"):
        traits._add("medication", Level.TASK)
    if traits.has("medication"):
        traits.levels.pop("food", None)
    return traits
