"""Situations in the home where the commanded act, or the state it leaves, is itself the harm.

In: the `Context` and the situation tables (`knowledge/hazard_situations.json`). Out:
proposals for: reacting chemicals used together in one cleaning job; a meltable or electric
appliance put on a hob; a mains appliance used by a bath or shower someone is in; a hot iron left
on fabric; cooking left on when everyone goes out; a tap filling a plugged sink while the robot
goes elsewhere; things stored above a baby's cot; chemicals put low where a small child lives;
the robot parking itself in an exit; photographing or recording people in private places or
others' private papers and screens; stairs for a robot without a stair skill; pushing something
far heavier than the robot can move. Unpreventable unless stated. Never fails.
"""

from __future__ import annotations

import re
from functools import cache

from app.domain.analysis.context import Context
from app.domain.analysis.situation_base import (
    any_phrase,
    awake_carer_stays,
    contains,
    everyone_leaves,
    load_situations,
    robot_leaves_room,
    substances_in,
)
from app.domain.analysis.word_filter import may_occur
from app.domain.models import Category, Level, Preventability, Severity

_P, _U, _X = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE, Preventability.UNKNOWN
_S = Severity
_PHYS, _PSY, _OPS, _CON = (Category.PHYSICAL, Category.PSYCHOLOGICAL, Category.OPERATIONAL,
                           Category.CONSEQUENTIAL)
_PLACING = frozenset({"place", "transport", "heat", "handover", "remove", "push"})
_MOVING = frozenset({"navigate", "transport", "pick", "handover", "serve", "place", "remove"})
# "the kids' doorway", "Mum's bedroom door": the owner does not change what is blocked.
_OWNER_WORD = re.compile(r"\s[\w]+(?:'s|s')(?=\s)")
_SOFTENERS = frozenset({"just", "please", "now", "go", "and", "then", "so", "you", "can",
                        "could", "would"})
_POSSESSIVE = re.compile(r"\b(his|her|their|[a-z]+'s|[a-z]+s')\s+(?:\w+\s+)?$")


def situation_home_hazards(ctx: Context) -> None:
    """Add the home situation hazards of the whole command."""
    if not any(not g.step.negated for g in ctx.steps):
        return
    _chemicals_combined(ctx)
    _placements(ctx)
    _above_cot(ctx)
    _cooking_left(ctx)
    _blades_in_water(ctx)
    _unattended_fill(ctx)
    _low_chemicals(ctx)
    _robot_in_exit(ctx)
    _capture(ctx)
    _stairs(ctx)
    _safety_device(ctx)


def _above_cot(ctx: Context) -> None:
    """Something put above a cot ("on the shelf over the crib") can fall on the baby."""
    data = load_situations()
    babies = [p for p in ctx.view.real_people() if p.young or p.age_group == "infant"]
    placing = any(g.step.action in _PLACING and not g.step.negated for g in ctx.steps)
    if not (babies and placing):
        return
    cots = "|".join(re.escape(w) for w in data.group("infant_sleeper_places"))
    above = "|".join(re.escape(w) for w in data.group("above_preps"))
    pattern = rf"\b(?:{above})\s+(?:the\s+|her\s+|his\s+|their\s+|\w+'s?\s+)?(?:{cots})\b"
    if re.search(pattern, ctx.text):
        ctx.add(Level.DEPLOYMENT, _PHYS, "falling_object", "Something stored above a baby's "
                "cot can fall on the baby.", {"person": babies[0].id}, _S.CRITICAL, _U)


def _postures(ctx: Context) -> set[str]:
    scene = ctx.request.scene
    return {(p.posture or "").lower() for p in scene.people} - {""} if scene else set()


def _segments(text: str) -> list[str]:
    return [s.strip() for s in re.split(r"\s[,;.!?:]\s|\sthen\s", f" {text} ") if s.strip()]


def _chemicals_combined(ctx: Context) -> None:
    data = load_situations()
    text = ctx.text
    if not (any_phrase(text, data.group("clean_words")) and any_phrase(
            text, data.group("combine_cues"))):
        return
    names = substances_in(ctx, text)
    for grounded in ctx.steps:
        for ref in grounded.objects:
            names += [o.contents for o in ctx.objects(ref) if o.contents and o.contents
                      not in names]
    classes = {n: ctx.knowledge.substances[n].classes for n in names}
    for i, first in enumerate(names):
        for second in names[i + 1:]:
            for reaction in ctx.knowledge.reactions:
                a, b = reaction.classes
                if reaction.needs_heat or not ((a in classes[first] and b in classes[second])
                                               or (b in classes[first] and a in classes[second])):
                    continue
                ctx.add(Level.TASK, _PHYS, "chemical_mixing", f"Using {first.replace('_', ' ')}"
                        f" and {second.replace('_', ' ')} together can release "
                        f"{reaction.product}.", {}, _S(reaction.severity),
                        _X if reaction.uncertain else _U)


