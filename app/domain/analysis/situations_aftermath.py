"""Situations whose harm is the state a command leaves people in, read from the whole command.

In: a `Context` and the phrase groups of `knowledge/hazard_situations.json`. Out: proposals for:
noise made in a room where someone sleeps (startling); perishable food (raw meat, fish, dairy,
cooked rice) left at room temperature for hours or to thaw (food_safety); a floor washed and
left wet on the route people are about to walk (spill_slip); people kept in a room by the robot
("don't let them out") (blocked_exit); something heavy or breakable put on a shelf or ledge
above where someone lies or sits (falling_object); a cable run through a hall or doorway and
left there while someone unsteady or unable to see it is home (trip_hazard); a candle or open
flame lit and then left burning in a room nobody is in while the robot goes elsewhere
(appliance_left_on, critical with something that burns in the room). The commanded
state is the harm, so these are unpreventable; the rules are silent when the command itself
prevents the harm (quietly, in the fridge, a wet-floor sign, dry it). Never fails.
"""

from __future__ import annotations

import re
from functools import cache

from app.domain.analysis.context import Context
from app.domain.analysis.scene_view import ObjectView, PersonView, spaced_name
from app.domain.analysis.situation_base import (
    any_phrase,
    contains,
    load_situations,
    named_people,
    robot_leaves_room,
)
from app.domain.models import Category, Level, Preventability, Severity

_U = Preventability.UNPREVENTABLE
_PLACING = frozenset({"place", "transport"})
_HEAVY_KG = 2.0
_ABOVE = frozenset({"above", "over"})
_S = Severity
_SEGMENT = re.compile(r"\s[,;.!?:]\s|\sthen\s")
_OPEN_FLAMES = frozenset({"candle"})
_GOING = frozenset({"navigate", "assist", "transport", "fetch", "handover"})
_PRONOUN_PEOPLE = frozenset({"them", "him", "her", "anyone", "anybody", "nobody", "everyone",
                             "everybody", "either", "both"})


def aftermath_hazards(ctx: Context) -> None:
    """Add the hazards of the state the whole command leaves people in."""
    if not any(not g.step.negated for g in ctx.steps):
        return
    _noise_where_asleep(ctx)
    _food_left_out(ctx)
    _wet_floor(ctx)
    _kept_in(ctx)
    _over_someone(ctx)
    _cord_across_the_way(ctx)
    _flame_left_burning(ctx)


def rooms_named(ctx: Context, text: str) -> set[str]:
    """Scene rooms the text names: by id, by a word for the room, or as a child's room.

    Args:
        ctx: the analysis context.
        text: normalised text.

    Returns:
        The room ids (only rooms of the scene).
    """
    rooms = {room for room in ctx.view.rooms if contains(text, room.replace("_", " "))}
    rooms |= {room for word, room in ctx.knowledge.room_words.items()
              if room in ctx.view.rooms and contains(text, word)}
    if any_phrase(text, load_situations().group("child_room_words")):
        cots = load_situations().group("infant_sleeper_places")
        rooms |= {p.room for p in ctx.view.real_people() if p.room and (p.child or p.young)}
        rooms |= {o.room for o in ctx.view.objects.values() if o.room and any(
            contains(o.type.lower(), w) for w in cots)}
        rooms |= {r for r in ctx.view.rooms if any(w in r for w in ("kid", "child", "nursery",
                                                                   "baby", "play"))}
    return rooms


def _noise_where_asleep(ctx: Context) -> None:
    """Told to be loud where someone sleeps: waking them with a start is the commanded act."""
    data = load_situations()
    noise = any_phrase(ctx.text, data.group("noise_words"))
    if not noise or any_phrase(ctx.text, data.group("quiet_words")):
        return
    rooms = rooms_named(ctx, ctx.text)
    for grounded in ctx.steps:
        for ref in (*grounded.objects, grounded.destination, grounded.source):
            if ref is not None and ref.kind == "room":
                rooms.update(ref.ids)
    # A sleeper the command names counts where the noise is, or anywhere if no room is named.
    sleepers = [p for p in named_people(ctx) if p.asleep and (not rooms or p.room in rooms)]
    sleepers += [p for room in sorted(rooms) for p in ctx.view.people_in(room) if p.asleep]
    for person in {p.id: p for p in sleepers if not p.is_user}.values():
        fragile = person.child or person.frail
        ctx.add(Level.DEPLOYMENT, Category.PSYCHOLOGICAL, "startling", f"Making noise "
                f"('{noise}') where {person.label} is asleep: it wakes them with a start.",
                {"person": person.id}, _S.CRITICAL if fragile else _S.HIGH, _U)


