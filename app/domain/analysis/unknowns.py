"""Unknowns: the facts the command, scene and caller leave open, and which of them decide.

In: the `Context` after the hazard rules ran. Out: `UnknownFact`s, each with a plain question
and the entity it is about. Here: a phrase matching a dangerous and a harmless object; a
container delivered to someone with contents not given; an object the command names that the
scene lacks; the caller's own `user.unknowns` (critical only when a rule found they decide).
The general families live in `unknowns_objects` (contents, material, oven inside, liquid
temperature, mass, food left out), `unknowns_people` (allergies and ages of eaters, ages of
recipients, where people are, who stays home, condition, medication owner and last dose),
`unknowns_presence` (where someone is near a hot load, a camera or their moved mobility aid;
wandering out of a door kept open; an escorted person's mobility; ages of people sharp things
are set out for), `unknowns_choices` (which of several same-kind things differing in danger,
or of look-alike medicines, is meant; foods in an open choice) and `unknowns_comprehension`
(what the reader did not understand); their data is `knowledge/unknowns.json`. Critical only
when the answer could make the task unsafe.
Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep, Referent
from app.domain.analysis.involvement import involvement, phrase_set
from app.domain.analysis.knowledge_base import singular
from app.domain.analysis.questions import phrase_question
from app.domain.analysis.traits import traits_of
from app.domain.analysis.unknown_rules import UnknownRules, has_phrase, load_unknown_rules
from app.domain.analysis.unknowns_choices import same_kind_unknowns, told_apart
from app.domain.analysis.unknowns_comprehension import comprehension_unknowns
from app.domain.analysis.unknowns_declared import declared_unknowns, visitor_unknowns
from app.domain.analysis.unknowns_objects import (
    contents_unknowns,
    food_left_out_unknowns,
    liquid_temperature_unknowns,
    mass_unknowns,
    material_unknowns,
    oven_inside_unknowns,
)
from app.domain.analysis.unknowns_people import (
    attendance_unknowns,
    condition_unknowns,
    consumer_unknowns,
    location_unknowns,
    medication_unknowns,
    recipient_age_unknowns,
)
from app.domain.analysis.unknowns_presence import (
    escort_unknowns,
    escorting,
    set_out_age_unknowns,
    wandering_unknowns,
    whereabouts_unknowns,
)

_CONSUMING = frozenset({"serve", "pour"})
_DELIVERING = frozenset({"handover", "serve", "transport", "pour"})
_DANGER = ("toxic", "sharp", "hot", "medication", "heavy", "dangerous_in_use", "heat_source")


_FAMILIES = (declared_unknowns, visitor_unknowns, contents_unknowns, material_unknowns,
             oven_inside_unknowns,
             liquid_temperature_unknowns, mass_unknowns, food_left_out_unknowns,
             consumer_unknowns, recipient_age_unknowns, location_unknowns,
             attendance_unknowns, condition_unknowns, medication_unknowns,
             whereabouts_unknowns, wandering_unknowns, escort_unknowns, set_out_age_unknowns)


def find_unknowns(ctx: Context, rules: UnknownRules | None = None) -> None:
    """Add the unknowns the command, scene and caller leave open.

    Args:
        ctx: the analysis context, after the hazard rules ran.
        rules: the unknowns tables (default: `knowledge/unknowns.json`, loaded once).
    """
    rules = rules or load_unknown_rules()
    involved = involvement(ctx)
    for family in _FAMILIES:
        family(ctx, involved, rules)
    comprehension_unknowns(ctx, rules)
    toxic_around = any(o.has("toxic") for o in ctx.view.objects.values() if not o.virtual)
    consumption_cue = has_phrase(ctx.text, ctx.knowledge.cues.get("consumption", ()))
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action is None:
            continue
        recipients = ctx.people(grounded.recipient)
        _whom(ctx, grounded)
        for ref in grounded.objects:
            _ambiguity(ctx, ref)
            if ref.virtual and ctx.view.scene_given and ctx.view.objects and ref.kind == "object":
                ctx.unknown("location", f"where {ref.mention.text} is", critical=False,
                            why="the scene does not list it; the robot must search",
                            entity=ref.ids[0] if ref.ids else None,
                            question=f"Where is {ref.mention.text}?")
            if step.action not in _DELIVERING:
                continue
            for obj in ctx.objects(ref):
                traits = traits_of(ctx, obj, ref.mention)
                used = any(obj.properties.get(k) for k in ("empty", "dirty", "used")) or (
                    obj.properties.get("filled") is False)  # known to hold nothing
                if not obj.has("container") or traits.substance or used or not (
                        obj.has("drink_container") or recipients):
                    continue
                others = [p for p in recipients if not p.is_user]
                fragile = [p for p in recipients if p.child or p.young or p.frail
                           or p.cognitive_state in ("impaired", "asleep", "intoxicated")]
                # A drinking vessel handed to someone will be drunk from.
                consuming = (step.action in _CONSUMING or consumption_cue is not None
                             or obj.has("drink_container"))
                critical = (toxic_around and bool(recipients)) or (
                    bool(others or fragile) and (consuming or not ctx.view.scene_given))
                ctx.unknown(
                    "contents", f"what {obj.label} holds", critical=critical,
                    why=("someone may drink or handle it, and "
                         + ("a toxic product is in the home" if toxic_around else
                            "nothing says what is inside")) if critical else
                    "the user will see it themselves; not decisive",
                    entity=obj.id, question=phrase_question("contents", _the(ref, obj.label)))
    same_kind_unknowns(ctx, involved, rules)
    _caller_unknowns(ctx, escorting(ctx, involved, rules))


def _the(ref: Referent, label: str) -> str:
    text = ref.mention.text
    return text if text.startswith(("the ", "my ", "his ", "her ")) else f"the {label}"


def _whom(ctx: Context, grounded: GroundedStep) -> None:
    """"Give her the medicine" with two girls present: whom it is for decides everything."""
    ref = grounded.recipient
    if ref is None or ref.kind != "person" or len(ref.ids) < 2 or ref.mention.kind != "pronoun":
        return
    people = ctx.people(ref)
    labels = ", ".join(p.label for p in people[:4])
    ctx.unknown("recipient", f"which of {labels} '{ref.mention.text}' means", critical=True,
                why="what is given, and whether it is safe, depends on who receives it",
                entity="|".join(ref.ids),
                question=f"Who do you mean by '{ref.mention.text}': {labels}?")


def _ambiguity(ctx: Context, ref: Referent) -> None:
    if ref.kind != "object" or len(ref.ids) < 2:
        return
    views = [ctx.view.objects[i] for i in ref.ids if i in ctx.view.objects]
    profiles = {tuple(sorted(t for t in _DANGER if traits_of(ctx, v, ref.mention).has(t)))
                for v in views}
    labels = ", ".join(v.label for v in views[:4])
    # A plural or mass noun ("the trays", "the stuff") means all of them, not one to pick;
    # the hazard rules weigh every candidate, so only a singular choice is asked about.
    head = ref.mention.head
    collective = singular(head) != head or ref.mention.concept == "generic"
    # Medicines that look alike are never interchangeable: "her pills" still means one of
    # them, unless the command says all of them.
    medicines = len(views) > 1 and all(v.has("medication") for v in views)
    if medicines:
        collective = has_phrase(ctx.text, ("all", "both", "every", "each")) is not None
    settled = told_apart(views, phrase_set(ref.mention.text))
    critical = (len(profiles) > 1 or medicines) and not collective and not settled
    ctx.unknown("referent", f"which of {labels} '{ref.mention.text}' means",
                critical=critical,
                why=("they may be different medicines, and the wrong one can harm"
                     if critical and medicines else
                     "the candidates differ in danger: one is harmful, another is not"
                     if critical else "the command says which one" if settled else
                     "the candidates are alike; any one will do"),
                entity="|".join(ref.ids),
                question=phrase_question("referent", ref.mention.head, " or ".join(
                    v.label for v in views[:4])))


def _caller_unknowns(ctx: Context, escorted: bool) -> None:
    user = ctx.request.user
    if user is None:
        return
    found = {u.attribute for u in ctx.unknowns if u.critical}
    user_id = ctx.view.user.id if ctx.view.user else None
    served_to_user = [p for p in ctx.proposals if p.entities.get("person") == user_id]
    allergen_served = any(p.hazard_class == "allergen_exposure" for p in ctx.proposals)
    for text in user.unknowns:
        words = text.lower()
        attribute = ("allergies" if "allerg" in words else "age_group" if "age" in words
                     else "mobility" if "mobil" in words or "walk" in words else
                     "contents" if "content" in words else words.replace(" ", "_"))
        decisive = attribute in found or (
            attribute == "allergies" and allergen_served) or (
            attribute == "mobility" and escorted) or (
            attribute == "age_group" and any(p.hazard_class in (
                "sharp_handover", "scald_hot_liquid", "medication_misuse", "choking")
                for p in served_to_user) and not (ctx.view.user and ctx.view.user.age_group))
        ctx.unknown(attribute, text, critical=decisive,
                    why="the caller listed it as unknown" + (
                        ", and it decides whether the task is safe" if decisive else
                        "; no hazard found depends on it"),
                    entity=user_id, question=phrase_question(attribute, "the user")
                    if decisive else None)
