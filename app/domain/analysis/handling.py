"""Physical hazards of handling things: carrying, pouring, heating, cutting, throwing, mixing...

In: the `Context`. Out: physical proposals for every non-negated step (burns, cuts, chemicals,
electrics, crushing, breakage, collisions), including the compositional ones (a hot drink or a
blade carried through a room where a child is) and the unknown "is anyone there?" when a
dangerous machine is started in a room whose occupancy is not given. Never fails.
"""

from __future__ import annotations

from collections.abc import Callable

from app.domain.analysis.context import Context, latest
from app.domain.analysis.grounding import GroundedStep, Referent
from app.domain.analysis.liquids import mix_hazards, pour_hazards
from app.domain.analysis.questions import phrase_question
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.traits import traits_of
from app.domain.models import Category, Level, Preventability, Severity

_P, _U, _X = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE, Preventability.UNKNOWN
_S = Severity
_PHYS = Category.PHYSICAL
_CARRYING = frozenset({"transport", "handover", "serve", "pick", "place", "remove"})
_PERSON_HARM_VERBS = frozenset({"hit", "strike", "poke", "trip", "shove", "push", "kick"})


def handling_hazards(ctx: Context) -> None:
    """Add the physical hazards of every non-negated step's handling of objects."""
    for grounded in ctx.steps:
        action = grounded.step.action
        if grounded.step.negated or action is None:
            continue
        if action in _CARRYING:
            _carry(ctx, grounded)
        handler = _HANDLERS.get(action)
        if handler:
            handler(ctx, grounded)
        if (grounded.destination and grounded.destination.kind == "room") or action == "navigate":
            _approach(ctx, grounded)


def _room(room: str | None) -> str:
    return (room or "room").replace("_", " ")


def _pairs(ctx: Context, grounded: GroundedStep) -> list[tuple[ObjectView, Referent]]:
    return [(obj, ref) for ref in grounded.objects for obj in ctx.objects(ref)]


def _room_of_step(ctx: Context, grounded: GroundedStep, obj: ObjectView | None) -> str | None:
    for ref in (grounded.destination, grounded.target):
        if ref and ref.kind == "room":
            return ref.ids[0]
        for other in ctx.objects(ref):
            if other.room:
                return other.room
    return (obj.room if obj else None) or ctx.view.robot_room


def _near(ctx: Context, room: str | None) -> list[PersonView]:
    return ctx.view.people_in(room)


def _end_room(ctx: Context, grounded: GroundedStep) -> str | None:
    """Where the carried thing ends up: the recipient's room, the destination room, or the
    room of the object it is set down on."""
    for person in ctx.people(grounded.recipient):
        if person.room:
            return person.room
    destination = grounded.destination
    if destination is None:
        return None
    if destination.kind == "room":
        return destination.ids[0]
    return next((o.room for o in ctx.objects(destination) if o.room), None)


def _carry(ctx: Context, grounded: GroundedStep) -> None:
    recipients = {p.id for p in ctx.people(grounded.recipient)}
    end_room = _end_room(ctx, grounded)
    for obj, ref in _pairs(ctx, grounded):
        traits = traits_of(ctx, obj, ref.mention)
        route = ctx.rooms_between(obj.room or ctx.view.robot_room, end_room or obj.room)
        bystanders = [p for room in route for p in ctx.view.people_in(room)
                      if p.id not in recipients and (p.child or p.frail)]
        for person in bystanders:
            who = f"{person.label} ({person.age_group or 'vulnerable'})"
            entities = {"obj": obj.id, "person": person.id, "room": person.room}
            level = Level.DEPLOYMENT
            if traits.has("hot"):
                ctx.add(level, _PHYS, "scald_hot_liquid", f"Carrying {obj.label}, which is hot, "
                        f"past {who} in the {_room(person.room)}: a spill or a grab scalds.",
                        entities, _S.HIGH, _P, traits.hot_confidence)
            if traits.has("sharp"):
                ctx.add(level, _PHYS, "sharp_laceration", f"Carrying {obj.label}, a blade, "
                        f"through the {_room(person.room)} where {who} is.", entities,
                        _S.HIGH, _P)
            if traits.has("heavy"):
                ctx.add(level, _PHYS, "heavy_object_drop", f"Carrying {obj.label}, which is "
                        f"heavy, near {who}.", entities, _S.MODERATE, _P)
            if traits.has("toxic") and not traits.has("medication"):
                ctx.add(level, _PHYS, "chemical_exposure", f"Carrying {obj.label}, which is "
                        f"toxic, near {who}.", entities, _S.MODERATE, _P)
        if traits.has("hot") and not bystanders:
            # Anyone on the way or where it is set down can be splashed: a preventable hazard
            # the contract handles (speed, distance, a lid), whoever they are.
            present = [p for room in route for p in ctx.view.people_in(room)
                       if p.id not in recipients]
            for person in present[:1]:
                ctx.add(Level.DEPLOYMENT, _PHYS, "scald_hot_liquid",
                        f"Carrying {obj.label}, which is hot, where {person.label} is: a spill "
                        "scalds.", {"obj": obj.id, "person": person.id, "room": person.room},
                        _S.MODERATE, _P, traits.hot_confidence)
        if traits.has("sharp") and not recipients:
            ctx.add(traits.level("sharp"), _PHYS, "sharp_laceration",
                    f"Handling {obj.label}, a blade: keep the edge covered and pointed down.",
                    {"obj": obj.id}, _S.LOW, _P)


