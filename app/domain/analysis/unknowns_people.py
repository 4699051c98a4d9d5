"""Unknown facts about people that decide whether a task is safe.

In: the `Context`, the command's `Involvement` and the `UnknownRules` tables. Out (appended to
the context as `UnknownFact`s, each with a plain question and the person or object as entity):
the age and allergies of visitors, children and infants who will eat an allergen, a choking
food or an infant-unsafe food; the age of someone a hot, sharp or intoxicating thing is
prepared for; where a listed person is when something can crush them, when noise or fumes
spread or when the robot speeds; whether anyone stays home to watch something left running;
the condition of a frail person served hot food in care or left alone; whose unlabelled
medication it is and when an as-needed medicine was last taken. A fact the scene gives is never
asked. Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.involvement import Involvement, plain_name
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.unknown_rules import UnknownRules, has_phrase, load_unknown_rules
from app.domain.analysis.unknowns_choices import open_choice_items

_DELIVERING = frozenset({"serve", "handover", "transport", "pour", "place", "heat"})
_HOT_WORDS = ("hot", "boiling", "scalding", "steaming")


def _stated_age(person: PersonView) -> bool:
    """Whether the person's age is given, not just implied by a loose word like "kid"."""
    props = person.properties
    return bool(props.get("age_group") or props.get("age") or props.get("age_years")) or (
        person.age_group in ("infant", "teen", "adult", "older_adult") or person.young)


def _visitor(person: PersonView, text: str, rules: UnknownRules) -> bool:
    words = rules.group("consumers.visitor_words")
    # "the neighbour's boy" is a visitor as much as "the neighbour" is.
    role, text = (person.role or "").replace("'s", ""), text.replace("'s", "")
    return person.role_class == "guest" or has_phrase(role, words) is not None or (
        has_phrase(text, words) is not None and not person.is_user)


def visiting_or_small(person: PersonView, text: str) -> bool:
    """Whether the household may not know the person's allergies: a visitor, a baby or a
    toddler (adults and children who live here are presumed known to the caller).

    Args:
        person: the person who will eat.
        text: the lower-case command.

    Returns:
        True when their allergies must be asked before they are given an allergen.
    """
    rules = load_unknown_rules()
    return _visitor(person, text, rules) or person.young or person.age_group == "infant"


def _allergens(ctx: Context, obj: ObjectView, words: str) -> list[str]:
    found = [str(a).lower() for a in obj.properties.get("allergens", []) or []]
    if obj.contents and ctx.knowledge.substances[obj.contents].allergen:
        found.append(str(ctx.knowledge.substances[obj.contents].allergen))
    found += [g for w, g in ctx.knowledge.allergen_words.items() if has_phrase(words, (w,))]
    return sorted(set(found))


def consumer_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask visitors' and small children's allergies and ages before they eat risky food."""
    eaters = inv.others()
    # Food carried to named people is food for them, as much as food served.
    serving = inv.actions & {"serve", "heat"} or inv.recipients or has_phrase(
        inv.text, rules.group("consumers.serving_words")) or (
        eaters and inv.actions & {"transport", "handover"})
    if has_phrase(inv.text, rules.group("consumers.visitor_words")) and not any(
            _visitor(p, "", rules) for p in eaters):  # no listed guest: they are not in the scene
        _visitors_food(ctx, inv, rules)  # "bake flapjacks for when Chloe's friends come over"
    if not serving or not eaters:
        return
    # The caller saying they do not know someone's allergies opens them for every eater.
    caller_open = any("allerg" in u.lower() for u in (
        ctx.request.user.unknowns if ctx.request.user else ()))
    for obj in [*inv.objects.values(), *open_choice_items(ctx, inv, rules)]:
        words = inv.words_of(obj)
        if not (obj.has("food") or obj.has("consumable") or obj.has("allergen")
                or obj.contents or obj.properties.get("allergens")
                or has_phrase(words, rules.group("consumers.choking_foods"))):
            continue
        allergens = _allergens(ctx, obj, words)
        choking = has_phrase(words, rules.group("consumers.choking_foods"))
        infant_unsafe = has_phrase(words, rules.group("consumers.infant_unsafe_foods")) or (
            obj.has("infant_unsafe"))
        for person in eaters:
            if allergens and person.allergies is None and (
                    caller_open or visiting_or_small(person, inv.text)):
                group = ", ".join(a.replace("_", " ") for a in allergens)
                ctx.unknown("allergies", f"whether {person.label} is allergic to {group}",
                            critical=True, why=f"{plain_name(obj)} contains {group}, a common "
                            "allergen, and nothing says whether they can eat it",
                            entity=person.id, question=f"Is {person.label} allergic to {group}?")
            if (choking or infant_unsafe) and not _stated_age(person):
                risk = choking or "honey"
                ctx.unknown("age_group", f"the age of {person.label}", critical=True,
                            why=f"{risk} is unsafe for babies and small children",
                            entity=person.id, question=f"How old is {person.label}? "
                            f"{risk.capitalize()} is not safe for very young children.")


def _visitors_food(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Food with a common allergen made for visitors the scene does not list: nobody has said
    what they are allergic to."""
    if not (inv.actions & {"serve", "heat", "place", "handover", "transport", "cut", "mix"}):
        return
    allergens = sorted({a.replace("_", " ").removesuffix("s") for obj in inv.objects.values()
                        for a in _allergens(ctx, obj, inv.words_of(obj))})
    if allergens:
        group = ", ".join(a.replace("_", " ") for a in allergens)
        ctx.unknown("allergies", f"whether the visitors are allergic to {group}", critical=True,
                    why=f"the food has {group}, a common allergen, and it is for visitors "
                    "whose allergies nobody has given", entity=None,
                    question=f"Are any of the visitors allergic to {group}?")


