"""Situations where a person's condition, age or state makes the commanded act itself harmful.

In: the `Context` and the situation tables (`knowledge/hazard_situations.json`, substances).
Out: proposals for: hard food given to someone who cannot swallow safely; choking foods fed to a
baby or toddler; a food served to someone allergic to an ingredient of it; medicines that must
not be taken together, or not by that age group, or handed round to several people; a frail or
very young person left alone in the bath or left feeding; acts that startle or touch a sleeping
person; scolding; undressing someone in front of others; personal care the robot has no skill
for. The commanded outcome is the harm, so these are unpreventable. Never fails.
"""

from __future__ import annotations

import re

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep
from app.domain.analysis.scene_view import PersonView
from app.domain.analysis.situation_base import (
    any_phrase,
    contained,
    contains,
    has_condition,
    is_softened,
    load_situations,
    named_people,
    robot_leaves_room,
    substances_in,
)
from app.domain.models import Category, Level, Preventability, Severity

_U = Preventability.UNPREVENTABLE
_S = Severity
_PHYS, _PSY, _OPS = Category.PHYSICAL, Category.PSYCHOLOGICAL, Category.OPERATIONAL
_OUT_OF_WATER = re.compile(r"\b(?:out of|after) (?:the|her|his|their|a) (?:bath|tub|bathtub|"
                           r"shower|pool|paddling pool)\b")
_GIVING = frozenset({"handover", "serve", "transport", "pour", "heat", "misc"})
_GIVING_VERBS = ("give", "feed", "serve", "offer", "bring", "take", "hand", "pass", "make",
                 "prepare", "cook", "pack", "spoon", "fix")


def situation_people_hazards(ctx: Context) -> None:
    """Add the person-centred situation hazards of the whole command."""
    if not any(not g.step.negated for g in ctx.steps):
        return
    _swallowing(ctx)
    _infant_food(ctx)
    _allergy(ctx)
    _medicines(ctx)
    _left_alone(ctx)
    _asleep(ctx)
    _scolding(ctx)
    _exposure(ctx)
    _care_skills(ctx)
    _overdose(ctx)
    _confine(ctx)


def _level(person: PersonView) -> Level:
    return Level.USER if person.is_user else Level.DEPLOYMENT


def _feeds(ctx: Context) -> bool:
    """Whether the command gives, serves or prepares something for someone."""
    return any(not g.step.negated and (g.step.action in _GIVING or (g.step.verb or "").split(
        " ")[0] in _GIVING_VERBS) for g in ctx.steps) or any(
        contains(ctx.text, v) for v in ("feed", "lunch", "lunches", "dinner", "breakfast",
                                         "snack", "tea"))


def _recipients(ctx: Context) -> list[PersonView]:
    """People something is given to: parsed recipients, else the people the command names."""
    found = [p for g in ctx.steps if not g.step.negated for p in ctx.people(g.recipient)
             if not p.virtual]
    found += [p for g in ctx.steps if not g.step.negated and (g.step.verb or "") in (
        "feed", "spoon-feed") for r in g.objects for p in ctx.people(r) if not p.virtual]
    return list({p.id: p for p in found}.values()) or named_people(ctx)


def _foods(ctx: Context, group: str) -> list[str]:
    data = load_situations()
    words = data.group(group)
    softening = data.group("softening_words")
    return [w for w in contained(ctx.text, words) if not is_softened(ctx.text, w, softening)]


def _swallowing(ctx: Context) -> None:
    if not _feeds(ctx):
        return
    foods = _foods(ctx, "hard_foods")
    if not foods:
        return
    for person in _recipients(ctx):
        if has_condition(ctx, person, "dysphagia"):
            ctx.add(_level(person), _PHYS, "choking", f"Giving {foods[0]} to {person.label}, "
                    "who cannot swallow safely: solid or hard food chokes them.",
                    {"person": person.id}, _S.CRITICAL, _U)


def _infant_food(ctx: Context) -> None:
    if not _feeds(ctx):
        return
    foods = _foods(ctx, "infant_choking_foods")
    if not foods:
        return
    for person in _recipients(ctx):
        if (person.young or person.age_group == "infant"):
            ctx.add(_level(person), _PHYS, "choking", f"Feeding {foods[0]} to {person.label} "
                    f"({person.age_group}): whole or round foods like this choke small children.",
                    {"person": person.id}, _S.CRITICAL, _U)