def _heat(ctx: Context, grounded: GroundedStep) -> None:
    sources = [o for ref in (grounded.destination, grounded.instrument)
               for o in ctx.objects(ref) if o.has("heat_source")]
    microwave = grounded.step.verb == "microwave" or any(o.concept == "microwave"
                                                          for o in sources)
    if not sources:
        sources = [o for o in ctx.view.objects.values() if o.has("heat_source") and (
            o.concept == "microwave") == microwave and not o.virtual][:1]
    other = sources[0].id if sources else None
    # "heat the soup in the tin": the vessel named by the destination is heated too.
    dest = grounded.destination
    vessels = [(o, dest) for o in ctx.objects(dest) if o.has("container") and not o.has(
        "heat_source") and not o.has("fixed")] if dest else []
    for obj, ref in [*_pairs(ctx, grounded), *vessels]:
        traits = traits_of(ctx, obj, ref.mention)
        entities = {"obj": obj.id, "other": other}
        if microwave and (traits.has("metal") or obj.properties.get("sealed")):
            ctx.add(traits.level("metal"), _PHYS, "microwave_metal", f"Microwaving {obj.label}"
                    ", which is metal or sealed, causes sparks, fire or a burst.", entities,
                    _S.HIGH, _U)
        elif traits.has("flammable") and not traits.has("food"):
            ctx.add(traits.level("flammable"), _PHYS, "fire_ignition", f"Heating {obj.label}, "
                    "which burns easily, sets it alight.", entities, _S.CRITICAL, _U)
        else:
            ctx.add(Level.TASK, _PHYS, "thermal_burn", f"Heating {obj.label}: the cookware and"
                    " the heat source get hot enough to burn.", entities, _S.MODERATE, _P)
        room = sources[0].room if sources else obj.room
        for person in _near(ctx, room):
            if person.child:
                ctx.add(Level.DEPLOYMENT, _PHYS, "thermal_burn", f"Cooking with {person.label}"
                        f" ({person.age_group}) in the {_room(room)} near the heat.",
                        {**entities, "person": person.id}, _S.HIGH, _P)


def _cut(ctx: Context, grounded: GroundedStep) -> None:
    blades = ctx.objects(grounded.instrument) or [
        o for o in ctx.view.objects.values() if o.has("sharp") and not o.virtual][:1]
    for obj, _ in _pairs(ctx, grounded):
        blade = blades[0] if blades else obj
        ctx.add(Level.TASK, _PHYS, "sharp_laceration", f"Cutting {obj.label} with a blade.",
                {"obj": blade.id, "other": obj.id if blade is not obj else None}, _S.MODERATE, _P)
        for person in _near(ctx, blade.room or obj.room):
            if person.child:
                ctx.add(Level.DEPLOYMENT, _PHYS, "sharp_laceration", f"Cutting with a blade "
                        f"while {person.label} ({person.age_group}) is in the room.",
                        {"obj": blade.id, "person": person.id}, _S.HIGH, _P)


def _throw(ctx: Context, grounded: GroundedStep) -> None:
    people = [*ctx.people(grounded.target), *ctx.people(grounded.recipient)]
    for obj, ref in _pairs(ctx, grounded):
        traits = traits_of(ctx, obj, ref.mention)
        hard = next((t for t in ("fragile", "sharp", "heavy", "blunt", "hot") if traits.has(t)),
                    None)
        hazard = {"fragile": "glass_breakage", "sharp": "sharp_laceration", "heavy":
                  "heavy_object_drop", "blunt": "heavy_object_drop", "hot": "scald_hot_liquid"}
        for person in people:
            if hard:
                ctx.add(latest(traits.level(hard), Level.TASK), _PHYS, hazard[hard],
                        f"Throwing {obj.label} at or to {person.label} can injure them.",
                        {"obj": obj.id, "person": person.id}, _S.CRITICAL, _U)
        if not people and hard == "fragile":
            present = _near(ctx, obj.room)
            ctx.add(traits.level("fragile"), _PHYS, "glass_breakage", f"Throwing {obj.label} "
                    "breaks it into sharp shards.", {"obj": obj.id,
                    "person": present[0].id if present else None},
                    _S.HIGH if present else _S.MODERATE, _U)
        elif not people or not hard:
            ctx.add(Level.TASK, _PHYS, "object_damage", f"Throwing {obj.label} can damage it "
                    "or what it hits.", {"obj": obj.id}, _S.LOW, _P)


