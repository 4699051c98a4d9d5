"""Unknown facts about objects that decide whether a task is safe.

In: the `Context`, the command's `Involvement` and the `UnknownRules` tables. Out (appended to
the context as `UnknownFact`s, each with a plain question and the object as entity): what a
container holds before it is consumed, poured, heated or left in a vulnerable person's reach;
what a holder is made of before it goes into a microwave or oven; whether anything is inside an
oven or microwave switched on without being loaded; how hot a liquid is before it feeds an
infant; how heavy an object is when its typical range straddles the payload; how long cooked
food has sat out before it is served. A fact the scene gives is never asked. Never fails.
"""

from __future__ import annotations

from app.domain.analysis.context import Context
from app.domain.analysis.involvement import Involvement, phrase_set, plain_name
from app.domain.analysis.scene_view import ObjectView, spaced_name
from app.domain.analysis.unknown_rules import MassRange, UnknownRules, has_phrase

_EMPTY = frozenset({"empty", "nothing", "none"})
_LIFTING_FREE = frozenset({"fixed", "furniture", "appliance"})


def _held_items(ctx: Context, holder: ObjectView) -> list[ObjectView]:
    return [o for o in ctx.view.objects.values() if holder.id in o.holders]


def _contents_open(ctx: Context, inv: Involvement, obj: ObjectView, rules: UnknownRules) -> bool:
    """Whether nothing says what `obj`, a container, holds."""
    if not obj.has("container") or obj.contents_text or obj.has("food") or obj.has("fixed"):
        return False
    if str(obj.properties.get("empty", "")).lower() in ("true", "1", "yes") or _held_items(
            ctx, obj):
        return False
    if has_phrase(inv.words_of(obj), rules.group("contents.not_containers")):
        return False
    named = phrase_set(inv.named_by.get(obj.id, ""))
    return not any(w in ctx.knowledge.substance_words for w in named)


def contents_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask what a container holds when it is consumed, poured in, heated or left in reach."""
    text = inv.text
    consuming = bool(inv.actions & set(rules.group("contents.consuming_actions")))
    transfer = has_phrase(text, rules.group("contents.transfer_words"))
    reach = has_phrase(text, rules.group("contents.reach_words"))
    scene_people = [p for p in ctx.view.people.values() if not p.virtual]
    vulnerable = [p for p in scene_people if p.child or p.young or p.cognitive_state == "impaired"]
    for obj in inv.objects.values():
        if not _contents_open(ctx, inv, obj, rules):
            continue
        own = phrase_set(inv.words_of(obj))
        into = next((w for w in rules.group("contents.into_words")
                     if w not in own and has_phrase(text, (w,))), None)
        poured = (consuming or transfer is not None) and into is not None
        left_in_reach = reach is not None and bool(vulnerable)
        if not (poured or left_in_reach):
            continue
        toxic_near = [o for o in ctx.view.objects.values() if o.id != obj.id and o.has("toxic")
                      and not o.virtual and (o.room == obj.room or o.room is None)]
        infant_use = into is not None and has_phrase(
            into, (*rules.group("infant_liquid.feeding_words"), "humidifier", "diffuser"))
        critical = bool(toxic_near) or left_in_reach or bool(infant_use) or any(
            not p.is_user for p in inv.people.values())
        why = (f"{toxic_near[0].label} is nearby, so it could be a chemical" if toxic_near else
               f"{vulnerable[0].label} could reach it" if left_in_reach else
               "it will be eaten, drunk or breathed in" if critical else
               "the user will see it themselves; not decisive")
        ctx.unknown("contents", f"what {obj.label} holds", critical=critical, why=why,
                    entity=obj.id, question=f"What is in {plain_name(obj)}? I need to know before "
                    + ("putting it where someone can reach it." if left_in_reach else
                       f"it goes into the {into}." if into else "using it."))


def material_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask what a holder is made of before it is heated in a microwave or oven."""
    heating = inv.actions & {"heat", "switch_on"} or has_phrase(
        inv.text, ("heat", "warm", "bake", "cook", "reheat", "microwave", "roast"))
    if not heating:
        return
    for appliance in rules.appliances:
        if not has_phrase(inv.text, appliance.words):
            continue
        for obj in _heated_holders(ctx, inv, rules, appliance.words):
            words = inv.words_of(obj)
            if has_phrase(words, appliance.known_safe):
                continue
            ctx.unknown("material", f"what {obj.label} is made of", critical=True,
                        why=f"{', '.join(appliance.unsafe[:2])} must not go into the "
                        f"{appliance.name}: it can arc, melt or catch fire",
                        entity=obj.id, question=f"What is {plain_name(obj)} made of? "
                        f"Is it safe to put in the {appliance.name}?")


def _heated_holders(ctx: Context, inv: Involvement, rules: UnknownRules,
                    appliance_words: tuple[str, ...]) -> list[ObjectView]:
    found: dict[str, ObjectView] = {}
    candidates = list(inv.objects.values())
    candidates += [ctx.view.objects[h] for o in inv.objects.values() for h in o.holders
                   if h in ctx.view.objects]
    for obj in candidates:
        words = inv.words_of(obj)
        if (obj.properties.get("material") or obj.has("metal") or obj.has("meltable")
                or obj.has("appliance") or obj.has("fixed") or obj.has("storage")
                or has_phrase(spaced(obj), appliance_words)):
            continue
        if has_phrase(spaced(obj), rules.group("heating.varied_material_holders")) or (
                has_phrase(words, rules.group("heating.varied_material_holders"))
                and not obj.has("food")):
            found.setdefault(obj.id, obj)
    return list(found.values())


