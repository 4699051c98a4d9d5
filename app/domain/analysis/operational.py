"""Operational hazards: payload, skills, sensors, reach, routes, speed, grounding.

In: the `Context` (the robot profile may be absent: then nothing about the robot is claimed).
Out: operational proposals at the user level (robot capabilities) or deployment level (scene).
Skills and sensors are only checked when the request lists them; a missing mass is reported as
a non-critical unknown rather than guessed. Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep
from app.domain.analysis.scene_view import ObjectView, PersonView
from app.domain.analysis.situation_base import any_phrase, contains, load_situations
from app.domain.analysis.traits import traits_of
from app.domain.models import Category, Confidence, Level, Preventability, Severity

_P, _U = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE
_S = Severity
_OPS = Category.OPERATIONAL
_LIFTING = frozenset({"transport", "handover", "serve", "pick", "place", "remove", "throw",
                      "pour"})
# Head verbs that take a person's whole weight ("lift grandma out", "carry him up", "hoist her").
_PERSON_LIFT_VERBS = frozenset({"lift", "transfer", "carry", "reposition", "hoist", "heave",
                                "haul", "scoop", "sweep", "raise", "pick", "cart", "piggyback"})
_NOT_LIFTING = frozenset({"pick out", "pick on", "carry on", "raise with", "pick at"})
_PERSON_MASS_KG = {"infant": 8.0, "child": 25.0, "teen": 55.0, "adult": 70.0,
                   "older_adult": 65.0}
# Doing these without the skill for them endangers someone whatever the object.
_RISKY_ACTIONS = frozenset({"cut", "heat", "assist", "pour", "climb", "throw"})
_PLACE_LIKE = ("fixed", "furniture", "surface", "appliance", "storage", "container")
_RISKY_TRAITS = ("sharp", "hot", "toxic", "heavy", "medication", "fragile", "heat_source",
                 "dangerous_in_use")


def operational_hazards(ctx: Context) -> None:
    """Add the operational hazards of every non-negated step."""
    robot = ctx.request.robot
    _road_crossing(ctx)
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action is None:
            continue
        if robot is not None and robot.payload_kg is not None:
            _payload(ctx, grounded, robot.payload_kg)
        elif step.action == "assist":
            _support_unknown(ctx, grounded)
        if robot is not None and robot.skills is not None:
            _skills(ctx, grounded, robot.skills)
        if robot is not None and robot.sensors is not None:
            _sensors(ctx, grounded, robot.sensors)
        _reach_and_route(ctx, grounded)
        if ctx.cue("hurry"):
            flat_out = ctx.cue("max_speed")
            for person in _people_on_way(ctx, grounded, everywhere=flat_out):
                level = Level.TASK if person.virtual else Level.DEPLOYMENT
                if flat_out and (person.child or person.frail) and not person.is_user:
                    # Told to go flat out where a child or frail person is: obeying is the harm.
                    ctx.add(level, _OPS, "speed_near_people", f"Driving at full speed where "
                            f"{person.label} is; a child or frail person cannot get out of the "
                            "way.", {"person": person.id}, _S.HIGH, _U)
                else:
                    ctx.add(level, _OPS, "speed_near_people", f"Hurrying near {person.label}.",
                            {"person": person.id}, _S.MODERATE, _P)


def _support_unknown(ctx: Context, grounded: GroundedStep) -> None:
    """Steadying or helping someone move ("give Dad a hand up the stairs") puts their weight on
    the robot; with no stated payload, whether it can bear it is the question."""
    for person in (p for r in grounded.objects for p in ctx.people(r) if not p.is_user):
        ctx.unknown("robot_payload", f"whether the robot can bear {person.label}'s weight",
                    critical=True, why=f"helping {person.label} move puts their weight on the "
                    "robot, and its payload is not stated", entity=person.id,
                    question=f"Can the robot safely take {person.label}'s weight if they lean "
                    "on it or stumble? Its payload is not stated.")
        return


def _road_crossing(ctx: Context) -> None:
    """Crossing a road ("the postbox across the road") is traffic: a home robot needs a skill
    for it that it lists, or the gate asks."""
    data = load_situations()
    if not any(not g.step.negated and g.step.action is not None for g in ctx.steps) or (
            any_phrase(ctx.text, data.group("road_crossing_phrases")) is None):
        return
    robot = ctx.request.robot
    if robot is None or robot.skills is None:
        ctx.unknown("robot_skills", "whether the robot can cross a road safely", critical=True,
                    why="the task crosses a road with traffic", entity=None,
                    question="Can the robot cross a road with traffic safely?")
        return
    if _canonical(robot.skills, ctx.knowledge.skill_aliases).isdisjoint(
            data.group("road_skills")):
        ctx.add(Level.USER, _OPS, "missing_skill", "The task crosses a road; the robot lists "
                "no skill for traffic.", {}, _S.HIGH, _U)


def _worked_on_in_place(ctx: Context, grounded: GroundedStep, obj: ObjectView) -> bool:
    """A fixture or furniture named by "clear/load/lay/unpack..." is worked on, not lifted."""
    return (grounded.step.verb or "") in ctx.knowledge.place_object_verbs and any(
        obj.has(p) for p in _PLACE_LIKE)


def _rolled(ctx: Context, grounded: GroundedStep, obj: ObjectView) -> bool:
    """Wheeled things ("wheel the bin", a trolley, a wheelchair) are rolled, not lifted."""
    rolling = load_situations().group("rolling_words")
    verb = (grounded.step.verb or "").split(" ")[0]
    return verb in ("wheel", "roll", "trundle") or any(
        contains(f"{obj.type} {obj.name or ''}".lower(), w) for w in rolling)


def _pushed(ctx: Context, grounded: GroundedStep, payload: float) -> None:
    """Pushing or dragging something many times the payload: the robot cannot move it safely."""
    factor = float(load_situations().records["push_factor"])
    for ref in grounded.objects:
        for obj in ctx.objects(ref):
            if obj.mass_kg is None or _rolled(ctx, grounded, obj) or obj.virtual:
                continue
            # A kind's typical mass may be far from this one's: only a clear excess counts.
            limit = factor * payload * (1.0 if obj.mass_given else 2.0)
            if obj.mass_kg > limit:
                ctx.add(Level.USER, _OPS, "payload_exceeded", f"{obj.label} weighs about "
                        f"{obj.mass_kg:g} kg, far more than the robot can push or pull safely "
                        f"(payload {payload:g} kg).", {"obj": obj.id}, _S.HIGH, _U)


def _payload(ctx: Context, grounded: GroundedStep, payload: float) -> None:
    if grounded.step.action == "push":
        _pushed(ctx, grounded, payload)
    if grounded.step.action in _LIFTING:
        for ref in grounded.objects:
            for obj in ctx.objects(ref):
                if _worked_on_in_place(ctx, grounded, obj) or _rolled(ctx, grounded, obj):
                    continue
                if obj.mass_kg is None:
                    if obj.has("furniture") or obj.has("heavy"):
                        ctx.unknown("mass_kg", f"the mass of {obj.label}", critical=False,
                                    why="it may exceed the robot's payload", entity=obj.id,
                                    question=f"How heavy is {obj.label}?")
                # A thing the scene does not list has only a guessed mass: never certain.
                elif obj.mass_kg > payload and (obj.mass_given or (
                        obj.mass_kg > 2 * payload and not obj.virtual)):
                    ctx.add(Level.USER, _OPS, "payload_exceeded", f"{obj.label} weighs about "
                            f"{obj.mass_kg:g} kg, more than the robot's {payload:g} kg payload: "
                            "it may drop it.", {"obj": obj.id}, _S.HIGH, _U)
                elif obj.mass_kg > payload:
                    # Only a typical mass for its kind: this one may be lighter; the contract's
                    # load check decides at run time.
                    ctx.add(Level.USER, _OPS, "payload_exceeded", f"{obj.label} typically "
                            f"weighs about {obj.mass_kg:g} kg, near or over the robot's "
                            f"{payload:g} kg payload.", {"obj": obj.id}, _S.MODERATE, _P,
                            Confidence.UNCERTAIN)
                    ctx.unknown("mass_kg", f"the mass of {obj.label}", critical=False,
                                why="its kind is often heavier than the robot's payload",
                                entity=obj.id, question=f"How heavy is {obj.label}?")
    if _lifts_whole_body(grounded.step.verb):
        for ref in grounded.objects:
            for person in ctx.people(ref):
                mass = person.properties.get("mass_kg") or _PERSON_MASS_KG.get(
                    person.age_group or "adult", 70.0)
                if float(mass) > payload:
                    ctx.add(Level.USER, _OPS, "payload_exceeded", f"Lifting {person.label} "
                            f"(about {float(mass):g} kg) is beyond the robot's {payload:g} kg "
                            "payload.", {"person": person.id}, _S.CRITICAL, _U)
                _transfer_skill(ctx, person)


def _transfer_skill(ctx: Context, person: PersonView) -> None:
    """Lifting or carrying a person is a patient transfer: a care skill of its own."""
    robot = ctx.request.robot
    if robot is None or robot.skills is None:
        return
    have = _canonical(robot.skills, ctx.knowledge.skill_aliases)
    needed = load_situations().records["care_tasks"]["transfer"]["skills"]
    if have.isdisjoint(needed):
        ctx.add(Level.USER, _OPS, "missing_skill", f"Lifting or carrying {person.label} is a "
                "person transfer, a care skill the robot does not list.",
                {"person": person.id}, _S.HIGH, _U)


def _lifts_whole_body(verb: str | None) -> bool:
    """Whether a verb (maybe phrasal: "lift out", "pick up") takes a body's whole weight."""
    verb = (verb or "").strip()
    return verb not in _NOT_LIFTING and verb.split(" ")[0] in _PERSON_LIFT_VERBS and (
        verb != "pick")


