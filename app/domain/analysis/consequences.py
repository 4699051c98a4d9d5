"""Consequential hazards: the state the task leaves behind once every step has run.

In: the `Context`. Out: consequential proposals from a pass over the steps in order: what is
left switched on (and whether anyone awake stays to attend it), left open, placed on stairs,
walkways or in a child's reach, put on a heat source, taken from a person who needs it; with
the unknowns (does grandma need her walker? is a small child at home?) when they decide.
Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep
from app.domain.analysis.questions import phrase_question
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.situation_base import (
    awake_carer_stays,
    contains,
    everyone_leaves,
    has_condition,
)
from app.domain.analysis.traits import traits_of
from app.domain.models import Category, Level, Preventability, Severity

_P, _U, _X = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE, Preventability.UNKNOWN
_S = Severity
_CON = Category.CONSEQUENTIAL
_MOVING = frozenset({"place", "transport", "remove", "push", "block", "pour", "handover",
                     "serve", "throw"})


def consequential_hazards(ctx: Context) -> None:
    """Add the hazards of the state left behind by the whole command."""
    switched: dict[str, tuple[bool, GroundedStep]] = {}
    opened: dict[str, tuple[bool, GroundedStep]] = {}
    for grounded in ctx.steps:
        step = grounded.step
        action = step.action
        objects = [o for r in grounded.objects for o in ctx.objects(r)]
        if action == "switch_off" and step.negated:
            for obj in objects:
                if obj.switched_on is not False:
                    switched[obj.id] = (True, grounded)
            continue
        if step.negated or action is None:
            continue
        for obj in objects:
            if action == "switch_on":
                switched[obj.id] = (True, grounded)
            elif action == "switch_off":
                switched[obj.id] = (False, grounded)
                _darkness(ctx, obj)
            elif action in ("open", "unlock") or (action == "remove" and obj.has(
                    "safety_barrier")):
                opened[obj.id] = (True, grounded)
            elif action in ("close", "lock"):
                opened[obj.id] = (False, grounded)
        if action in _MOVING:
            _placement(ctx, grounded, switched)
            _walking_aid(ctx, grounded)
        elif action == "navigate" and grounded.objects:
            # "roll the wheelchair back to the store": driving somewhere with it moves it too.
            _walking_aid(ctx, grounded)
        if action == "block":
            for obj in objects:
                ctx.add(Level.TASK, _CON, "blocked_exit", f"Blocking {obj.label} cuts off a "
                        "way out.", {"obj": obj.id}, _S.HIGH, _U)
    for obj_id, (on, grounded) in switched.items():
        if on:
            _left_on(ctx, ctx.view.objects[obj_id], grounded)
    for obj_id, (is_open, grounded) in opened.items():
        if is_open:
            _left_open(ctx, ctx.view.objects[obj_id], grounded)


def _awake_attendant(ctx: Context) -> bool | None:
    """True if someone awake is known to be home, False if known not, None if not known."""
    if ctx.cue("leaving"):
        return False
    if not ctx.view.people_known:
        return None
    return ctx.view.anyone_awake_home()


def _left_on(ctx: Context, obj: ObjectView, grounded: GroundedStep) -> None:
    if obj.has("heat_source") or obj.has("ignition") or obj.concept in ("iron", "heater"):
        hazard, harm = "appliance_left_on", "a fire"
    elif obj.has("water_source"):
        hazard, harm = "flooding", "a flood"
    else:
        return
    attendant = _awake_attendant(ctx)
    entities = {"obj": obj.id, "room": obj.room}
    blocked = any(obj.properties.get(k) for k in ("blocked", "clogged", "plugged"))
    if attendant is False or (hazard == "flooding" and blocked):
        why = "with no one awake at home" if attendant is False else "into a blocked drain"
        ctx.add(Level.TASK if ctx.cue("leaving") else Level.DEPLOYMENT, _CON, hazard,
                f"{obj.label} is left running {why}: it can cause {harm}.", entities,
                _S.CRITICAL if hazard == "appliance_left_on" else _S.HIGH, _U)
    elif attendant is None:
        ctx.add(Level.TASK, _CON, hazard, f"{obj.label} stays on after the task; it must be "
                "switched off before everyone leaves or sleeps.", entities, _S.MODERATE, _P)
        ctx.unknown("presence", f"whether someone stays to attend {obj.label}", critical=False,
                    why=f"an unattended {obj.type.lower()} can cause {harm}", entity=obj.id,
                    question=phrase_question("presence", obj.label))
    else:
        ctx.add(Level.DEPLOYMENT, _CON, hazard, f"{obj.label} stays on while someone is "
                "home; switch it off when done.", entities, _S.MODERATE, _P)


def _left_open(ctx: Context, obj: ObjectView, grounded: GroundedStep) -> None:
    children = ctx.view.children()
    young = [p for p in children if p.young or p.age_group == "infant"] or children
    text = grounded.step.text
    if obj.has("safety_barrier"):
        lost = [p for p in young if p.room is None and not p.virtual]
        if lost and all(p.room is None for p in young):
            # The child is at home but where is not known: in reach of the danger or not.
            child = lost[0]
            ctx.add(Level.DEPLOYMENT, _CON, "safety_barrier_removed", f"{obj.label} is opened "
                    f"while {child.label} ({child.age_group}) may be near it; where they are is "
                    "not known.", {"aid": obj.id, "obj": obj.id, "person": child.id}, _S.HIGH, _X)
            ctx.unknown("person_location", f"where {child.label} is right now", critical=True,
                        why=f"{obj.label} keeps {child.label} from danger; opening it matters "
                        "only if they can get to it", entity=child.id,
                        question=f"Where is {child.label} right now? {obj.label} keeps them "
                        "from danger while it is open.")
        elif young:
            ctx.add(Level.DEPLOYMENT, _CON, "safety_barrier_removed", f"{obj.label} is opened "
                    f"or removed while {young[0].label} ({young[0].age_group}) is at home.",
                    {"aid": obj.id, "obj": obj.id, "person": young[0].id}, _S.HIGH, _U)
        elif ctx.view.people_known:
            ctx.add(Level.DEPLOYMENT, _CON, "safety_barrier_removed", f"{obj.label} is opened;"
                    " close it again when done.", {"aid": obj.id, "obj": obj.id}, _S.LOW, _P)
        else:
            ctx.add(Level.TASK, _CON, "safety_barrier_removed", f"{obj.label} is opened or "
                    "removed, and whether a small child is at home is not known.",
                    {"aid": obj.id, "obj": obj.id}, _S.HIGH, _X)
            ctx.unknown("child_present", "whether a baby or young child is at home",
                        critical=True, why=f"{obj.label} exists to keep a small child from "
                        "danger", entity=None, question=phrase_question("child_present", ""))
    elif obj.has("door") or obj.has("window"):
        at_risk = [p for p in young if p.room in (obj.room, None) or obj.room is None]
        wanderers = [p for p in ctx.view.real_people() if not p.is_user and (
            p.cognitive_state == "impaired" or has_condition(ctx, p, "wanders"))]
        # Left open on purpose ("leave it open") or with everyone gone, a door stays open for
        # as long as nobody awake is watching: a person who wanders walks out through it.
        if wanderers and (everyone_leaves(ctx) or grounded.step.keeps_state) and (
                awake_carer_stays(ctx) is not True):
            ctx.add(Level.DEPLOYMENT, _CON, "door_left_open", f"{obj.label} is left open "
                    f"while {wanderers[0].label}, who may wander off, is left without anyone "
                    "watching.", {"obj": obj.id, "person": wanderers[0].id}, _S.CRITICAL, _U)
        if at_risk:
            ctx.add(Level.DEPLOYMENT, _CON, "door_left_open", f"{obj.label} is left open with"
                    f" {at_risk[0].label} ({at_risk[0].age_group}) nearby: a fall or an "
                    "escape.", {"obj": obj.id, "person": at_risk[0].id}, _S.HIGH,
                    _U if grounded.step.keeps_state or "window" in text else _P)
        elif grounded.step.keeps_state or ctx.cue("leaving"):
            ctx.add(Level.TASK, _CON, "door_left_open", f"{obj.label} is left open.",
                    {"obj": obj.id}, _S.MODERATE, _P)
    elif obj.has("toxic") or (obj.contents and ctx.knowledge.substances[obj.contents].props & {
            "toxic"}):
        severity = _S.HIGH if children else _S.MODERATE
        ctx.add(Level.DEPLOYMENT, _CON, "unsealed_chemical", f"{obj.label} is left open.",
                {"obj": obj.id}, severity, _U if children else _P)
    elif obj.concept == "fridge":
        ctx.add(Level.DEPLOYMENT, _CON, "door_left_open", f"{obj.label} is left open: food "
                "spoils.", {"obj": obj.id}, _S.LOW, _P)


def _placement(ctx: Context, grounded: GroundedStep,
               switched: dict[str, tuple[bool, GroundedStep]]) -> None:
    destination = grounded.destination
    mention = destination.mention if destination else None
    placed = [(ref, obj) for ref in grounded.objects for obj in ctx.objects(ref)]
    if not placed:
        return
    heat = [o for o in ctx.objects(destination) if o.has("heat_source")]
    children = ctx.view.children()
    # Hung on a hook, nail or peg, it is off the floor and out of the way.
    aside = (mention is not None and mention.head in ("wall", "corner", "side")) or any(
        contains(ctx.text, w) for w in ("out of the way", "to one side", "against the wall")
    ) or (grounded.step.verb or "").startswith("hang")
    on_stairs, at_exit, on_walkway = (ctx.place_in(mention, group)
                                      for group in ("stairs", "exit", "walkway"))
    for ref, obj in placed:
        traits = traits_of(ctx, obj, ref.mention)
        entities = {"obj": obj.id}
        if on_stairs and not aside:
            ctx.add(Level.TASK, _CON, "trip_hazard", f"{obj.label} left on the stairs "
                    "is a fall hazard.", entities, _S.HIGH, _U)
        elif at_exit and not aside and grounded.step.destination_prep in (
                "in front of", "against", "by", "at", "next to", "near", "in"):
            ctx.add(Level.TASK, _CON, "blocked_exit", f"{obj.label} placed at "
                    f"{mention.text if mention else 'the door'} blocks the way out.",
                    entities, _S.HIGH, _U)
        elif on_walkway and not aside and (obj.has("heavy") or obj.has(
                "furniture") or obj.has("container") or obj.has("cord") or not obj.has(
                "food")) and grounded.step.action != "pour":
            frail = any(p.frail for p in ctx.view.people.values())
            ctx.add(Level.TASK, _CON, "trip_hazard", f"{obj.label} left on a walkway can "
                    "trip someone.", entities, _S.HIGH if frail else _S.MODERATE,
                    _U if frail else _P)
        if grounded.step.action == "pour" and on_walkway:
            ctx.add(Level.TASK, _CON, "spill_slip", "Liquid poured on the floor is a "
                    "slip hazard.", entities, _S.MODERATE, _U)
        for source in heat:
            lit = switched.get(source.id, (bool(source.switched_on), grounded))[0]
            if traits.has("flammable") and not traits.has("food"):
                ctx.add(Level.DEPLOYMENT if not source.virtual else Level.TASK, _CON,
                        "fire_risk_left" if not lit else "fire_ignition", f"{obj.label}, "
                        f"which burns, put on {source.label}.", {"obj": obj.id,
                        "other": source.id}, _S.CRITICAL if lit else _S.MODERATE,
                        _U if lit else _P)
        _reach(ctx, grounded, obj, traits.has("medication"), any(traits.has(t) for t in (
            "toxic", "sharp", "hot", "small")), children)


def _reach(ctx: Context, grounded: GroundedStep, obj: ObjectView, medication: bool,
           dangerous: bool, children: list[PersonView]) -> None:
    if not (medication or dangerous):
        return
    mention = grounded.destination.mention if grounded.destination else None
    hazard = "medication_left_accessible" if medication else "hazard_left_in_reach"
    safe = ctx.place_in(mention, "safe_storage") or ctx.cue("keep_away") or (
        grounded.step.verb in ("put away", "store", "lock up", "hide"))
    # Low is what the command says, or where the named destination itself sits ("in there":
    # the fruit bowl on the coffee table).
    low = ctx.place_in(mention, "low_reach") or any(
        any(contains(" ".join(sorted(o.place_words)), w) for w in ctx.knowledge.places[
            "low_reach"]) for o in ctx.objects(grounded.destination))
    if safe or grounded.step.action in ("handover", "serve") or grounded.recipient:
        return
    child_place = mention is not None and any(w in mention.text for w in (
        "play", "nursery", "crib", "cot", "toy", "kid", "child"))
    if children and (low or child_place):
        ctx.add(Level.DEPLOYMENT, _CON, hazard, f"{obj.label} left where {children[0].label} "
                f"({children[0].age_group}) can reach it.", {"obj": obj.id,
                "person": children[0].id}, _S.CRITICAL, _U)
    elif child_place:
        ctx.add(Level.TASK, _CON, hazard, f"{obj.label} left in a child's place.",
                {"obj": obj.id}, _S.CRITICAL, _U)
    elif children:
        ctx.add(Level.DEPLOYMENT, _CON, hazard, f"{obj.label} must end up out of "
                f"{children[0].label}'s reach.", {"obj": obj.id, "person": children[0].id},
                _S.HIGH, _P)


def _walking_aid(ctx: Context, grounded: GroundedStep) -> None:
    handed = ctx.people(grounded.recipient)
    if grounded.recipient is not None and (not handed or any(p.virtual for p in handed)):
        return  # brought to someone ("bring her walker over to her"): not taken away
    recipients = {p.id for p in handed}
    if _left_by_its_user(grounded):
        return
    for ref in grounded.objects:
        for aid in ctx.objects(ref):
            if not aid.has("walking_aid") or aid.type.lower() in ("glasses", "hearing aid"):
                continue
            users = [p for p in ctx.people(grounded.away_from) or ctx.people(grounded.source)
                     or list(ctx.view.people.values()) if p.id not in recipients]
            owner = ref.mention.owner or aid.owner
            if owner:
                users = [p for p in users if owner in (p.role or "", p.id, p.name or "",
                                                       "her", "him")] or users
            for person in users:
                if person.needs_walking_aid:
                    level = Level.USER if person.is_user else Level.DEPLOYMENT
                    ctx.add(level, _CON, "walking_aid_removed", f"Taking {aid.label} away "
                            f"from {person.label}, who needs it to walk.",
                            {"aid": aid.id, "obj": aid.id, "person": person.id},
                            _S.HIGH, _U)
                elif person.needs_walking_aid is None and (person.frail or person.age_group
                                                           == "older_adult"):
                    ctx.add(Level.TASK, _CON, "walking_aid_removed", f"Moving {aid.label} "
                            f"away from {person.label}, who may need it.", {"aid": aid.id,
                            "obj": aid.id, "person": person.id}, _S.HIGH, _X)
                    ctx.unknown("needs_walking_aid", f"whether {person.label} needs "
                                f"{aid.label}", critical=True, why="without it they may fall",
                                entity=person.id, question=phrase_question(
                                    "needs_walking_aid", person.label, aid.label))


def _left_by_its_user(grounded: GroundedStep) -> bool:
    """Put right by its user ("next to her chair", "beside his bed"): still within reach."""
    mention = grounded.destination.mention if grounded.destination else None
    return mention is not None and grounded.step.destination_prep in (
        "next to", "beside", "by", "near", "close to", "within reach of") and any(
        w in ("her", "his", "their", "him", "them") or w.endswith("'s")
        for w in mention.text.split())


def _darkness(ctx: Context, obj: ObjectView) -> None:
    if not obj.has("light"):
        return
    for person in ctx.view.real_people():
        if (person.room is None and person.frail and not person.asleep and person.mobility in (
                "assisted", "wheelchair")) or (person.room is None and person.needs_walking_aid):
            # Someone unsteady whose whereabouts are unknown may be exactly where it goes dark.
            ctx.unknown("person_location", f"where {person.label} is right now", critical=True,
                        why=f"{person.label} is unsteady on their feet and may be where "
                        f"{obj.label} lights the way", entity=person.id,
                        question=f"Where is {person.label} right now? Switching off "
                        f"{obj.label} could leave them walking in the dark.")
    for person in ctx.view.people_in(obj.room) if obj.room else ctx.view.people.values():
        if person.frail and not person.asleep:
            ctx.add(Level.DEPLOYMENT, _CON, "darkness_fall", f"Switching off {obj.label} "
                    f"while {person.label}, unsteady on their feet, moves about.",
                    {"obj": obj.id, "person": person.id}, _S.HIGH, _U)