def recipient_age_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask the age of someone a hot, sharp, toxic or intoxicating thing is meant for."""
    hot_words = has_phrase(inv.text, _HOT_WORDS)
    for person in inv.others():
        if person.age_group is not None:
            continue
        for obj in inv.objects.values():
            named_hot = hot_words and has_phrase(inv.named_by.get(obj.id, ""), _HOT_WORDS)
            if named_hot or any(obj.has(t) for t in ("sharp", "alcohol", "hot")) or (
                    obj.has("toxic") and obj.has("medication")):
                ctx.unknown("age_group", f"the age of {person.label}", critical=True,
                            why=f"{plain_name(obj)} is only safe for someone old enough to "
                            "handle it", entity=person.id,
                            question=f"How old is {person.label}?")
                break


def location_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask where a listed person is when something can crush them, noise spreads or the robot
    speeds."""
    lost = [p for p in ctx.view.people.values()
            if p.room is None and not p.virtual and not p.is_user]
    if not lost:
        return
    crushing = next((o for o in inv.objects.values() if _crushes(o, inv, rules)), None)
    if crushing is not None and not (inv.unparsed or inv.actions & set(
            rules.group("location.crushing_actions"))):
        crushing = None
    noise = has_phrase(inv.text, rules.group("location.noise_words") +
                       rules.group("location.fume_words"))
    speeding = has_phrase(inv.text, ctx.knowledge.cues.get("max_speed", ()))
    for person in lost:
        sensitive = person.young or person.age_group == "infant" or person.asleep or (
            person.frail and person.age_group != "adult")
        at_risk = person.child or person.frail or person.age_group is None
        if crushing is not None and at_risk:
            about = plain_name(crushing)
            reason = f"{about} can crush or trap someone in its way"
        elif speeding and at_risk:
            reason, about = "the robot will move fast and could knock them over", "the robot"
        elif noise and sensitive:
            reason, about = f"the {noise} would wake or distress them nearby", f"the {noise}"
        else:
            continue
        ctx.unknown("person_location", f"where {person.label} is right now", critical=True,
                    why=reason, entity=person.id,
                    question=f"Where is {person.label} right now? I need to know they are clear "
                    f"of {about}.")


def _crushes(obj: ObjectView, inv: Involvement, rules: UnknownRules) -> bool:
    words = inv.words_of(obj)
    if has_phrase(words, rules.group("location.crushing_words")):
        return True
    door_like = obj.has("door") or has_phrase(words, ("door", "gate", "shutter", "hatch"))
    return bool(door_like) and any(
        str(obj.properties.get(k, "")).lower() in ("true", "1", "yes")
        for k in rules.group("location.crushing_properties"))


