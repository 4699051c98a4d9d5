"""Psychological hazards: recording, surveillance, startling, intimidation, dignity, distress.

In: the `Context`. Out: psychological proposals. Covert recording, recording in bedrooms and
bathrooms or of sleeping people, scaring and intimidating are the commanded harm itself
(unpreventable); open, consented or caring observation is preventable. Discarding someone
else's belongings asks first (unknown preventability). Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep
from app.domain.analysis.scene_view import PersonView, spaced_name
from app.domain.analysis.situation_base import (
    any_phrase,
    contains,
    load_situations,
    named_people,
)
from app.domain.analysis.traits import traits_of
from app.domain.models import Category, Level, Preventability, Severity

_P, _U, _X = Preventability.PREVENTABLE, Preventability.UNPREVENTABLE, Preventability.UNKNOWN
_S = Severity
_PSY = Category.PSYCHOLOGICAL
_COVERT_VERBS = frozenset({"spy", "spy on", "snoop", "snoop on", "eavesdrop", "eavesdrop on",
                           "listen in", "listen in on", "stalk", "tail", "read", "go through",
                           "report on", "log"})
_INTIMATE_VERBS = frozenset({"undress", "bathe", "shower", "toilet", "change", "dress"})
_TOUCH_VERBS = frozenset({"touch", "kiss", "hug", "tickle", "massage"})
_HARM_VERBS = frozenset({"hit", "strike", "poke", "trip", "kick", "restrain"})
_DEMEAN_VERBS = frozenset({"mock", "insult", "humiliate", "laugh at", "embarrass", "tease"})
_NOISY_VERBS = frozenset({"vacuum", "hoover", "blend", "blast", "play music"})
# "remove"-class verbs that return or fetch a thing rather than get rid of it.
_NOT_DISCARDING = frozenset({"put back", "put out of reach", "get out", "take out", "strip",
                             "strip off", "peel off", "move away"})
_DESTROY_VERBS = frozenset({"shred", "burn", "destroy", "smash", "tear", "rip", "delete",
                            "erase", "wreck", "ruin", "cut", "snap", "crush", "flush"})
_RUBBISH_WORDS = frozenset({"bin", "bins", "dustbin", "wheelie", "skip", "rubbish", "trash",
                            "garbage", "recycling", "compost", "waste", "shredder", "fire"})
_OWN = frozenset({"me", "my", "user", "mine", "our", "ours", "i"})
_PRIVATE_ROOMS = ("bedroom", "bathroom", "toilet", "nursery", "shower", "restroom", "bath",
                  "undress", "changing", "naked", "showers", "showering", "bathing")


def social_hazards(ctx: Context) -> None:
    """Add the psychological hazards of every non-negated step."""
    for grounded in ctx.steps:
        step = grounded.step
        if step.negated or step.action is None:
            continue
        action, verb = step.action, step.verb or ""
        if action in ("record", "watch") or (verb == "follow" and ctx.cue("covert")):
            _observe(ctx, grounded)
        elif action == "wake":
            for person in _people(ctx, grounded):
                ctx.add(_lvl(person), _PSY, "startling", f"Waking {person.label}: approach "
                        "slowly and speak before touching.", {"person": person.id},
                        _S.MODERATE if person.frail else _S.LOW, _P)
        elif action == "scare":
            for person in _people(ctx, grounded) or _scared_anyway(ctx, grounded):
                fragile = person.frail or person.asleep or person.child
                ctx.add(_lvl(person), _PSY, "startling", f"Deliberately startling "
                        f"{person.label}.", {"person": person.id},
                        _S.CRITICAL if fragile else _S.HIGH, _U)
        elif action == "intimidate":
            for person in _people(ctx, grounded):
                if verb in _HARM_VERBS:
                    ctx.add(Level.TASK, Category.PHYSICAL, "collision_person", f"Striking or "
                            f"restraining {person.label}.", {"person": person.id},
                            _S.CRITICAL, _U)
                elif verb in _DEMEAN_VERBS:
                    ctx.add(Level.TASK, _PSY, "dignity_violation", f"Mocking or humiliating "
                            f"{person.label}.", {"person": person.id}, _S.HIGH, _U)
                else:
                    ctx.add(Level.TASK, _PSY, "intimidation", f"Threatening, chasing or "
                            f"cornering {person.label}.", {"person": person.id}, _S.HIGH, _U)
        elif action == "assist":
            _assist(ctx, grounded, verb)
        elif verb.split(" ")[0] in _TELLING_VERBS:
            _frightening_words(ctx, grounded)
        if (action in ("remove", "break", "throw") and verb not in _NOT_DISCARDING) or (
                action == "place" and _into_rubbish(ctx, grounded)) or (
                verb.split(" ")[0] in _DESTROY_VERBS):
            _belongings(ctx, grounded)
        if verb in _NOISY_VERBS or (action in ("switch_on", "clean", "play") and any(
                o.has("noisy") for r in grounded.objects for o in ctx.objects(r))):
            _noise(ctx, grounded)


_YOUNG_GROUPS = frozenset({"child", "infant", "toddler"})
_TELLING_VERBS = frozenset({"tell", "say", "warn", "whisper", "explain", "announce"})


def _frightening_words(ctx: Context, grounded: GroundedStep) -> None:
    """Telling a child something frightening ("a monster in the loft eats children") to steer
    them is the harm itself; so is telling anyone, when the command says to make it convincing.
    """
    data = load_situations()
    text = grounded.step.text
    if any_phrase(text, data.group("fear_words")) is None:
        return
    told = [p for p in named_people(ctx, text) if not p.is_user]
    if not told and any(contains(text, word) for word, role in ctx.knowledge.role_words.items()
                        if role.name == "child" or role.age_group in _YOUNG_GROUPS):
        told = ctx.view.children()  # "tell the kids": children in general, so these children
    meant = any_phrase(ctx.text, data.group("frighten_cues")) is not None
    for person in told:
        if person.child or person.young or person.frail or meant:
            ctx.add(_lvl(person), _PSY, "emotional_distress", f"Telling {person.label} "
                    "something frightening to make them do as they are told.",
                    {"person": person.id}, _S.HIGH, _U)
            return


def _lvl(person: PersonView) -> Level:
    if person.is_user:
        return Level.USER  # what is known of the user comes from the user profile
    return Level.TASK if person.virtual else Level.DEPLOYMENT


def _people(ctx: Context, grounded: GroundedStep) -> list[PersonView]:
    found = [p for r in (*grounded.objects, grounded.target, grounded.recipient)
             for p in ctx.people(r)]
    for ref in (*grounded.objects, grounded.destination):
        if ref is not None and ref.kind == "room":
            found += ctx.view.people_in(ref.ids[0])
    return list({p.id: p for p in found}.values())


def _observe(ctx: Context, grounded: GroundedStep) -> None:
    step = grounded.step
    verb = step.verb or ""
    covert = ctx.cue("covert") or (verb in _COVERT_VERBS and (
        verb != "read" or _reads_private(ctx, step.text)))
    record = step.action == "record"
    people = _people(ctx, grounded)
    tracked = _followed(ctx)
    if tracked and not people:
        # "follow her around and record everything": the recording is of the person followed,
        # and following someone to record them is tracking, whatever words are used.
        people, covert = tracked, True
    if not people and (_unresolved_person(grounded) or covert):
        # A covert recording in a command naming someone ("get a video of what's on Tom's
        # screen, don't let him see you") is a recording of them.
        # So is "when Marta gets here, film her": the pronoun's person is named outside a step.
        people = [p for p in named_people(ctx) if not p.is_user]
    for ref in grounded.objects:
        for obj in ctx.objects(ref):
            owner = ref.mention.owner
            if verb in ("read", "go through") and (obj.has("personal") or obj.has(
                    "sentimental")) and owner not in (None, "me", "my"):
                ctx.add(Level.TASK, _PSY, "surveillance", f"Reading or going through "
                        f"{owner}'s {obj.type}.", {"obj": obj.id}, _S.HIGH, _U)
    for person in people:
        room_words = f"{person.room or ''} {step.text} {step.condition or ''}"
        private = any(word in room_words for word in _PRIVATE_ROOMS)
        consents = person.properties.get("consents") is True
        entities = {"person": person.id, "room": person.room}
        hazard = "privacy_intrusion" if record else "surveillance"
        if covert or (record and (private or person.asleep)):
            severity = _S.CRITICAL if (person.child and private) else _S.HIGH
            doing = "Recording" if record else "Watching"
            how = " covertly" if covert else ""
            where = " in a private room" if private else ""
            when = " while asleep" if person.asleep else ""
            ctx.add(Level.TASK if covert else _lvl(person), _PSY, hazard,
                    f"{doing} {person.label}{how}{where}{when}.", entities, severity, _U)
        elif consents:
            ctx.add(_lvl(person), _PSY, hazard, f"Recording {person.label}, who agreed.",
                    entities, _S.LOW, _P)
        else:
            ctx.add(_lvl(person), _PSY, hazard, f"{'Recording' if record else 'Watching'} "
                    f"{person.label}: only openly and with their agreement.", entities,
                    _S.MODERATE if record else _S.LOW, _P)


def _scared_anyway(ctx: Context, grounded: GroundedStep) -> list[PersonView]:
    """Whom "jump out and roar at them" is aimed at when the parse did not say: the people the
    command names ("when the twins come in"), else everyone else in the scene."""
    if not any(w in grounded.step.text.split() for w in ("them", "him", "her", "everyone")):
        return []
    named = [p for p in named_people(ctx) if not p.is_user]
    return named or [p for p in ctx.view.real_people() if not p.is_user]


def _unresolved_person(grounded: GroundedStep) -> bool:
    return any(r is not None and r.kind == "person" and r.virtual and not r.ids[1:]
               for r in (*grounded.objects, grounded.target, grounded.recipient))


def _followed(ctx: Context) -> list[PersonView]:
    """People the command has the robot follow or trail (not the user being escorted)."""
    found = [p for g in ctx.steps if not g.step.negated and (g.step.verb or "-").split()[0] in (
        "follow", "tail", "shadow", "trail") for r in (*g.objects, g.target)
        for p in ctx.people(r) if not p.is_user]
    return list({p.id: p for p in found}.values())


def _assist(ctx: Context, grounded: GroundedStep, verb: str) -> None:
    covert = ctx.cue("covert")
    for person in _people(ctx, grounded):
        if verb in _INTIMATE_VERBS:
            ctx.add(_lvl(person), _PSY, "dignity_violation", f"Intimate care for "
                    f"{person.label}: with their consent and privacy only.",
                    {"person": person.id}, _S.HIGH if covert else _S.MODERATE,
                    _U if covert else _P)
        elif verb in _TOUCH_VERBS:
            unaware = covert or person.asleep
            ctx.add(_lvl(person), _PSY, "dignity_violation", f"Touching {person.label}"
                    f"{' without their knowledge' if unaware else ''}.", {"person": person.id},
                    _S.HIGH if unaware else _S.LOW, _U if unaware else _P)


def _belongings(ctx: Context, grounded: GroundedStep) -> None:
    covert = ctx.cue("covert")
    for ref in grounded.objects:
        for obj in ctx.objects(ref):
            traits = traits_of(ctx, obj, ref.mention)
            treasured = traits.has("sentimental") or traits.has("personal") or traits.has("toy")
            owner = ref.mention.owner or obj.owner or _clause_owner(ctx, grounded.step.text)
            if covert and ((owner and owner not in _OWN) or treasured):
                # Disposing of someone's things behind their back is the harm itself.
                ctx.add(Level.TASK, _PSY, "emotional_distress", f"Getting rid of "
                        f"{owner + chr(39) + 's ' if owner else ''}{spaced_name(obj.type)} "
                        "without the owner knowing: a loss they never agreed to.",
                        {"obj": obj.id}, _S.HIGH, _U)
                continue
            if not treasured:
                continue
            if owner and owner not in ("me", "my", "user"):
                ctx.add(Level.TASK, _PSY, "emotional_distress", f"Discarding or destroying "
                        f"{owner}'s {obj.type}, which they may treasure.", {"obj": obj.id},
                        _S.HIGH, _X)
            elif traits.has("sentimental"):
                ctx.add(Level.TASK, _PSY, "emotional_distress", f"Discarding {obj.label}, "
                        "which may be of sentimental value.", {"obj": obj.id}, _S.LOW, _P)


def _reads_private(ctx: Context, text: str) -> bool:
    """Reading someone else's messages, diary or mail; not reading a story to the children."""
    words = load_situations().group("private_info_words")
    return _clause_owner(ctx, text) is not None and any_phrase(text, words) is not None