def _placements(ctx: Context) -> None:
    data = load_situations()
    in_water = not _postures(ctx).isdisjoint(data.group("in_water_postures")) or any_phrase(
        ctx.text, data.group("in_water_words")) is not None
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action is None:
            continue
        objects = [o for r in grounded.objects for o in ctx.objects(r)]
        places = ctx.objects(grounded.destination)
        for obj in objects:
            for place in places:
                if place.id == obj.id:
                    continue
                if place.has("heat_source") and place.concept != "microwave" and (
                        obj.has("meltable") or (obj.has("electrical") and not obj.has("fixed"))):
                    lit = place.switched_on is True
                    ctx.add(Level.DEPLOYMENT, _PHYS, "fire_ignition", f"{obj.label}, electric "
                            f"or plastic, put on {place.label}: it melts and can catch fire.",
                            {"obj": obj.id, "other": place.id},
                            _S.CRITICAL if lit else _S.HIGH, _U)
                hot = obj.has("heat_source") and (obj.switched_on is True or obj.has("hot"))
                if hot and place.has("flammable") and (step.keeps_state or robot_leaves_room(
                        ctx) or step.condition):
                    ctx.add(Level.DEPLOYMENT, _PHYS, "fire_ignition", f"{obj.label}, hot, left "
                            f"on {place.label}, which burns, with no one watching.",
                            {"obj": place.id, "other": obj.id}, _S.CRITICAL, _U)
                if step.destination_prep in data.group("above_preps") and any(
                        contains(place.label.lower(), w) or place.type.lower() == w
                        for w in data.group("infant_sleeper_places")):
                    ctx.add(Level.DEPLOYMENT, _PHYS, "falling_object", f"{obj.label} stored "
                            f"above {place.label}: it can fall on the baby.",
                            {"obj": obj.id, "other": place.id}, _S.CRITICAL, _U)
            wet = any_phrase(step.text, data.group("wet_places"))
            if (wet and in_water and obj.has("electrical") and not obj.has("fixed")
                    and step.action in ("switch_on", *_PLACING)):
                ctx.add(Level.DEPLOYMENT, _PHYS, "electrical_shock", f"{obj.label}, a mains "
                        f"appliance, used by the {wet} while someone is in the water.",
                        {"obj": obj.id}, _S.CRITICAL, _U)


def _blades_in_water(ctx: Context) -> None:
    """Blades left under opaque water (a washing-up bowl, soapy sink) cut the next hand in."""
    murky_words = load_situations().group("murky_water_words")
    if not may_occur(ctx.text, murky_words):
        return
    for segment in _segments(ctx.text):
        murky = any_phrase(segment, murky_words)
        if not murky or not contains(segment, "leave"):
            continue
        for word in segment.split():
            concept = ctx.knowledge.noun_concept(word)
            if concept and "sharp" in ctx.knowledge.concepts[concept].props:
                ctx.add(Level.TASK, _PHYS, "sharp_laceration", f"Blades ({word}) left hidden "
                        f"in {murky}: whoever reaches in next cuts their hand.", {},
                        _S.HIGH, _U)
                return


def _cooking_left(ctx: Context) -> None:
    data = load_situations()
    if not everyone_leaves(ctx) or awake_carer_stays(ctx) is True:
        return
    if any(g.step.action == "switch_off" and not g.step.negated for g in ctx.steps):
        return
    cooking = re.search(data.records["cooking_temperature_pattern"], ctx.text) or any_phrase(
        ctx.text, data.group("cooking_words"))
    switched = [o for g in ctx.steps if g.step.action == "switch_on" and not g.step.negated
                for r in g.objects for o in ctx.objects(r) if o.has("heat_source")]
    if not (cooking or switched):
        return
    ovens = switched or [o for o in ctx.view.objects.values() if o.has("heat_source") and
                         o.concept in ("oven", "stove")]
    oven = ovens[0] if ovens else None
    ctx.add(Level.TASK, _CON, "appliance_left_on", "Cooking is left going while everyone goes "
            "out: an unattended oven or hob can start a fire.",
            {"obj": oven.id if oven else None}, _S.CRITICAL, _U)


def _unattended_fill(ctx: Context) -> None:
    data = load_situations()
    text = ctx.text
    plugged = any_phrase(text, data.group("plug_words")) or any(
        o.properties.get(k) in (True, "true", "yes") for o in ctx.view.objects.values()
        for k in ("plugged", "blocked", "clogged"))
    if plugged and any_phrase(text, data.group("water_fill_words")) and robot_leaves_room(ctx):
        sink = next((o for o in ctx.view.objects.values() if o.concept in ("sink", "bathtub")),
                    None)
        ctx.add(Level.TASK, _CON, "flooding", "Water is left running into a plugged basin "
                "with nobody watching it: it overflows.", {"obj": sink.id if sink else None},
                _S.HIGH, _U)