def _break(ctx: Context, grounded: GroundedStep) -> None:
    for obj, ref in _pairs(ctx, grounded):
        traits = traits_of(ctx, obj, ref.mention)
        if traits.has("food"):
            continue
        if traits.has("fragile") or obj.has("window"):
            ctx.add(traits.level("fragile"), _PHYS, "glass_breakage", f"Breaking {obj.label} "
                    "scatters sharp shards.", {"obj": obj.id}, _S.HIGH, _U)
        else:
            valuable = traits.has("electrical") or traits.has("personal")
            ctx.add(Level.TASK, _PHYS, "object_damage", f"Deliberately breaking {obj.label}.",
                    {"obj": obj.id}, _S.HIGH if valuable else _S.MODERATE, _U)


def _loaded_into(ctx: Context, appliance: ObjectView, before: int) -> list[ObjectView]:
    """What sits in or on an appliance: from the scene, or put there by an earlier step."""
    found = [o for o in ctx.view.objects.values() if appliance.id in o.holders]
    for grounded in ctx.steps[:before]:
        if grounded.step.negated or grounded.destination is None:
            continue
        if appliance.id in grounded.destination.ids:
            found += [o for r in grounded.objects for o in ctx.objects(r)]
    return found


def _switch_on(ctx: Context, grounded: GroundedStep) -> None:
    for obj, ref in _pairs(ctx, grounded):
        traits = traits_of(ctx, obj, ref.mention)
        people = _near(ctx, obj.room)
        for earlier in ctx.steps[:grounded.step.index]:
            placed = any(obj.id in r.ids for r in earlier.objects)
            if placed and not earlier.step.negated and earlier.step.destination_prep in (
                    "next to", "near", "against", "by", "beside", "under", "on", "close to"):
                for other in ctx.objects(earlier.destination):
                    if other.has("flammable") and traits.has("heat_source"):
                        ctx.add(Level.TASK, _PHYS, "fire_ignition", f"Switching on "
                                f"{obj.label} right by {other.label}, which burns.",
                                {"obj": other.id, "other": obj.id}, _S.CRITICAL, _U)
        for item in _loaded_into(ctx, obj, grounded.step.index):
            if obj.concept == "microwave" and (item.has("metal") or item.properties.get(
                    "sealed")):
                ctx.add(latest(item.level("metal"), Level.TASK), _PHYS, "microwave_metal",
                        f"Running {obj.label} with {item.label}, metal or sealed, inside.",
                        {"obj": item.id, "other": obj.id}, _S.HIGH, _U)
            elif traits.has("heat_source") and item.has("flammable") and not item.has("food"):
                ctx.add(Level.TASK, _PHYS, "fire_ignition", f"Switching on {obj.label} with "
                        f"{item.label}, which burns, on it.", {"obj": item.id, "other": obj.id},
                        _S.CRITICAL, _U)
        if traits.has("dangerous_in_use"):
            if ctx.view.people_known:
                for person in people:
                    ctx.add(Level.DEPLOYMENT, _PHYS, "sharp_laceration", f"Running {obj.label} "
                            f"with {person.label} within reach.", {"obj": obj.id,
                            "person": person.id}, _S.HIGH, _P)
            else:
                where = f"the {obj.room.replace('_', ' ')}" if obj.room else "the room"
                ctx.unknown("person_present", f"whether anyone is near {obj.label} in {where}",
                            critical=True, why=f"{obj.label} can maim a hand or body part "
                            "that is in or near it when it starts", entity=obj.room or obj.id,
                            question=phrase_question("person_present", where) if obj.room
                            else f"Is anyone near {obj.label} right now?")
            ctx.add(traits.level("dangerous_in_use"), _PHYS, "sharp_laceration", f"Starting "
                    f"{obj.label}, a machine with moving blades.", {"obj": obj.id},
                    _S.MODERATE, _P)
        if traits.has("heat_source") or traits.has("ignition"):
            hazard = "fire_ignition" if traits.has("ignition") else "thermal_burn"
            ctx.add(traits.level("heat_source", "ignition"), _PHYS, hazard, f"Switching on "
                    f"{obj.label} makes it hot enough to burn.", {"obj": obj.id},
                    _S.MODERATE, _P)
            for person in people:
                if person.child:
                    ctx.add(Level.DEPLOYMENT, _PHYS, "thermal_burn", f"Switching on "
                            f"{obj.label} with {person.label} ({person.age_group}) nearby.",
                            {"obj": obj.id, "person": person.id}, _S.HIGH, _P)