def _canonical(names: list[str], aliases: dict[str, str]) -> set[str]:
    out = set()
    for name in names:
        key = name.lower().replace("-", "_").replace(" ", "_")
        out |= {key, aliases.get(key, key)}
    return out


def _risky(ctx: Context, grounded: GroundedStep) -> bool:
    if grounded.recipient is not None or grounded.step.action in _RISKY_ACTIONS:
        return True
    return any(traits_of(ctx, o, r.mention).has(t) for r in grounded.objects
               for o in ctx.objects(r) for t in _RISKY_TRAITS)


def _skills(ctx: Context, grounded: GroundedStep, skills: list[str]) -> None:
    have = _canonical(skills, ctx.knowledge.skill_aliases)
    action = grounded.step.action or ""
    if action == "transport" and any("tray" in s or s.startswith("carry") for s in have):
        # A tray or carrier robot transports what people load onto it.
        have |= {"pick", "place", "handover"}
    first = next((i for r in grounded.objects for i in r.ids), None)
    for group in ctx.knowledge.verb_skills.get(action, ()):
        if have.isdisjoint(group):
            risky = _risky(ctx, grounded)
            ctx.add(Level.USER, _OPS, "missing_skill", f"'{grounded.step.text}' needs the "
                    f"{' or '.join(group)} skill, which the robot does not list.",
                    {"obj": first}, _S.HIGH if risky else _S.MODERATE, _U)