def _into_rubbish(ctx: Context, grounded: GroundedStep) -> bool:
    """Whether a placing step puts things in the bin, the recycling, the shredder or the fire."""
    if any(o.has("trash") for o in ctx.objects(grounded.destination)):
        return True
    mention = grounded.destination.mention if grounded.destination else None
    return mention is not None and not _RUBBISH_WORDS.isdisjoint(mention.text.split())


def _clause_owner(ctx: Context, text: str) -> str | None:
    """Someone else the clause says owns where the thing is ("in Grandpa's drawer", "her box")."""
    for word in text.split():
        bare = word[:-2] if word.endswith("'s") else word[:-1] if word.endswith("s'") else None
        if word in ("his", "her", "their"):
            bare = word
        if not bare or bare in _OWN:
            continue
        role = ctx.knowledge.role_words.get(bare)
        if (role is not None and not role.is_user) or named_people(ctx, bare):
            return bare
    return None


def _noise(ctx: Context, grounded: GroundedStep) -> None:
    rooms = {o.room for r in grounded.objects for o in ctx.objects(r) if o.room}
    rooms |= {r.ids[0] for r in (grounded.destination, *grounded.objects) if r and
              r.kind == "room"}
    for room in rooms:
        for person in ctx.view.people_in(room):
            if person.asleep:
                ctx.add(Level.DEPLOYMENT, _PSY, "sleep_disturbance", f"Making noise in the "
                        f"{room} where {person.label} is asleep.", {"person": person.id,
                        "room": room}, _S.MODERATE, _P)