def _allergy(ctx: Context) -> None:
    if not _feeds(ctx):
        return
    groups = {ctx.knowledge.substances[s].allergen for s in substances_in(ctx, ctx.text)}
    groups.discard(None)
    if not groups:
        return
    for person in _recipients(ctx):
        if not person.allergies:
            continue
        words = {w for a in person.allergies for w in (a, *a.replace("_", " ").split())}
        allergic = {ctx.knowledge.allergen_words.get(w, w) for w in words}
        for group in sorted(g for g in groups if g in allergic):
            ctx.add(_level(person), _PHYS, "allergen_exposure", f"Preparing or serving food "
                    f"that contains {group.replace('_', ' ')} for {person.label}, who is "
                    "allergic to it.", {"person": person.id}, _S.CRITICAL, _U)


def _clause_substances(ctx: Context, grounded: GroundedStep) -> list[str]:
    found = substances_in(ctx, grounded.step.text)
    for ref in (*grounded.objects, grounded.instrument):
        for obj in ctx.objects(ref):
            if obj.contents and obj.contents not in found:
                found.append(obj.contents)
    return found


def _medicines(ctx: Context) -> None:
    data = load_situations()
    pairs = [tuple(r["classes"]) for r in data.records["interactions"]]
    limits = data.records["age_limits"]
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or not (step.action in _GIVING or grounded.recipient):
            continue
        names = _clause_substances(ctx, grounded)
        records = [ctx.knowledge.substances[n] for n in names]
        classes = [c for r in records for c in r.classes]
        people = [p for p in ctx.people(grounded.recipient) if not p.virtual]
        for a, b in pairs:
            same = a == b and len([c for c in classes if c == a]) > 1
            if (a != b and a in classes and b in classes) or same:
                why = next(r["why"] for r in data.records["interactions"]
                           if tuple(r["classes"]) == (a, b))
                ctx.add(Level.TASK, _PHYS, "medication_misuse", f"Giving these together: "
                        f"{why}.", {"person": people[0].id if people else None},
                        _S.CRITICAL, _U)
        adult_only = any_phrase(step.text, data.group("adult_only_words")) is not None
        medicine = any("medication" in r.props for r in records)
        for person in people:
            for record in records:
                for tag, limit in limits.items():
                    if tag in record.props and person.age_group in limit["groups"]:
                        ctx.add(_level(person), _PHYS, "medication_misuse", f"Giving "
                                f"{record.name.replace('_', ' ')} to {person.label} "
                                f"({person.age_group}): {limit['why']}.",
                                {"person": person.id}, _S.CRITICAL, _U)
            if adult_only and medicine and person.age_group in ("infant", "child"):
                ctx.add(_level(person), _PHYS, "medication_misuse", f"Giving an adults' "
                        f"medicine to {person.label}, a child.", {"person": person.id},
                        _S.CRITICAL, _U)
        _handed_round(ctx, grounded, medicine)


def _handed_round(ctx: Context, grounded: GroundedStep, medicine: bool) -> None:
    """One drawer's or trolley's medicine handed to several people cannot be each one's own."""
    data = load_situations()
    text = ctx.text
    many = any_phrase(grounded.step.text, data.group("multi_recipient_words"))
    if not many or any_phrase(text, data.group("own_medication_words")):
        return
    meds_named = medicine or any(ctx.knowledge.noun_concept(w) == "medication" for w in
                                 text.split()) or any(o.has("medication") or o.owner for r in
                                                      grounded.objects for o in ctx.objects(r))
    if meds_named and any_phrase(grounded.step.text, data.group("unknown_content_words")):
        ctx.add(Level.TASK, _PHYS, "medication_misuse", "Handing the same medication to "
                "several people: it is prescribed for one person at most.", {},
                _S.CRITICAL, _U)


def _left_alone(ctx: Context) -> None:
    data = load_situations()
    text = ctx.text
    # Put in the water, then the robot goes off elsewhere: that too leaves them alone in it.
    put_in_water = any_phrase(text, data.group("in_water_words")) and robot_leaves_room(ctx)
    if not (any_phrase(text, data.group("left_alone_words")) or put_in_water):
        return
    # "out of the bath", "after her bath": the bath is over, nobody is left in the water.
    bathing = any_phrase(_OUT_OF_WATER.sub(" ", text), data.group("bathing_words"))
    feeding = any_phrase(text, data.group("self_feeding_words"))
    people = named_people(ctx) or ([p for p in ctx.view.real_people() if not p.is_user]
                                    if any(contains(text, w) for w in ("them", "they",
                                                                       "themselves")) else [])
    for person in people:
        very_young = person.young or person.age_group == "infant"
        if bathing and (person.frail or very_young or person.cognitive_state == "impaired"):
            where = bathing if bathing.startswith(("in ", "into ")) else f"in the {bathing}"
            ctx.add(_level(person), _PHYS, "fall_from_height", f"Leaving {person.label} alone "
                    f"{where}: a frail, confused or very young person can fall or drown.",
                    {"person": person.id}, _S.CRITICAL, _U)
        if feeding and very_young:
            ctx.add(_level(person), _PHYS, "choking", f"Leaving {person.label} to feed alone: "
                    "a baby feeding unwatched can choke.", {"person": person.id},
                    _S.CRITICAL, _U)


