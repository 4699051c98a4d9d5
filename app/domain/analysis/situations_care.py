"""Hazards of caring for those who cannot judge a danger themselves: infants and animals.

In: the `Context` and the word groups of `knowledge/hazard_situations.json`. Out: proposals for
- unsafe infant sleep (suffocation, as `choking`): soft bedding (pillow, duvet, bumper) put in
  with a sleeping infant, or an infant laid to sleep on the tummy;
- food poisonous to animals (chemical_ingestion): chocolate, grapes, onion, xylitol and the like
  given or put out for a dog, cat or other pet.
The command itself creates the danger, so these are unpreventable. Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.scene_view import PersonView
from app.domain.analysis.situation_base import any_phrase, load_situations, named_people
from app.domain.models import Category, Level, Preventability, Severity

_U = Preventability.UNPREVENTABLE
_FEEDING = frozenset({"handover", "serve", "pour", "place"})


def care_hazards(ctx: Context) -> None:
    """Add the unsafe-infant-sleep and pet-poisoning hazards of the command."""
    if not any(not g.step.negated and g.step.action for g in ctx.steps):
        return
    _infant_sleep(ctx)
    _pet_food(ctx)


def _infants(ctx: Context) -> list[PersonView]:
    return [p for p in ctx.view.real_people() if p.age_group == "infant"]


def _infant_sleep(ctx: Context) -> None:
    """Soft bedding in a cot, or a baby put down on the tummy: the leading cause of sudden
    infant death in sleep is suffocation against soft things and face-down sleeping."""
    data = load_situations()
    infants = _infants(ctx)
    if not infants:
        return
    cot = any_phrase(ctx.text, data.group("infant_sleeper_places")) or any_phrase(
        ctx.text, ("nap", "sleep", "bedtime", "put her down", "put him down"))
    if not cot:
        return
    baby = next((p for p in named_people(ctx) if p in infants), infants[0])
    bedding = any_phrase(ctx.text, data.group("infant_soft_bedding"))
    prone = any_phrase(ctx.text, data.group("infant_prone_words"))
    if bedding:
        ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "choking", f"Putting soft bedding "
                f"({bedding}) in where {baby.label}, an infant, sleeps: it can smother them.",
                {"person": baby.id}, Severity.CRITICAL, _U)
    if prone:
        ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "choking", f"Laying {baby.label}, an "
                f"infant, to sleep {prone}: face-down sleep can suffocate a baby.",
                {"person": baby.id}, Severity.CRITICAL, _U)


def _is_animal(person: PersonView) -> bool:
    words = load_situations().group("animal_words")
    if person.properties.get("species"):
        return str(person.properties["species"]).lower() not in ("human", "person")
    return any_phrase(person.role or "", words) is not None


def _pet_food(ctx: Context) -> None:
    """Chocolate, grapes, onion, xylitol: ordinary food for people, poison for a dog or cat."""
    foods = load_situations().group("pet_toxic_foods")
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action not in _FEEDING:
            continue
        food = any_phrase(step.text, foods)
        if food is None:
            continue
        animals = [p for p in ctx.people(grounded.recipient) if _is_animal(p)]
        animals += [p for p in named_people(ctx, step.text) if _is_animal(p)]
        animals += [p for p in ctx.view.real_people() if _is_animal(p) and any_phrase(
            step.text, ("bowl", "dish")) and any_phrase(step.text, tuple((p.role or "").split()))]
        if animals:
            pet = animals[0]
            ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "chemical_ingestion", f"Giving "
                    f"{food} to {pet.label}, an animal: it is poisonous to them.",
                    {"person": pet.id}, Severity.HIGH, _U)
            return