def _sensors(ctx: Context, grounded: GroundedStep, sensors: list[str]) -> None:
    have = _canonical(sensors, ctx.knowledge.sensor_aliases)
    action = grounded.step.action or ""
    for group in ctx.knowledge.verb_sensors.get(action, ()):
        if have.isdisjoint(group) and have.isdisjoint(
                {ctx.knowledge.sensor_aliases.get(g, g) for g in group}):
            # Misreading while handling something dangerous (a knife, medicines) harms someone.
            risky = _risky(ctx, grounded) or _handles_medication(ctx)
            ctx.add(Level.USER, _OPS, "missing_sensor", f"'{grounded.step.text}' needs a "
                    f"{group[0].replace('_', ' ')}, which the robot does not list.", {},
                    _S.HIGH if risky else _S.MODERATE, _U)
    moving = action in ("navigate", "transport", "handover", "serve")
    if moving and ctx.view.real_people() and have.isdisjoint({"lidar", "camera"}):
        ctx.add(Level.USER, _OPS, "missing_sensor", "Moving among people without a camera or "
                "lidar to see them.", {}, _S.HIGH, _U)


def _handles_medication(ctx: Context) -> bool:
    """Whether any step of the command acts on medicines (by scene object or by word)."""
    if any(traits_of(ctx, o, r.mention).has("medication") for g in ctx.steps
           if not g.step.negated for r in g.objects for o in ctx.objects(r)):
        return True
    return any(ctx.knowledge.noun_concept(w) in ("medication", "pill_bottle")
               for w in ctx.text.split())


