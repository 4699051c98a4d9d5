"""Physical hazards of giving, serving or bringing something to a person.

In: the `Context` (grounded steps with a recipient). Out: proposals (sharp_handover,
scald_hot_liquid, chemical_ingestion/exposure, medication_misuse, choking, allergen_exposure,
food_safety) whose severity and preventability follow the recipient's age and condition, and the
critical unknowns (age, allergies, whose medication) when the answer would decide. Never fails.
"""

from __future__ import annotations

from collections.abc import Callable

from app.domain.analysis.context import Context, latest
from app.domain.analysis.grounding import GroundedStep
from app.domain.analysis.questions import phrase_question
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.situation_base import named_people
from app.domain.analysis.traits import Traits, traits_of
from app.domain.analysis.unknowns_people import visiting_or_small
from app.domain.models import Category, Confidence, Level, Preventability, Severity

GIVING_ACTIONS = frozenset({"handover", "serve", "transport", "pour", "heat", "pick"})
_P, _U, _X = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE, Preventability.UNKNOWN
Adder = Callable[..., None]
_OWNER_PRONOUNS: dict[str, str | None] = {"her": "female", "his": "male", "him": "male",
                                          "their": None, "them": None}
_AGE_SENSITIVE = ("sharp", "hot", "toxic", "medication", "small", "alcohol", "ignition")
_AGE_SPANNING_WORDS = frozenset({"girl", "girls", "boy", "boys", "lad", "lass", "youngster"})


def giving_hazards(ctx: Context) -> None:
    """Add the hazards of every non-negated step that hands or serves an object to a person."""
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated:
            continue
        if step.action in GIVING_ACTIONS:
            for person in ctx.people(grounded.recipient):
                for referent in grounded.objects:
                    for obj in ctx.objects(referent):
                        _give(ctx, grounded, obj, traits_of(ctx, obj, referent.mention), person)
                    _mislabelled(ctx, referent.mention.contents or referent.mention.substance,
                                 person)
        elif step.action in _SETTING_OUT and grounded.recipient is None:
            _set_out_for(ctx, grounded)


def _mislabelled(ctx: Context, asked_for: str | None, person: PersonView) -> None:
    """"Pour Ava a glass of the lemonade" when the bottle labelled lemonade holds weedkiller:
    what the command calls it is its label; what she would drink is what is in it."""
    if not asked_for:
        return
    for obj in ctx.view.objects.values():
        label = f"{obj.properties.get('label', '')} {obj.name or ''}".lower()
        if obj.virtual or asked_for.lower() not in label.split():
            continue
        substance = ctx.knowledge.substances.get(obj.contents) if obj.contents else None
        if obj.has("toxic") or obj.has("corrosive") or (
                substance is not None and substance.props & {"toxic", "corrosive"}):
            ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "chemical_ingestion", f"{obj.label} "
                    f"is labelled '{asked_for}' but holds something toxic; {person.label} "
                    "would drink it.", {"obj": obj.id, "person": person.id}, Severity.CRITICAL,
                    _U)
            return


_SETTING_OUT = frozenset({"place", "pour"})
_FOR_TAKING = ("medication", "consumable", "food", "drink")


def _set_out_for(ctx: Context, grounded: GroundedStep) -> None:
    """Medicine or food put into someone's own cup or pot ("two of grandad's pills into her
    pot", "into Nan's beaker") is given to that person, and is judged as a handover."""
    destination = grounded.destination
    owner = destination.mention.owner if destination is not None else None
    if not owner:
        return
    named = [p for p in named_people(ctx) if not p.is_user]
    if owner in _OWNER_PRONOUNS:
        gender = _OWNER_PRONOUNS[owner]
        people = [p for p in named if gender is None or p.gender in (gender, None)]
    else:
        people = [p for p in named if owner in {(p.name or "").lower(), p.role, p.id.lower()}]
    if len(people) != 1:
        return
    for referent in grounded.objects:
        for obj in ctx.objects(referent):
            traits = traits_of(ctx, obj, referent.mention)
            if any(traits.has(t) for t in _FOR_TAKING):
                _give(ctx, grounded, obj, traits, people[0])


def _age(person: PersonView) -> tuple[str | None, Level]:
    if person.age_group:
        return person.age_group, person.age_level
    if person.is_user:
        # The person giving the command is presumed an adult; noted, never critical.
        return "adult", Level.USER
    return None, Level.TASK if person.virtual else Level.DEPLOYMENT


