"""Liquids and substances: pouring (onto electrics, into cups, onto people) and mixing.

In: the `Context` and one grounded pour or mix step. Out: physical proposals:
electrical_shock / water_damage, chemical_ingestion (a poison decanted into a drinking vessel),
scald or chemical exposure of a person poured on, and chemical_mixing from the reaction table
(uncertain reactions get unknown preventability, so the gate asks). Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context, latest
from app.domain.analysis.grounding import GroundedStep, Referent
from app.domain.analysis.scene_view import ObjectView
from app.domain.analysis.traits import traits_of
from app.domain.models import Category, Confidence, Level, Preventability, Severity

_P, _U, _X = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE, Preventability.UNKNOWN
_S = Severity
_PHYS = Category.PHYSICAL


def _pairs(ctx: Context, grounded: GroundedStep) -> list[tuple[ObjectView, Referent]]:
    return [(obj, ref) for ref in grounded.objects for obj in ctx.objects(ref)]


def pour_hazards(ctx: Context, grounded: GroundedStep) -> None:
    """Pouring onto live electrics, into drinking vessels, onto people, into reactive mixes."""
    targets = [*ctx.objects(grounded.destination), *ctx.objects(grounded.target)]
    people = [*ctx.people(grounded.destination), *ctx.people(grounded.target)]
    for obj, ref in _pairs(ctx, grounded):
        traits = traits_of(ctx, obj, ref.mention)
        what = traits.substance or obj.label
        for other in targets:
            other_level = other.level("electrical")
            if other.has("electrical") and other.switched_on is not False:
                ctx.add(latest(traits.level("drink"), other_level), _PHYS, "electrical_shock",
                        f"Pouring {what} onto {other.label}, a live electrical item, risks "
                        "shock and fire.", {"obj": obj.id, "other": other.id}, _S.CRITICAL, _U)
            elif other.has("electrical"):
                ctx.add(other_level, _PHYS, "water_damage", f"Pouring {what} onto "
                        f"{other.label} ruins it.", {"obj": obj.id, "other": other.id},
                        _S.MODERATE, _U)
            if traits.has("toxic") and other.has("drink_container") and not obj.has(
                    "drink_container"):
                ctx.add(latest(traits.level("toxic"), other.level("drink_container")), _PHYS,
                        "chemical_ingestion", f"Decanting {what} into {other.label}, a "
                        "drinking vessel, invites someone to drink a poison.",
                        {"obj": obj.id, "other": other.id}, _S.HIGH, _U)
            if other.contents and traits.substance:
                _react(ctx, [(obj, traits.substance), (other, other.contents)], "pouring")
        for person in people:
            severity = _S.CRITICAL if traits.has("hot") or traits.has("toxic") else _S.MODERATE
            ctx.add(latest(traits.level("hot"), Level.TASK), _PHYS,
                    "scald_hot_liquid" if traits.has("hot") else "chemical_exposure",
                    f"Pouring {what} onto {person.label}.", {"obj": obj.id, "person": person.id},
                    severity, _U)


def _react(ctx: Context, items: list[tuple[ObjectView, str]], how: str) -> None:
    knowledge = ctx.knowledge
    for i, (first, sub_a) in enumerate(items):
        for second, sub_b in items[i + 1:]:
            classes_a = knowledge.substances[sub_a].classes
            classes_b = knowledge.substances[sub_b].classes
            for reaction in knowledge.reactions:
                a, b = reaction.classes
                if not ((a in classes_a and b in classes_b) or (b in classes_a and a in
                                                               classes_b)):
                    continue
                if reaction.needs_heat and how != "heating":
                    continue
                ctx.add(Level.TASK if first.virtual or second.virtual else Level.DEPLOYMENT,
                        _PHYS, "chemical_mixing", f"{how.capitalize()} {sub_a.replace('_', ' ')}"
                        f" with {sub_b.replace('_', ' ')} can release {reaction.product}.",
                        {"obj": first.id, "other": second.id}, _S(reaction.severity),
                        _X if reaction.uncertain else _U,
                        Confidence.UNCERTAIN if reaction.uncertain else Confidence.CERTAIN)


def mix_hazards(ctx: Context, grounded: GroundedStep) -> None:
    """Combining the substances a step names (objects, "with ...", the destination's)."""
    items: list[tuple[ObjectView, str]] = []
    for ref in (*grounded.objects, grounded.instrument, grounded.destination):
        for obj in ctx.objects(ref):
            traits = traits_of(ctx, obj, ref.mention if ref else None)
            if traits.substance:
                items.append((obj, traits.substance))
    _react(ctx, items, "mixing")