def _low_chemicals(ctx: Context) -> None:
    data = load_situations()
    small = [p for p in ctx.view.real_people() if p.young or p.age_group == "infant"]
    if not small:
        return
    for segment in _segments(ctx.text):
        names = [n for n in substances_in(ctx, segment) if ctx.knowledge.substances[n].props & {
            "toxic", "corrosive", "medication"}]
        low = any_phrase(segment, data.group("low_open_places"))
        if names and low and not any_phrase(segment, data.group("secured_words")):
            ctx.add(Level.DEPLOYMENT, _CON, "hazard_left_in_reach", f"{names[0].replace('_', ' ')}"
                    f" put on the {low} where {small[0].label} can reach it.",
                    {"person": small[0].id}, _S.CRITICAL, _U)


def _robot_in_exit(ctx: Context) -> None:
    data = load_situations()
    if not may_occur(ctx.text, data.group("exit_words")):
        return
    for segment in _segments(ctx.text):
        segment = _OWNER_WORD.sub("", f" {segment} ").strip()
        exit_word = any_phrase(segment, data.group("exit_words"))
        if not exit_word:
            continue
        words = segment.split()
        while words and words[0] in _SOFTENERS:
            words = words[1:]  # "just park yourself", "go and stand"
        station = any(" ".join(words[:n]) in data.group("robot_station_verbs") for n in (1, 2, 3))
        blocks = any(contains(segment, f"{prep} the {exit_word}") or contains(
            segment, f"{prep} {exit_word}") for prep in data.group("exit_block_preps")) if (
            exit_word) else False
        if station and blocks and any_phrase(ctx.text, data.group("stay_words")):
            ctx.add(Level.TASK, _CON, "blocked_exit", f"The robot parks itself in the "
                    f"{exit_word} and stays: the way out is blocked.", {}, _S.HIGH, _U)


def _capture(ctx: Context) -> None:
    data = load_situations()
    text = ctx.text
    if not any_phrase(text, data.group("capture_words")):
        return
    private = any_phrase(text, data.group("private_state_words"))
    someone = any_phrase(text, data.group("anyone_words")) or not _postures(ctx).isdisjoint(
        data.group("private_postures"))
    if private and someone:
        ctx.add(Level.TASK, _PSY, "privacy_intrusion", f"Photographing or recording people in "
                f"a private place ({private}).", {}, _S.HIGH, _U)
    for match in _info_pattern(data.group("private_info_words")).finditer(text):
        word = match.group(1)
        owner = _POSSESSIVE.search(text[:match.start()])
        if owner and owner.group(1) not in data.group("own_owner_words"):
            ctx.add(Level.TASK, _PSY, "surveillance", f"Capturing someone else's private "
                    f"{word} ({owner.group(1)} {word}).", {}, _S.HIGH, _U)
            return


@cache
def _info_pattern(words: tuple[str, ...]) -> re.Pattern[str]:
    alternatives = "|".join(re.escape(w) for w in sorted(words, key=len, reverse=True))
    return re.compile(rf"(?<![\w'])({alternatives})(?![\w'])")


def _stairs(ctx: Context) -> None:
    data = load_situations()
    robot = ctx.request.robot
    if robot is None or robot.skills is None or any_phrase(ctx.text, data.group("lift_words")):
        return
    have = {s.lower().replace("-", "_").replace(" ", "_") for s in robot.skills}
    if not have.isdisjoint(data.group("stair_skills")):
        return
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action not in _MOVING:
            continue
        rooms = [i for r in (grounded.destination, *grounded.objects) if r and r.kind == "room"
                 for i in r.ids]
        upstairs = any(any(w in room for w in data.group("stairs_room_words")) for room in rooms)
        if (
                any_phrase(step.text, data.group("stairs_words")) or upstairs):
            ctx.add(Level.USER, _OPS, "missing_skill", f"'{step.text}' means going up or down "
                    "stairs, and the robot lists no stair-climbing skill.", {}, _S.HIGH, _U)
            return


def _safety_device(ctx: Context) -> None:
    """A smoke or CO alarm, extinguisher or sprinkler disabled leaves no warning of a fire."""
    data = load_situations()
    if not may_occur(ctx.text, data.group("safety_devices")):
        return
    for segment in _segments(ctx.text):
        device = any_phrase(segment, data.group("safety_devices"))
        if not device:
            continue
        renewed = any(contains(ctx.text, w) for w in ("new battery", "new batteries", "replace",
                                                      "fresh battery", "fresh batteries", "test"))
        if device and not renewed and any_phrase(segment, data.group("disable_words")):
            ctx.add(Level.TASK, _CON, "safety_barrier_removed", f"Disabling the {device} "
                    "leaves the home without warning of a fire or gas.", {}, _S.HIGH, _U)
            return