def _give(ctx: Context, grounded: GroundedStep, obj: ObjectView, traits: Traits,
          person: PersonView) -> None:
    age, age_level = _age(person)
    child = age in ("infant", "child")
    young = person.young or age == "infant"
    entities = {"obj": obj.id, "person": person.id}
    who = f"{person.label} ({age.replace('_', ' ')})" if age else person.label
    what = obj.label
    consuming = grounded.step.action in ("serve", "pour", "heat") or ctx.cue("consumption")
    if age is None and any(traits.has(t) for t in _AGE_SENSITIVE):
        ctx.unknown("age_group", f"the age of {person.label}", critical=True,
                    why=f"{what} is only safe to give to someone old enough to handle it",
                    entity=person.id, question=phrase_question("age_group", person.label))

    def add(trait: str, hazard: str, mechanism: str, severity: Severity,
            preventability: Preventability, category: Category = Category.PHYSICAL,
            confidence: Confidence = Confidence.CERTAIN) -> None:
        level = latest(traits.level(trait), age_level if age or trait != "allergen" else
                       Level.TASK)
        ctx.add(level, category, hazard, mechanism, entities, severity, preventability,
                confidence)

    # "the girl", "the boy": a word that fits a five-year-old and a fifteen-year-old alike,
    # old enough for a blade or a hot mug at one age and not at the other.
    vague_child = age == "child" and not young and not person.age_stated and (
        person.role or "").rpartition(" ")[2] in _AGE_SPANNING_WORDS
    if vague_child and (traits.has("sharp") or traits.has("hot")):
        ctx.unknown("age", f"how old {person.label} is", critical=True,
                    why=f"whether a child can safely take {what} depends on their age",
                    entity=person.id, question=phrase_question("age", person.label))
    if traits.has("sharp"):
        if vague_child:
            add("sharp", "sharp_handover", f"Giving {what} to {who}, a child whose age is not "
                "given: a young child cannot handle it safely.", Severity.CRITICAL, _X,
                confidence=Confidence.UNCERTAIN)
        elif child:
            add("sharp", "sharp_handover", f"Giving {what} to {who}, a child who "
                "cannot handle it safely, risks a deep cut.", Severity.CRITICAL, _U)
        elif age is None:
            add("sharp", "sharp_handover", f"Giving {what} to {who}, whose age is "
                "not known, may put it in a child's hands.", Severity.HIGH, _X)
        else:
            add("sharp", "sharp_handover", f"Handing {what} to {who}: the blade "
                "must point away and be offered handle first.", Severity.MODERATE, _P)
    if traits.has("hot"):
        confidence = traits.hot_confidence
        if vague_child:
            add("hot", "scald_hot_liquid", f"Giving {what}, which is hot, to {who}, a child "
                "whose age is not given: a young child spills it and is scalded.",
                Severity.HIGH, _X, confidence=Confidence.UNCERTAIN)
        elif child:
            add("hot", "scald_hot_liquid", f"Giving {what}, which is hot, to {who}: a child "
                "cannot be trusted to hold a hot drink and a spill scalds.",
                Severity.CRITICAL if young else Severity.HIGH, _U, confidence=confidence)
        elif age is None:
            add("hot", "scald_hot_liquid", f"Giving {what}, which is hot, to {who}, whose age "
                "is not known, could scald a child.", Severity.HIGH, _X, confidence=confidence)
        else:
            add("hot", "scald_hot_liquid", f"Carrying and handing {what}, which is hot, to "
                f"{who} risks a scald if it spills.", Severity.MODERATE, _P, confidence=confidence)
    if traits.has("ignition") and not traits.has("heat_source") and (
            child or person.cognitive_state == "impaired"):
        # A lighter or matches: a child (or someone confused) lights what should not burn.
        add("ignition", "fire_ignition", f"Giving {what}, which makes a flame, to {who}, who "
            "cannot be trusted with fire: burns or a house fire.",
            Severity.CRITICAL if young or age == "child" else Severity.HIGH, _U)
    if traits.has("toxic") and not traits.has("medication"):
        if consuming or obj.has("drinking_vessel") or traits.has("drink"):
            add("toxic", "chemical_ingestion", f"Serving {what}, a toxic substance, to {who} "
                "as food or drink can poison them.", Severity.CRITICAL, _U)
        elif child or person.cognitive_state == "impaired":
            add("toxic", "chemical_exposure", f"Giving {what}, which is toxic, to {who}, who "
                "cannot be expected to handle it safely, risks poisoning or burns.",
                Severity.CRITICAL, _U)
        elif age is None:
            add("toxic", "chemical_exposure", f"Giving {what}, which is toxic, to {who}, whose age "
                "is not known, may put a chemical in a child's hands.", Severity.HIGH, _X)
        else:
            add("toxic", "chemical_exposure", f"Handing {what}, which is toxic, to {who}: it must "
                "stay closed and upright.", Severity.LOW, _P)
    if traits.has("medication"):
        _medication(ctx, obj, what, person, who, child, add)
    if traits.has("small") and not traits.has("medication"):
        if young:
            add("small", "choking", f"Giving {what}, small enough to swallow, to {who} is a "
                "choking hazard.", Severity.CRITICAL, _U)
        elif child:
            add("small", "choking", f"Giving {what} to {who}: small pieces can choke a "
                "child; supervision needed.", Severity.MODERATE, _P)
        elif age is None:
            add("small", "choking", f"Giving {what} to {who}, whose age is not known, could "
                "choke a small child.", Severity.HIGH, _X)
    if traits.has("alcohol"):
        if age in ("infant", "child", "teen"):
            add("alcohol", "chemical_ingestion", f"Serving alcohol ({what}) to {who}, a "
                "minor.", Severity.HIGH, _U)
        elif age is None:
            add("alcohol", "chemical_ingestion", f"Serving alcohol ({what}) to {who}, whose "
                "age is not known.", Severity.HIGH, _X)
    if (traits.has("raw") or obj.properties.get("spoiled") or obj.properties.get("expired")
            or (traits.has("infant_unsafe") and age == "infant")):
        add("food", "food_safety", f"Serving {what} to {who}: it is spoiled, raw or unsafe "
            "for them and can make them ill.", Severity.HIGH, _U,
            category=Category.CONSEQUENTIAL)
    if traits.has("allergen") and traits.allergen:
        _allergen(ctx, traits.allergen, what, person, who, add)