def _reach_and_route(ctx: Context, grounded: GroundedStep) -> None:
    action = grounded.step.action or ""
    for ref in grounded.objects:
        for obj in ctx.objects(ref):
            if action in _LIFTING and not obj.virtual and not _worked_on_in_place(
                    ctx, grounded, obj):
                record = ctx.knowledge.ai2thor_types.get(obj.type)
                fixed = obj.has("fixed") or (record is not None and not record.get(
                    "pickupable") and not record.get("moveable"))
                if fixed and action != "pour":
                    ctx.add(Level.DEPLOYMENT, _OPS, "non_manipulable", f"{obj.label} is a "
                            "fixture the robot cannot pick up or carry.", {"obj": obj.id},
                            _S.MODERATE, _U)
            high = {"top", "shelf"} <= obj.place_words or "high" in obj.place_words
            if obj.properties.get("elevated") or high:
                ctx.add(Level.DEPLOYMENT, _OPS, "reach_limit", f"{obj.label} sits high up, "
                        "near the limit of the robot's reach.", {"obj": obj.id}, _S.LOW, _P)
            if len(ref.ids) > 1:
                ctx.add(Level.DEPLOYMENT, _OPS, "object_grounding", f"'{ref.mention.text}' "
                        f"matches {len(ref.ids)} objects.", {"obj": ref.ids[0]}, _S.LOW, _P)
    destination = grounded.destination
    if destination is not None and destination.kind == "room" and ctx.view.rooms:
        room = destination.ids[0]
        start = ctx.view.robot_room
        route = ctx.rooms_between(start, room)
        unknown_room = room not in ctx.view.rooms
        unreachable = bool(ctx.view.connections) and start and len(route) == 2 and not any(
            {start, room} == set(c) for c in ctx.view.connections) and start != room
        if unknown_room or unreachable:
            ctx.add(Level.DEPLOYMENT, _OPS, "unreachable_location", f"No known route to the "
                    f"{room.replace('_', ' ')}.", {"room": room}, _S.MODERATE, _U)


def _people_on_way(ctx: Context, grounded: GroundedStep, *, everywhere: bool = False
                   ) -> list[PersonView]:
    rooms = {r.ids[0] for r in (grounded.destination, grounded.path) if r and r.kind == "room"}
    if everywhere:
        # Told to go flat out: every room the command names is on the way.
        rooms |= {p.room for p in ctx.view.people.values()
                  if p.room and _names_room(ctx, ctx.text, p.room)}
    if grounded.step.action == "navigate":
        # "laps of the lounge", "down the hall": any room the clause names is driven through.
        rooms |= {p.room for p in ctx.view.people.values()
                  if p.room and _names_room(ctx, grounded.step.text, p.room)}
        rooms |= {p.room for r in (grounded.target, *grounded.objects) for p in ctx.people(r)
                  if p.room}
    rooms |= {p.room for p in ctx.people(grounded.recipient) if p.room}
    found = [p for room in sorted(rooms) for p in ctx.view.people_in(room)]
    found += [p for r in (*grounded.objects, grounded.recipient, grounded.target)
              for p in ctx.people(r) if not p.is_user]
    return list({p.id: p for p in found}.values())


def _names_room(ctx: Context, text: str, room: str | None) -> bool:
    """Whether the clause names the room (by its id or any word for it)."""
    if not room:
        return False
    words = {w for w, r in ctx.knowledge.room_words.items() if r == room}
    words.add(room.replace("_", " "))
    padded = f" {text} "
    return any(f" {w} " in padded for w in words)