def _food_left_out(ctx: Context) -> None:
    """Raw meat, fish, dairy or cooked food left out for hours grows bacteria that sicken."""
    data = load_situations()
    food = any_phrase(ctx.text, data.group("perishable_foods"))
    if not food:
        return
    for segment in _segments(ctx.text):
        left = any_phrase(segment, data.group("left_out_words")) or (
            "out" in segment.split() and any(w in segment.split() for w in ("leave", "left")))
        cold = any_phrase(segment, data.group("cold_storage_places"))
        if not left or cold:
            continue
        long = any_phrase(segment, data.group("long_durations")) or any_phrase(
            segment, data.group("thaw_words"))
        if long:
            ctx.add(Level.TASK, Category.CONSEQUENTIAL, "food_safety", f"The {food} is left "
                    f"at room temperature ({long}): bacteria multiply and it can cause food "
                    "poisoning.", {}, _S.HIGH, _U)
            return


def _wet_floor(ctx: Context) -> None:
    """A floor washed and left wet just before people walk it: someone slips."""
    data = load_situations()
    text = ctx.text
    washed = any_phrase(text, data.group("wet_clean_words")) or (
        any_phrase(text, data.group("floor_wash_verbs")) and any_phrase(
            text, data.group("floor_words")))
    left_wet = any_phrase(text, data.group("left_wet_words"))
    if not (washed and left_wet) or any_phrase(text, data.group("slip_precaution_words")):
        return
    coming = any_phrase(text, data.group("arrival_words"))
    walkers = [p for p in ctx.view.real_people() if not p.is_user]
    frail = [p for p in walkers if p.frail or p.child]
    if coming and walkers:
        who = (frail or walkers)[0]
        ctx.add(Level.DEPLOYMENT, Category.CONSEQUENTIAL, "spill_slip", f"The floor is left "
                f"wet ({left_wet}) just as people come through ({coming}): {who.label} can "
                "slip and fall.", {"person": who.id}, _S.HIGH, _U)
    elif awake := [p for p in frail if not p.asleep]:
        # Someone unsteady is at home and awake: they will cross it (to the toilet, the door)
        # before it dries, whether or not the command says when.
        ctx.add(Level.DEPLOYMENT, Category.CONSEQUENTIAL, "spill_slip", f"The floor is left "
                f"wet ({left_wet}) while {awake[0].label}, who is unsteady, is at home: they "
                "can slip and fall.", {"person": awake[0].id}, _S.HIGH, _U)


def _kept_in(ctx: Context) -> None:
    """The robot told to keep people from leaving a room: they are trapped if anything happens."""
    for match in _keep_in_pattern().finditer(ctx.text):
        span = match.group(0)
        people = named_people(ctx, span) or _role_named(ctx, span)
        if not people and _PRONOUN_PEOPLE & set(span.split()):
            people = named_people(ctx) or _role_named(ctx, ctx.text)
        if people:
            ctx.add(Level.TASK, Category.CONSEQUENTIAL, "blocked_exit", f"Keeping "
                    f"{people[0].label} from leaving the room: they cannot get out in an "
                    "emergency and are confined against their will.", {"person": people[0].id},
                    _S.HIGH, _U)
            return


@cache
def _keep_in_pattern() -> re.Pattern[str]:
    return re.compile(load_situations().records["keep_in_pattern"])


def _role_named(ctx: Context, text: str) -> list[PersonView]:
    """Scene people of an age group a role word of the text implies ("the kids", "the boys")."""
    groups = {role.age_group for word, role in ctx.knowledge.role_words.items()
              if not role.is_user and role.age_group and contains(text, word)}
    return [p for p in ctx.view.real_people() if not p.is_user and p.age_group in groups]


def _segments(text: str) -> list[str]:
    return [s.strip() for s in _SEGMENT.split(f" {text} ") if s.strip()] or [text]


def _over_someone(ctx: Context) -> None:
    """Something heavy or breakable put above where a person lies or sits can fall on them.

    Where people are comes from the scene's relations (a person on the sofa, a shelf above the
    sofa); the place is named in the command either as the thing above ("on the shelf") or by
    what it is over ("over the sofa").
    """
    scene = ctx.request.scene
    if scene is None:
        return
    resting = {r.object: ctx.view.people[r.subject] for r in scene.relations
               if r.subject in ctx.view.people and r.object in ctx.view.objects}
    if not resting:
        return
    above = {r.subject: r.object for r in scene.relations
             if r.relation.lower() in _ABOVE and r.object in resting}
    named = [resting[o] for o in resting if _over_named(ctx, ctx.view.objects[o].type)]
    named += [resting[below] for shelf, below in above.items()
              if shelf in ctx.view.objects
              and contains(ctx.text, spaced_name(ctx.view.objects[shelf].type))]
    if not named:
        return
    for grounded in ctx.steps:
        if grounded.step.negated or grounded.step.action not in _PLACING:
            continue
        for ref in grounded.objects:
            for obj in ctx.objects(ref):
                mass = obj.properties.get("mass_kg")
                weighty = obj.has("heavy") or (
                    isinstance(mass, int | float) and mass >= _HEAVY_KG)
                if weighty or obj.has("fragile") or obj.has("sharp"):
                    person = named[0]
                    ctx.add(Level.DEPLOYMENT, Category.PHYSICAL, "falling_object",
                            f"{obj.label} is put above where {person.label} lies or sits: "
                            "if it slips or the shelf gives, it falls on them.",
                            {"obj": obj.id, "person": person.id}, _S.HIGH, _U)
                    return


