"""Unknown facts about people near what the robot does: where they are, how they move, their
condition and age.

In: the `Context`, the command's `Involvement` and the `UnknownRules` tables (`presence.*`).
Out (appended to the context as critical `UnknownFact`s, each with a plain question and the
person as entity): where a child is when something hot is carried through the home; where
someone is when the robot takes photos or films; where someone is when their wheelchair or
walking frame is moved; whether an older person may wander when an outside door is left open
for them; how well an older or frail person walks when the robot escorts them; how old the
people are that sharp, toxic or intoxicating things are laid out for. A fact the scene gives is
never asked. Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.involvement import Involvement, plain_name
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.unknown_rules import UnknownRules, has_phrase

_TRUE = ("true", "1", "yes")


def _unplaced(ctx: Context) -> list[PersonView]:
    return [p for p in ctx.view.people.values()
            if p.room is None and not p.virtual and not p.is_user]


def _ask_where(ctx: Context, person: PersonView, why: str, clear_of: str) -> None:
    if any(u.attribute == "person_location" and u.entity == person.id and u.critical
           for u in ctx.unknowns):
        return
    ctx.unknown("person_location", f"where {person.label} is right now", critical=True,
                why=why, entity=person.id,
                question=f"Where is {person.label} right now? I need to know they are clear "
                f"of {clear_of}.")


def _hot(obj: ObjectView, inv: Involvement) -> bool:
    named = inv.named_by.get(obj.id, "")
    return obj.has("hot") or str(obj.properties.get("temperature", "")).lower() in (
        "hot", "boiling", "scalding") or has_phrase(named, ("hot", "boiling", "steaming",
                                                            "scalding")) is not None


def whereabouts_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask where an unplaced person is when a hot load passes, a camera is used or their
    mobility aid is moved."""
    unplaced = _unplaced(ctx)
    if not unplaced:
        return
    hot = next((o for o in inv.objects.values() if _hot(o, inv)), None)
    if hot is not None and "transport" in inv.actions:
        for person in unplaced:
            if person.child or person.young:
                _ask_where(ctx, person, f"{plain_name(hot)} is carried through the home and "
                           "a child could run into its path", plain_name(hot))
    if has_phrase(inv.text, rules.group("presence.capture_words")):
        for person in unplaced:
            _ask_where(ctx, person, "they could be photographed or filmed without agreeing",
                       "the camera")
    if inv.actions & set(rules.group("presence.moving_aid_actions")):
        _moved_aid_unknowns(ctx, inv, rules, unplaced)


def _moved_aid_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules,
                        unplaced: list[PersonView]) -> None:
    """A mobility aid, or something of a person who relies on one, is moved while nobody
    knows where that person is: they may be sitting in it or need it beside them."""
    aids = [o for o in inv.objects.values() if o.has("walking_aid")]
    for person in unplaced:
        reliant = has_phrase(str(person.mobility or "").lower(),
                             rules.group("presence.reliant_mobility")) is not None
        owned = [o for o in inv.objects.values() if person.name and has_phrase(
            inv.named_by.get(o.id, ""), (f"{person.name.lower()}'s",))]
        moved = owned if reliant and owned else aids if (reliant or owned) else []
        if moved:
            _ask_where(ctx, person, f"they may be sitting in {plain_name(moved[0])} or need "
                       "it beside them", plain_name(moved[0]))


def _exit_left_open(ctx: Context, inv: Involvement, rules: UnknownRules) -> ObjectView | None:
    text = inv.text
    doors = [o for o in inv.objects.values()
             if str(o.properties.get("exterior", "")).lower() in _TRUE
             or has_phrase(inv.words_of(o), rules.group("presence.exit_words"))]
    opening = inv.actions & set(rules.group("presence.exit_actions")) or has_phrase(
        text, rules.group("presence.exit_open_words"))
    # Opening a door to let someone in is brief; only a door kept open stays a way out.
    kept = has_phrase(text, rules.group("presence.exit_keep_words"))
    return doors[0] if doors and opening and kept and "close" not in inv.actions else None


def wandering_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask whether an older person may wander when an outside door is left open for them."""
    door = _exit_left_open(ctx, inv, rules)
    if door is None:
        return
    for person in inv.others():
        if person.cognitive_state is not None or person.age_group != "older_adult":
            continue
        ctx.unknown("cognitive_state", f"whether {person.label} might wander out",
                    critical=True, why=f"with {plain_name(door)} open, an older person with "
                    "memory problems can walk out and get lost or hurt", entity=person.id,
                    question=f"Is it safe to leave {plain_name(door)} open with {person.label} "
                    "at home? Might they wander out?")


def escort_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask how well an older or frail person walks before the robot escorts them."""
    escorted = _escorted(ctx, inv, rules)
    for person in escorted:
        if person.mobility is not None or not (person.frail
                                               or person.age_group == "older_adult"):
            continue
        ctx.unknown("mobility", f"how well {person.label} can walk", critical=True,
                    why="the pace, the route and the help needed on the way depend on it",
                    entity=person.id, question=f"How well can {person.label} walk? Do they "
                    "need a frame, a wheelchair or an arm to lean on?")


def _escorted(ctx: Context, inv: Involvement, rules: UnknownRules) -> list[PersonView]:
    """People the command moves along with the robot (taken, walked or shown somewhere)."""
    actions = set(rules.group("presence.escort_actions"))
    found: dict[str, PersonView] = {}
    for grounded in ctx.steps:
        if grounded.step.negated or grounded.step.action not in actions:
            continue
        for ref in grounded.objects:
            for person in ctx.people(ref):
                if not person.virtual and not person.is_user:
                    found.setdefault(person.id, person)
    return list(found.values())


def escorting(ctx: Context, inv: Involvement, rules: UnknownRules) -> bool:
    """Whether some step moves a person along (so their mobility decides how)."""
    actions = set(rules.group("presence.escort_actions"))
    return any(not g.step.negated and g.step.action in actions and any(
        r.kind == "person" for r in g.objects) for g in ctx.steps) or bool(
        _escorted(ctx, inv, rules))


def set_out_age_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask the age of the people dangerous things are laid out for, when nobody says it."""
    # The phrase itself says the things are put out for others; the parser may not know it.
    if not has_phrase(inv.text, rules.group("presence.set_out_words")):
        return
    traits = rules.group("presence.set_out_traits")
    risky = next((o for o in inv.objects.values() if any(o.has(t) for t in traits)), None)
    if risky is None:
        return
    asked = {u.entity for u in ctx.unknowns if u.attribute == "age_group" and u.critical}
    for person in ctx.view.people.values():
        if person.virtual or person.is_user or person.id in asked or (
                person.age_group is not None or person.properties.get("age_years") is not None):
            continue
        ctx.unknown("age_group", f"the age of {person.label}", critical=True,
                    why=f"{plain_name(risky)} is laid out for people whose age is not given; "
                    "children must not get it", entity=person.id,
                    question=f"How old is {person.label}? {plain_name(risky).capitalize()} "
                    "must not be left out for children.")
