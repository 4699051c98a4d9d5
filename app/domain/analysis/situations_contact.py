"""Hazards the command brings onto, over or among people's bodies.

In: the `Context` (grounded steps, scene view, normalised text). Out: proposals for
- heat on a body (thermal_burn): a heat source or heated appliance laid over, on or in with
  someone, or put among them ("the electric blanket over the baby", "the fan heater inside the den
  with them");
- spray at a body (chemical_exposure): a toxic spray used on something on a person ("blast the
  wasp on Jamie's arm with the bug spray");
- flame by oxygen (fire_ignition): a flame lit or handed where someone breathes medical oxygen,
  or oxygen taken to someone who is smoking.
The command itself puts the hazard on the person, so these are unpreventable. Never fails.
"""

from __future__ import annotations

import re

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.situation_base import named_people
from app.domain.models import Category, Level, Preventability, Severity

_U = Preventability.UNPREVENTABLE
_CONTACT = re.compile(r"\b(?:over|on top of|onto|on|under|underneath|in with|with|next to|"
                      r"beside|around|among|against)\s+(?:the\s+|her\s+|him\b|them\b|his\s+|"
                      r"their\s+|[a-z]+'s\s+)?")
_HEATING = ("heat_source", "hot")
# Electric things whose type says they heat (FanHeater, ElectricBlanket, BottleWarmer), for
# types the knowledge tables do not list.
_HEATING_TYPE_WORDS = ("heat", "blanket", "warmer")
_BODY_WORDS = frozenset({"arm", "arms", "hand", "hands", "face", "leg", "legs", "head", "hair",
                         "skin", "neck", "eyes", "eye", "back", "shoulder", "foot", "feet",
                         "body", "chest", "mouth", "nose", "ear", "ears"})
_SPRAYING = frozenset({"clean", "scare", "pour", "throw"})
_FLAME = ("ignition", "flame")
_OXYGEN = "oxygen"
_SMOKING = ("smoking", "smokes", "cigarette", "vaping")


def contact_hazards(ctx: Context) -> None:
    """Add the heat-on-body, spray-at-body and flame-by-oxygen hazards of the command."""
    for grounded in ctx.steps:
        if grounded.step.negated or grounded.step.action is None:
            continue
        _heat_on_body(ctx, grounded)
        _spray_at_body(ctx, grounded)
    _flame_by_oxygen(ctx)


def _people_in_contact(ctx: Context, grounded: GroundedStep) -> list[PersonView]:
    text = grounded.step.text
    if not _CONTACT.search(text):
        return []
    people = [p for p in named_people(ctx, text) if not p.is_user]
    if not people and re.search(r"\b(?:with|over|on|among|around|beside) (?:them|him|her)\b",
                                text):
        people = [p for p in named_people(ctx) if not p.is_user] or [  # named earlier on
            p for g in ctx.steps for r in (*g.objects, g.recipient, g.target)
            for p in ctx.people(r) if not p.is_user]
    return people


def _objects(ctx: Context, grounded: GroundedStep) -> list[ObjectView]:
    return [o for r in grounded.objects for o in ctx.objects(r)]


def _fragile(person: PersonView) -> bool:
    return bool(person.child or person.young or person.frail or person.asleep
                or person.age_group == "infant")


def _heat_on_body(ctx: Context, grounded: GroundedStep) -> None:
    if grounded.step.action not in ("place", "switch_on", "transport"):
        return
    heaters = [o for o in _objects(ctx, grounded) if any(o.has(t) for t in _HEATING) or (
        o.has("electrical") and any(w in o.type.lower() for w in _HEATING_TYPE_WORDS))]
    people = _people_in_contact(ctx, grounded) if heaters else []
    if people:
        person = next((p for p in people if _fragile(p)), people[0])
        ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "thermal_burn", f"{heaters[0].label} is "
                f"put on, over or among {person.label}: it can overheat or burn them, or set "
                "bedding alight.", {"obj": heaters[0].id, "person": person.id},
                Severity.CRITICAL if _fragile(person) else Severity.HIGH, _U)


def _spray_at_body(ctx: Context, grounded: GroundedStep) -> None:
    if grounded.step.action not in _SPRAYING and not (grounded.step.verb or "").startswith(
            ("spray", "blast", "squirt", "mist")):
        return
    sprays = [o for r in (grounded.instrument, *grounded.objects) for o in ctx.objects(r)
              if o.has("toxic") or o.has("corrosive")]
    if not sprays:
        return
    on_body = [p for p in ctx.view.real_people() if not p.is_user and any(
        re.search(rf"\b{re.escape(word)}(?:'s)?\s+(?:\w+\s+)?(?:{'|'.join(_BODY_WORDS)})\b",
                  ctx.text) for word in _names(p))]
    for person in on_body[:1]:
        ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "chemical_exposure", f"Spraying "
                f"{sprays[0].label} at something on {person.label}'s body: the chemical goes "
                "on their skin and into their eyes and lungs.",
                {"obj": sprays[0].id, "person": person.id},
                Severity.CRITICAL if _fragile(person) else Severity.HIGH, _U)


def _names(person: PersonView) -> list[str]:
    words = [w.lower() for w in (person.name, person.role, person.id) if w]
    return [w for w in words if w]


def _flame_by_oxygen(ctx: Context) -> None:
    # Who breathes oxygen and who smokes are looked up only once a step brings a flame or
    # oxygen: most commands do neither.
    users: list[PersonView] | None = None
    smokers: list[PersonView] | None = None
    for grounded in ctx.steps:
        if grounded.step.negated:
            continue
        objects = _objects(ctx, grounded)
        lit = grounded.step.action == "switch_on" and any(
            any(o.has(t) for t in _FLAME) for o in objects)
        handed = grounded.step.action in ("handover", "transport") and any(
            any(o.has(t) for t in _FLAME) for o in objects)
        if (lit or handed) and users is None:
            users = _oxygen_users(ctx)
        if users and (lit or handed):
            ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "fire_ignition", f"A flame by "
                    f"{users[0].label}, who breathes medical oxygen: oxygen makes a small flame "
                    "a fierce fire.", {"person": users[0].id}, Severity.CRITICAL, _U)
            return
        oxygen = [o for r in grounded.objects for o in ctx.objects(r)
                  if _OXYGEN in f"{o.type} {o.contents_text or ''} {r.mention.text}".lower()]
        if oxygen and smokers is None:
            smokers = [p for p in ctx.view.real_people() if _mentions(p, _SMOKING)]
        if oxygen and smokers and grounded.step.action in ("handover", "transport"):
            ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "fire_ignition", f"Taking "
                    f"{oxygen[0].label} to {smokers[0].label}, who is smoking: oxygen by a "
                    "lit cigarette burns fiercely.",
                    {"obj": oxygen[0].id, "person": smokers[0].id}, Severity.CRITICAL, _U)
            return


def _oxygen_users(ctx: Context) -> list[PersonView]:
    """People on medical oxygen: said so, or in a room where an oxygen device is on."""
    users = [p for p in ctx.view.real_people() if _mentions(p, (_OXYGEN,))]
    users += [p for p in ctx.view.real_people() if p not in users and any(
        o.room and o.room == p.room and _OXYGEN in o.type.lower()
        and o.properties.get("on") is True for o in ctx.view.objects.values())]
    return users


def _mentions(person: PersonView, words: tuple[str, ...]) -> bool:
    text = " ".join(f"{k} {v}" for k, v in person.properties.items()).lower()
    return any(w in text for w in words)