def attendance_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask whether anyone stays home to watch something the command leaves running."""
    text = inv.text
    running = has_phrase(text, rules.group("attendance.running_words"))
    if running is None:
        return
    machine_only = running in rules.group("attendance.unattended_machines_need_leaving")
    leaving = has_phrase(text, rules.group("attendance.away_words")) is not None
    heating = bool(inv.actions & {"switch_on", "heat"})
    keep_on = has_phrase(text, rules.group("attendance.leave_running_words"))
    # Switching the thing off before going is the safe way to leave; nothing runs on.
    if "switch_off" in inv.actions and not keep_on:
        return
    if not (heating or keep_on) or not (leaving or (keep_on and not machine_only)):
        return
    present = [p for p in ctx.view.people.values()
               if not p.virtual and p.room is not None and not p.asleep]
    if present and not leaving:
        return
    target = next((o for o in inv.objects.values() if has_phrase(inv.words_of(o), (running,))),
                  None) or next(iter(inv.objects.values()), None)
    what = plain_name(target) if target is not None else f"the {running}"
    ctx.unknown("presence", f"whether someone stays at home to watch {what}", critical=True,
                why=f"{what} left running with nobody watching can start a fire or flood",
                entity=target.id if target is not None else None,
                question=f"Will someone stay at home to watch {what} while it runs?")


def condition_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask the condition of a frail person served hot food in care, or left on their own."""
    frail = [p for p in inv.others() if p.cognitive_state is None and (
        p.frail or p.age_group == "older_adult")]
    if not frail:
        return
    care = any(has_phrase(r.replace("_", " "), rules.group("condition.care_rooms"))
               for r in ctx.view.rooms) or any(
        has_phrase(p.role or "", rules.group("condition.care_roles"))
        for p in ctx.view.people.values() if p.role_class != "older_adult")
    alone = any(p.search(inv.text) for p in rules.left_alone)
    hot = [o for o in inv.objects.values() if (o.has("hot") or str(
        o.properties.get("temperature", "")).lower() == "hot") and not any(
        str(o.properties.get(k, "")).lower() in ("true", "1") for k in ("lidded", "sealed",
                                                                       "covered"))]
    delivering = bool(inv.actions & {"serve", "handover", "transport"})
    for person in frail:
        if alone:
            why = f"whether {person.label} can be left alone safely depends on their condition"
            question = (f"Can {person.label} safely be left alone? Are they able to call for "
                        "help or move if they need to?")
        elif care and hot and delivering:
            why = f"some residents cannot hold {plain_name(hot[0])} safely while it is hot"
            question = f"Can {person.label} safely manage {plain_name(hot[0])} while it is hot?"
        else:
            continue
        ctx.unknown("cognitive_state", f"the condition of {person.label}", critical=True,
                    why=why, entity=person.id, question=question)


def medication_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask whose unlabelled medication it is, and when an as-needed one was last taken."""
    consumption = has_phrase(inv.text, ctx.knowledge.cues.get("consumption", ()))
    if not inv.actions & _DELIVERING and not consumption:
        return
    others = [p for p in ctx.view.people.values() if not p.virtual and not p.is_user]
    caller_dose = any(has_phrase(u.lower(), rules.group("medication.caller_unknown_words"))
                      for u in (ctx.request.user.unknowns if ctx.request.user else ()))
    scheduled = has_phrase(inv.text, rules.group("medication.scheduled_holders"))
    for obj in inv.objects.values():
        if not obj.has("medication"):
            continue
        words = inv.words_of(obj)
        owned = obj.owner or "'s " in f"{inv.named_by.get(obj.id, '')} " or has_phrase(
            inv.named_by.get(obj.id, ""), ("my", "his", "her", "their", "own"))
        if not owned and others:
            ctx.unknown("medication_owner", f"whom {plain_name(obj)} is for", critical=True,
                        why="medication given to anyone but the person it is for can harm them",
                        entity=obj.id, question=f"Whose medication is {plain_name(obj)}, and who "
                        "should get which dose?")
        as_needed = has_phrase(words, rules.group("medication.as_needed"))
        dose_known = any(k in obj.properties for k in rules.group(
            "medication.dose_known_properties")) or scheduled or has_phrase(
            words, rules.group("medication.scheduled_holders"))
        if (as_needed or caller_dose) and not dose_known and others:
            ctx.unknown("last_dose", f"when {plain_name(obj)} was last taken", critical=True,
                        why="another dose too soon can be an overdose", entity=obj.id,
                        question=f"When was the last dose of {plain_name(obj)} taken?")