def _asleep(ctx: Context) -> None:
    data = load_situations()
    act = any_phrase(ctx.text, data.group("startle_acts")) or any_phrase(
        ctx.text, data.group("body_acts"))
    if not act:
        return
    for person in named_people(ctx):
        if person.asleep:
            fragile = person.frail or person.child
            ctx.add(_level(person), _PSY, "startling", f"Doing this ({act}) to {person.label} "
                    "while they sleep: it startles them and they cannot consent.",
                    {"person": person.id}, _S.CRITICAL if fragile else _S.HIGH, _U)


def _scolding(ctx: Context) -> None:
    data = load_situations()
    act = any_phrase(ctx.text, data.group("scold_acts")) or (
        "telling off" if re.search(data.records["scold_pattern"], ctx.text) else None)
    if not act:
        return
    for person in named_people(ctx):
        vulnerable = person.cognitive_state == "impaired" or person.frail or person.child
        ctx.add(_level(person), _PSY, "intimidation", f"Scolding or shouting at {person.label}"
                f"{', who is vulnerable' if vulnerable else ''}, is intimidating.",
                {"person": person.id}, _S.HIGH, _U)


def _exposure(ctx: Context) -> None:
    data = load_situations()
    if not any_phrase(ctx.text, data.group("undress_acts")):
        return
    public = any_phrase(ctx.text, data.group("public_exposure_words"))
    for person in named_people(ctx):
        others = [p for p in ctx.view.people_in(person.room) if p.id != person.id
                  and not p.is_user]
        if public or (others and any(contains(ctx.text, w) for w in (
                "lounge", "living room", "dining room", "dining hall", "hallway", "corridor"))):
            ctx.add(_level(person), _PSY, "dignity_violation", f"Undressing {person.label} "
                    "where others can see.", {"person": person.id}, _S.HIGH, _U)


def _care_skills(ctx: Context) -> None:
    robot = ctx.request.robot
    if robot is None or robot.skills is None:
        return
    have = {s.lower().replace("-", "_").replace(" ", "_") for s in robot.skills}
    tasks = load_situations().records["care_tasks"].items()
    missing = [(name, task, word) for name, task in tasks
               if (word := any_phrase(ctx.text, task["words"])) and have.isdisjoint(task["skills"])]
    if not missing or not (named_people(ctx) or any(
            contains(ctx.text, w) for w in ("her", "him", "them", "his"))):
        return  # a care task the robot cannot do, done for someone
    for name, task, word in missing:
        ctx.add(Level.USER, _OPS, "missing_skill", f"{task['what'].capitalize()} ('{word}') "
                f"needs a care skill ({name.replace('_', ' ')}) the robot does not list.", {},
                _S.HIGH, _U)


def _overdose(ctx: Context) -> None:
    """More medicine than the dose ("a double dose", "another dose") is an overdose."""
    data = load_situations()
    word = any_phrase(ctx.text, data.group("overdose_words"))
    if not word:
        return
    medicine = any("medication" in ctx.knowledge.substances[n].props
                   for n in substances_in(ctx, ctx.text)) or any(
        ctx.knowledge.noun_concept(w) == "medication" for w in ctx.text.split())
    if word and medicine and _feeds(ctx):
        ctx.add(Level.TASK, _PHYS, "medication_misuse", f"Giving more than the prescribed dose "
                f"('{word}') risks an overdose.", {}, _S.CRITICAL, _U)


def _confine(ctx: Context) -> None:
    """Locking a person in a room or tying them down restrains them against their will."""
    for match in re.finditer(load_situations().records["confine_pattern"], ctx.text):
        people = named_people(ctx, match.group(0))
        words = match.group(0).split()
        if people or any(w in ctx.knowledge.role_words for w in words):
            who = people[0] if people else None
            ctx.add(Level.TASK, _PSY, "intimidation", "Locking someone in or tying them down "
                    "confines them against their will.", {"person": who.id if who else None},
                    _S.HIGH, _U)
            return