def _medication(ctx: Context, obj: ObjectView, what: str, person: PersonView, who: str,
                child: bool, add: Adder) -> None:
    owner = _owner_of(ctx, obj, person)
    if owner == "other":
        add("medication", "medication_misuse", f"Giving {what}, someone else's medication, "
            f"to {who}.", Severity.CRITICAL, _U)
    elif child and owner != "self":
        add("medication", "medication_misuse", f"Giving medication ({what}) to {who}, a "
            "child, risks poisoning.", Severity.CRITICAL, _U)
    elif owner is None:
        add("medication", "medication_misuse", f"Giving medication ({what}) to {who} when it "
            "is not known to be theirs.", Severity.HIGH, _X)
        ctx.unknown("medication_owner", f"whom {what} is prescribed for", critical=True,
                    why="medication given to anyone but the person it is for can harm them",
                    entity=obj.id, question=phrase_question("medication_owner", what,
                                                            person.label))
    else:
        add("medication", "medication_misuse", f"Giving {who} their medication ({what}): "
            "the right dose at the right time only.", Severity.MODERATE, _P)


def _owner_of(ctx: Context, obj: ObjectView, person: PersonView) -> str | None:
    """"self" if the medication is the recipient's, "other" if someone else's, else None."""
    phrase = None
    for grounded in ctx.steps:
        for referent in grounded.objects:
            if obj.id in referent.ids and referent.mention.owner:
                phrase = referent.mention.owner
    phrase = phrase or obj.owner
    if not phrase:
        return None
    names = {person.id.lower(), (person.role or "").lower(), (person.name or "").lower()}
    if phrase in ("her", "him", "them", "their", "his") and not obj.owner:
        # "his medicine" says whose it should be, not which container it is: with no label
        # in the scene, nothing shows this one is his.
        return None
    if phrase in ("her", "him", "them", "their", "his") or phrase in names:
        return "self"
    if phrase in ("me", "my") and person.is_user:
        return "self"
    return "other"


def _allergen(ctx: Context, group: str, what: str, person: PersonView, who: str,
              add: Adder) -> None:
    if person.allergies is None:
        # The household knows its own members' allergies; a visitor's, a baby's, or any the
        # caller says they do not know, must be asked.
        caller_open = any("allerg" in u.lower() for u in (
            ctx.request.user.unknowns if ctx.request.user else ()))
        critical = not person.is_user and (caller_open or visiting_or_small(person, ctx.text))
        ctx.unknown("allergies", f"whether {person.label} is allergic to {group.replace('_', ' ')}",
                    critical=critical,
                    why=f"{what} contains a common allergen ({group.replace('_', ' ')})"
                    + ("" if critical else "; the household knows its own allergies"),
                    entity=person.id, question=phrase_question("allergies", person.label,
                                                               group.replace("_", " ")))
        add("allergen", "allergen_exposure", f"Serving {what} (contains "
            f"{group.replace('_', ' ')}) to {who}, whose allergies are not known.",
            Severity.MODERATE, _P)
        return
    words = {w for a in person.allergies for w in a.replace("_", " ").split()} | set(
        person.allergies)
    allergic = any(ctx.knowledge.allergen_words.get(w) == group or w == group for w in words)
    if allergic:
        add("allergen", "allergen_exposure", f"Serving {what} to {who}, who is allergic to "
            f"{group.replace('_', ' ')}.", Severity.CRITICAL, _U)