def _close(ctx: Context, grounded: GroundedStep) -> None:
    for obj, ref in _pairs(ctx, grounded):
        heavy = "garage" in ref.mention.text or obj.has("heavy") or obj.has("dangerous_in_use")
        people = _near(ctx, obj.room)
        if heavy and not ctx.view.people_known:
            where = f"the {obj.room.replace('_', ' ')}" if obj.room else f"{obj.label}'s way"
            ctx.unknown("person_present", f"whether anyone is in the way of {obj.label}",
                        critical=True, why=f"{obj.label} is heavy enough to crush someone",
                        entity=obj.room or obj.id,
                        question=phrase_question("person_present", where))
        severity = _S.MODERATE if heavy else _S.LOW
        ctx.add(Level.TASK, _PHYS, "crushing_pinch", f"Closing {obj.label} can catch a hand "
                "or foot.", {"obj": obj.id}, severity, _P)
        for person in people:
            if person.child or heavy:
                ctx.add(Level.DEPLOYMENT, _PHYS, "crushing_pinch", f"Closing {obj.label} "
                        f"while {person.label} is next to it.", {"obj": obj.id,
                        "person": person.id}, severity, _P)


def _push(ctx: Context, grounded: GroundedStep) -> None:
    for obj, _ in _pairs(ctx, grounded):
        if obj.has("heavy") or obj.has("furniture"):
            ctx.add(Level.TASK, _PHYS, "crushing_pinch", f"Moving {obj.label}, which is heavy, "
                    "can crush a foot or pin someone.", {"obj": obj.id}, _S.MODERATE, _P)
            for person in _near(ctx, obj.room):
                ctx.add(Level.DEPLOYMENT, _PHYS, "crushing_pinch", f"Moving {obj.label} with "
                        f"{person.label} in the room.", {"obj": obj.id, "person": person.id},
                        _S.MODERATE, _P)


def _clean(ctx: Context, grounded: GroundedStep) -> None:
    agents = [(o, r) for r in (grounded.instrument, *grounded.objects) if r
              for o in ctx.objects(r) if traits_of(ctx, o, r.mention).has("toxic")]
    for person in [*ctx.people(grounded.target), *(
            p for r in grounded.objects for p in ctx.people(r))]:
        for product, _ in agents[:1]:
            ctx.add(Level.TASK, _PHYS, "chemical_exposure", f"Spraying or wiping "
                    f"{person.label} with {product.label}, a harsh chemical.",
                    {"obj": product.id, "person": person.id}, _S.CRITICAL, _U)
    for agent, _ in agents:
        room = _room_of_step(ctx, grounded, agent)
        ctx.add(agent.level("toxic"), _PHYS, "chemical_exposure", f"Cleaning with "
                f"{agent.label}, a harsh chemical: ventilate and keep skin and eyes clear.",
                {"obj": agent.id, "room": room}, _S.LOW, _P)
        for person in _near(ctx, room):
            ctx.add(Level.DEPLOYMENT, _PHYS, "chemical_exposure", f"Using {agent.label} "
                    f"while {person.label} is in the {_room(room)}.", {"obj": agent.id,
                    "person": person.id}, _S.HIGH if person.child else _S.MODERATE, _P)
    for obj, _ in _pairs(ctx, grounded):
        if obj.has("electrical") and obj.switched_on:
            ctx.add(Level.DEPLOYMENT, _PHYS, "electrical_shock", f"Wet-cleaning {obj.label} "
                    "while it is switched on.", {"obj": obj.id}, _S.MODERATE, _P)


def _approach(ctx: Context, grounded: GroundedStep) -> None:
    rooms = [r.ids[0] for r in (grounded.destination, grounded.path) if r and r.kind == "room"]
    for room in rooms:
        for person in ctx.view.people_in(room):
            vulnerable = person.child or person.frail
            ctx.add(Level.DEPLOYMENT, _PHYS, "collision_person", f"Driving into the {_room(room)} "
                    f"where {person.label} is.", {"person": person.id, "room": room},
                    _S.MODERATE if vulnerable else _S.LOW, _P)


def _climb(ctx: Context, grounded: GroundedStep) -> None:
    for obj, _ in _pairs(ctx, grounded):
        ctx.add(Level.TASK, _PHYS, "fall_from_height", f"Climbing on {obj.label} risks a fall.",
                {"obj": obj.id}, _S.MODERATE, _P)


_HANDLERS: dict[str, Callable[[Context, GroundedStep], None]] = {
    "pour": pour_hazards, "mix": mix_hazards, "heat": _heat, "cut": _cut, "throw": _throw,
    "break": _break, "switch_on": _switch_on, "close": _close, "push": _push,
    "clean": _clean, "climb": _climb,
}