def _over_named(ctx: Context, object_type: str) -> bool:
    word = spaced_name(object_type)
    return any(contains(ctx.text, f"{prep} the {word}") or contains(ctx.text, f"{prep} {word}")
               for prep in _ABOVE)


_CORD_ROUTE = re.compile(r"\b(?:through|across|along|down|over|out through|out of|under)\s+"
                         r"(?:the\s+)?(?:front\s+|back\s+)?(\w+)")


def _cord_across_the_way(ctx: Context) -> None:
    """A cable run through a hall, doorway or across a floor and left there trips someone who
    cannot see it or is unsteady on their feet."""
    walkways = ctx.knowledge.places["walkway"]
    at_risk = [p for p in ctx.view.real_people() if not p.is_user and not p.asleep and (
        p.frail or p.child)]
    if not at_risk:
        return
    for grounded in ctx.steps:
        if grounded.step.negated:
            continue
        cords = [o for r in grounded.objects for o in ctx.objects(r) if o.has("cord")]
        if not cords:
            continue
        routes = {m.group(1) for m in _CORD_ROUTE.finditer(grounded.step.text)}
        crosses = any(contains(" ".join(routes), w) for w in walkways) or "door" in routes
        if cords and crosses:
            ctx.add(Level.DEPLOYMENT, Category.CONSEQUENTIAL, "trip_hazard", f"{cords[0].label} "
                    f"is run across the way people walk while {at_risk[0].label} is at home: "
                    "they can trip on it.", {"obj": cords[0].id, "person": at_risk[0].id},
                    _S.HIGH, _U)
            return


def _flame_left_burning(ctx: Context) -> None:
    """A candle lit and then left: the robot goes on elsewhere and nobody awake is in the room
    where it burns, so nothing watches the flame (a draught, a curtain, a cat knocks it over)."""
    if not ctx.view.people_known:
        return
    for index, grounded in enumerate(ctx.steps):
        if grounded.step.negated or grounded.step.action != "switch_on":
            continue
        for flame in (o for r in grounded.objects for o in ctx.objects(r)):
            room = flame.room
            if flame.concept not in _OPEN_FLAMES or room is None or any(
                    not p.asleep for p in ctx.view.people_in(room) if not p.virtual):
                continue
            if not (robot_leaves_room(ctx) or _goes_elsewhere(ctx, index, room)):
                continue
            fuel = _burnable_in(ctx, room, flame)
            near = f"; {fuel.label} in the room can catch" if fuel else ""
            ctx.add(Level.DEPLOYMENT, Category.CONSEQUENTIAL, "appliance_left_on",
                    f"{flame.label} is lit and left burning in the {spaced_name(room)} with no "
                    f"one there{near}.", {"obj": flame.id, "room": room},
                    _S.CRITICAL if fuel else _S.HIGH, _U)
            return


def _goes_elsewhere(ctx: Context, index: int, room: str) -> bool:
    """Whether a step after `index` takes the robot out of `room`: to another room it names, or
    to the user ("come and help me") when the user is somewhere else."""
    user_room = ctx.view.user.room if ctx.view.user else None
    for later in ctx.steps[index + 1:]:
        step = later.step
        if step.negated or step.action not in _GOING:
            continue
        named = rooms_named(ctx, step.text) | {
            i for ref in (later.destination, *later.objects) if ref is not None
            and ref.kind == "room" for i in ref.ids}
        if named - {room}:
            return True
        if step.action in ("navigate", "assist") and user_room and user_room != room and (
                contains(step.text, "me") or step.verb == "come"):
            return True
    return False


def _burnable_in(ctx: Context, room: str, flame: ObjectView) -> ObjectView | None:
    return next((o for o in ctx.view.objects.values() if o.room == room and o.id != flame.id
                 and o.has("flammable") and o.concept not in _OPEN_FLAMES), None)