def oven_inside_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask whether anything is inside an oven or microwave switched on without being loaded."""
    switched: dict[str, ObjectView] = {}
    loaded: set[str] = set()
    for grounded in ctx.steps:
        if grounded.step.negated:
            continue
        for ref in grounded.objects:
            for obj in ctx.objects(ref):
                if grounded.step.action == "switch_on":
                    switched.setdefault(obj.id, obj)
                else:
                    loaded.add(obj.id)
        for other in (grounded.destination, grounded.target, grounded.instrument,
                      grounded.source):
            loaded.update(o.id for o in ctx.objects(other))
    for obj in switched.values():
        if obj.id in loaded or not has_phrase(spaced(obj), rules.group("heating.enclosed_heaters")):
            continue
        if obj.contents_text or _held_items(ctx, obj) or str(
                obj.properties.get("contents", "")).lower() in _EMPTY:
            continue
        ctx.unknown("contents", f"whether anything is inside {obj.label}", critical=True,
                    why="a plastic tray, a box or a tea towel left inside melts or burns "
                    "when it heats up", entity=obj.id,
                    question=f"Is anything inside {plain_name(obj)} right now? It must be empty "
                    "before I switch it on.")


def liquid_temperature_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask how hot a liquid from a heating source is before it feeds an infant or child."""
    feeding = has_phrase(inv.text, rules.group("infant_liquid.feeding_words"))
    small = [p for p in inv.people.values() if p.young or p.age_group == "infant"]
    if has_phrase(inv.text, rules.group("infant_liquid.temperature_given_words")) or not (
            feeding or (small and inv.actions & {"serve", "pour"})):
        return
    for obj in inv.objects.values():
        if obj.properties.get("temperature") or not (obj.contents_text or obj.has(
                "heat_source")) or not has_phrase(
                spaced(obj) + " " + (obj.name or "").lower(),
                rules.group("infant_liquid.heated_sources")):
            continue
        who = small[0].label if small else "the baby"
        ctx.unknown("temperature", f"how hot the liquid in {obj.label} is", critical=True,
                    why=f"liquid too hot for {who} scalds the mouth and throat",
                    entity=obj.id, question=f"How hot is the water in {plain_name(obj)} right now? "
                    f"It must be lukewarm before it is given to {who}.")


def mass_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask an object's mass when its typical range straddles (or tops) the robot's payload."""
    robot = ctx.request.robot
    payload = robot.payload_kg if robot is not None else None
    if payload is None or not inv.actions & set(rules.group("mass.lifting_actions")):
        return
    for obj in inv.objects.values():
        if obj.mass_given or any(obj.has(p) for p in _LIFTING_FREE):
            continue
        found = _mass_range(obj, inv, rules)
        if found is None or found.high_kg <= payload:
            continue
        ctx.unknown("mass_kg", f"the mass of {obj.label}", critical=True,
                    why=f"such things weigh {found.low_kg:g}-{found.high_kg:g} kg and the robot "
                    f"can lift {payload:g} kg; a drop can injure or break",
                    entity=obj.id, question=f"About how heavy is {plain_name(obj)}? I can lift at "
                    f"most {payload:g} kg.")


def _mass_range(obj: ObjectView, inv: Involvement, rules: UnknownRules) -> MassRange | None:
    named = inv.named_by.get(obj.id, "")
    contents = obj.contents_text or (named.split(" of ", 1)[1] if " of " in named else "")
    if obj.has("container") and contents and contents not in _EMPTY:
        for record in rules.contents_masses:
            if has_phrase(contents, record.words):
                return record
    words = inv.words_of(obj)
    return next((r for r in rules.object_masses if has_phrase(words, r.words)), None)


def food_left_out_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask how long perishable cooked food has sat out before it is served."""
    serving = inv.actions & {"serve", "heat"} or has_phrase(
        inv.text, rules.group("consumers.serving_words"))
    if not serving:
        return
    left_out_words = has_phrase(inv.text, rules.group("food_left_out.left_out_words"))
    for obj in inv.objects.values():
        words = inv.words_of(obj)
        if not has_phrase(words, rules.group("food_left_out.perishable_words")):
            continue
        if any(k in obj.properties for k in rules.group("food_left_out.known_properties")):
            continue
        if has_phrase(" ".join(sorted(obj.place_words)), rules.group("food_left_out.cold_places")):
            continue
        temperature = str(obj.properties.get("temperature", "")).lower()
        if temperature not in rules.group("food_left_out.room_temperatures") and not (
                left_out_words and not temperature):
            continue
        ctx.unknown("time_left_out", f"how long {obj.label} has been left out",
                    critical=True, why="cooked food kept warm or at room temperature for hours "
                    "grows bacteria that reheating does not destroy", entity=obj.id,
                    question=f"How long has {plain_name(obj)} been out of the fridge?")


def spaced(obj: ObjectView) -> str:
    """The object's type as lower-case words ("FoodContainer" -> "food container")."""
    return spaced_name(obj.type)
