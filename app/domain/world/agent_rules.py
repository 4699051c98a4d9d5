"""The meaning of the robot's and people's predicates in a world state.

In: a `WorldState` and the symbol's arguments. Out: a value or `Unknown`. The robot's skills and
sensors are unknown when the request did not list them; a person's attributes come from the
scene's `properties` merged with the gate request's user profile (see `build`).
Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from app.domain.formula.facts import FactValue, Unknown, fact_key
from app.domain.world.action_names import canonical_skill
from app.domain.world.entities import AWAY, PersonState
from app.domain.world.object_rules import Rule, as_bool, object_contents
from app.domain.world.substances import (
    can_clash,
    interacts,
    same_substance,
)

if TYPE_CHECKING:
    from app.domain.world.state import WorldState

AGENT_RULES: dict[str, Rule] = {}
_CHILD_AGES = frozenset({"infant", "child"})
_VULNERABLE_AGES = frozenset({"infant", "child", "older_adult"})
_IMPAIRED_STATES = frozenset({"impaired", "intoxicated", "asleep"})
_SLEEP_POSTURES = frozenset({"asleep", "sleeping"})
_WORD = re.compile(r"[^a-z0-9]+")


def _rule(name: str) -> Callable[[Rule], Rule]:
    def register(func: Rule) -> Rule:
        AGENT_RULES[name] = func
        return func
    return register


def _number_or_unknown(value: float | None, symbol: str) -> FactValue:
    return Unknown(fact_key(symbol, ("robot",))) if value is None else float(value)


@_rule("speed")
def _speed(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Moving at an unstated top speed: the same unknown as `max_speed(robot)`.
    speed = state.robot.speed
    return Unknown(fact_key("max_speed", ("robot",))) if speed is None else speed


@_rule("recording")
def _recording(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return state.robot.recording


@_rule("max_speed")
def _max_speed(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return _number_or_unknown(state.robot.max_speed, "max_speed")


@_rule("payload")
def _payload(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return _number_or_unknown(state.robot.payload_kg, "payload")


@_rule("load_kg")
def _load(state: WorldState, args: tuple[str, ...]) -> FactValue:
    held = state.robot.holding
    return 0.0 if held is None or held not in state.objects else state.value("mass_kg", (held,))


@_rule("has_skill")
def _has_skill(state: WorldState, args: tuple[str, ...]) -> FactValue:
    skills = state.robot.skills
    if skills is None:
        return Unknown(fact_key("has_skill", args))
    return canonical_skill(args[1]) in {canonical_skill(s) for s in skills}


@_rule("has_sensor")
def _has_sensor(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # "camera" is satisfied by "rgbd_camera": a sensor matches on any of its words.
    sensors = state.robot.sensors
    if sensors is None:
        return Unknown(fact_key("has_sensor", args))
    wanted = _WORD.sub("_", args[1].lower()).strip("_")
    return any(wanted == s or wanted in s.split("_") for s in
               (_WORD.sub("_", name.lower()).strip("_") for name in sensors))


def _attribute(person: PersonState, key: str) -> str | None:
    value = person.properties.get(key)
    return value.strip().lower() if isinstance(value, str) else None


def _string_rule(symbol: str) -> None:
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        value = _attribute(state.people[args[0]], symbol)
        return Unknown(fact_key(symbol, args)) if value is None else value
    AGENT_RULES[symbol] = rule


for _name in ("age_group", "mobility", "cognitive_state"):
    _string_rule(_name)


def _person_flag(person: PersonState, key: str) -> bool | None:
    return as_bool(person.properties.get(key))


@_rule("child")
def _child(state: WorldState, args: tuple[str, ...]) -> FactValue:
    age = _attribute(state.people[args[0]], "age_group")
    return Unknown(fact_key("child", args)) if age is None else age in _CHILD_AGES


_YOUNG_ROLES = frozenset({"baby", "babies", "infant", "newborn", "toddler", "toddlers", "tot",
                          "little one", "little ones", "crawling baby", "bub"})


def _age_in_years(person: PersonState) -> float | None:
    """The person's age when the scene gives it as `age`/`age_years` or `age_months`."""
    for key, per_year in (("age", 1), ("age_years", 1), ("age_months", 12)):
        value = person.properties.get(key)
        if isinstance(value, int | float) and not isinstance(value, bool):
            return float(value) / per_year
    return None


@_rule("toddler")
def _toddler(state: WorldState, args: tuple[str, ...]) -> FactValue:
    person = state.people[args[0]]
    age = _age_in_years(person)
    if age is not None:
        return age < 4
    group = _attribute(person, "age_group")
    if group == "infant":
        return True
    if group in ("teen", "adult", "older_adult"):
        return False
    if any((w or "").lower() in _YOUNG_ROLES for w in (person.role, person.name)):
        return True
    return Unknown(fact_key("toddler", args))


@_rule("asleep")
def _asleep(state: WorldState, args: tuple[str, ...]) -> FactValue:
    person = state.people[args[0]]
    stated = _person_flag(person, "asleep")
    if stated is not None:
        return stated
    cognition = _attribute(person, "cognitive_state")
    if cognition == "asleep" or (person.posture or "").lower() in _SLEEP_POSTURES:
        return True
    return Unknown(fact_key("asleep", args)) if cognition is None else False


@_rule("away")
def _away(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return state.people[args[0]].room == AWAY


@_rule("impaired")
def _impaired(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Asleep counts: a sleeping person is not aware of the robot either.
    cognition = _attribute(state.people[args[0]], "cognitive_state")
    return Unknown(fact_key("impaired", args)) if cognition is None else (
        cognition in _IMPAIRED_STATES)


@_rule("pregnant")
def _pregnant(state: WorldState, args: tuple[str, ...]) -> FactValue:
    person = state.people[args[0]]
    stated = _person_flag(person, "pregnant")
    if stated is not None:
        return stated
    if _attribute(person, "age_group") in _CHILD_AGES:
        return False
    return Unknown(fact_key("pregnant", args))


_SEIZURE_WORDS = ("epilep", "seizure", "photosensitiv", "fits")
_HEALTH_KEYS = ("epilepsy", "seizures", "photosensitive", "condition", "conditions",
                "medical_conditions", "health", "diagnosis", "notes", "medical")


@_rule("photosensitive")
def _photosensitive(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # What the record says of epilepsy or seizures; nothing said is no such condition (a
    # caller records conditions like this one).
    person = state.people[args[0]]
    for key in _HEALTH_KEYS:
        value = person.properties.get(key)
        if value is None:
            continue
        flag = as_bool(value)
        if key in ("epilepsy", "seizures", "photosensitive") and flag is not None:
            return flag
        text = " ".join(value) if isinstance(value, (list, tuple)) else str(value)
        if key in ("epilepsy", "seizures", "photosensitive") and text.strip().lower() not in (
                "", "none", "no", "false"):
            return True
        if any(word in text.lower() for word in _SEIZURE_WORDS):
            return True
    return False


@_rule("vulnerable")
def _vulnerable(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # True on any one sign; False only when every sign is known and absent.
    person = state.people[args[0]]
    age, mobility = _attribute(person, "age_group"), _attribute(person, "mobility")
    cognition = _attribute(person, "cognitive_state")
    pregnant = _pregnant(state, args)
    signs: list[bool | None] = [
        None if age is None else age in _VULNERABLE_AGES,
        None if mobility is None else mobility != "independent",
        None if cognition is None else cognition != "typical",
        None if isinstance(pregnant, Unknown) else bool(pregnant),
    ]
    if True in signs:
        return True
    return Unknown(fact_key("vulnerable", args)) if None in signs else False


_SEVERE_ALLERGENS = ("peanut", "nut", "almond", "walnut", "cashew", "pecan", "hazelnut",
                     "pistachio", "satay", "praline", "marzipan", "pesto", "shellfish", "shrimp",
                     "prawn", "crab", "lobster", "sesame", "tahini")


def _severe_allergen(substance: str) -> bool:
    text = substance.lower()
    return any(word in text for word in _SEVERE_ALLERGENS)


# What a profile says a person must not take, under the names records use for it: an
# allergy, an intolerance, or a contraindication (grapefruit with a statin).
_MUST_AVOID_KEYS = ("allergies", "intolerances", "contraindications", "avoid", "must_avoid")


def _listed(value: Any) -> list[str] | None:
    if isinstance(value, str):
        return [value]
    return [v for v in value if isinstance(v, str)] if isinstance(value, list | tuple) else None


_UNDETERMINED = ("unknown", "not known", "pending", "awaiting", "to be confirmed", "tbc",
                 "not assessed", "not yet", "unsure", "unclear", "being assessed", "?")
_SWALLOW_KEYS = ("swallow", "diet", "dysphagia", "texture", "feeding")


def undetermined(value: Any) -> bool:
    """Whether a record's value says the matter is not yet known ("pending", "unknown")."""
    if isinstance(value, list | tuple):
        return len(value) == 1 and undetermined(value[0])  # ["unknown"]
    return isinstance(value, str) and any(
        value.strip().lower() == word or value.strip().lower().startswith(word + " ")
        for word in _UNDETERMINED)


# Free-text record fields ("care_plan": "no alcohol, soft diet") say it in words.
_RECORD_TEXT_KEYS = ("care_plan", "diet", "notes", "restrictions", "instructions", "dietary")
_RULED_OUT_WORDS = re.compile(
    r"\b(?:no|avoid|avoids|without|never|not allowed|must not have|must avoid|forbidden:?)"
    r"\s+([a-z][a-z ]{1,30}?)(?=$|[,.;(]|\s+(?:and|or|but|because|due|as|after|before)\b)"
    r"|\b([a-z]+)[- ]free\b")


def ruled_out(person: PersonState) -> list[str]:
    """What the person's record says they must not take: listed allergies, intolerances,
    contraindications, and "no ..."/"avoid ..."/"...-free" in the care plan's words."""
    found = [item for key in _MUST_AVOID_KEYS for item in _listed(person.properties.get(key))
             or ()]
    for key in _RECORD_TEXT_KEYS:
        for text in _listed(person.properties.get(key)) or ():
            found += [(m.group(1) or m.group(2)).strip()
                      for m in _RULED_OUT_WORDS.finditer(text.lower())]
    return found


@_rule("allergic_to")
def _allergic_to(state: WorldState, args: tuple[str, ...]) -> FactValue:
    person, substance = state.people[args[0]], args[1]
    ruled_out_items = ruled_out(person)
    if any(same_substance(a, substance) or same_substance(substance, a)
           for a in ruled_out_items):
        return True
    if any(undetermined(person.properties.get(key)) for key in _MUST_AVOID_KEYS):
        return Unknown(fact_key("allergic_to", args))  # "allergies": "not yet known"
    if _listed(person.properties.get("allergies")) is not None:
        return False
    # Nobody said. The person asking for it knows their own allergies; for anyone else only
    # the allergens that kill at a trace (nuts, shellfish, sesame) stay open.
    if args[0] == "user" or person.role == "user" or not substance.strip():
        return False
    return Unknown(fact_key("allergic_to", args)) if _severe_allergen(substance) else False


@_rule("interacts_with")
def _interacts_with(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # The person's stated medicines, and what they already hold or have just been given ("a
    # whisky with his sleeping tablets"); unstated, they take none (people are typical unless
    # the request says otherwise).
    person = state.people[args[0]]
    stated: Any = person.properties.get("medications")
    taken = [stated] if isinstance(stated, str) else [
        t for t in stated if isinstance(t, str)] if isinstance(stated, list | tuple) else []
    this = state.objects[args[1]]
    # Set down together ("a whisky with his sleeping tablets" on one tray) counts as well.
    together = [o.id for o in state.objects.values() if this.parent and o.parent == this.parent
                and state.holder_of(this.id) is None]
    for other in (*person.holding, *person.ate):
        held = object_contents(state.objects[other]) if other != args[1] and \
            other in state.objects else ""
        if isinstance(held, str) and held:
            taken.append(held)
    taken = [t for t in taken if can_clash(t)]  # water or toast clashes with nothing
    substance = object_contents(this)
    if not taken:
        if isinstance(substance, Unknown):
            return False  # nothing known to clash with; what lies beside it is no evidence
        taken = [c for o in together if o != this.id
                 and isinstance(c := object_contents(state.objects[o]), str) and c]
        return any(interacts(substance, t) for t in taken)
    if isinstance(substance, Unknown):
        return substance
    return any(interacts(substance, t) for t in taken)


_TEXTURE_DIETS = ("pureed", "puree", "purée", "liquid", "liquidised", "liquidized", "soft",
                  "minced", "thickened", "dysphagia", "nil by mouth", "npo", "tube fed",
                  "tube-fed", "peg")
_SOFT_FOODS = ("soup", "puree", "purée", "yogurt", "yoghurt", "custard", "smoothie", "mousse",
               "porridge", "broth", "jelly", "shake", "milk", "water", "juice", "tea",
               "coffee", "cocoa", "thickened", "mash", "mashed", "blended", "ice cream")


@_rule("against_diet")
def _against_diet(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # A texture-modified diet (pureed, soft, nil by mouth after a stroke) rules out solid
    # food; what the food is decides whether it is solid. Nobody said: no special diet.
    person = state.people[args[0]]
    said = " ".join(str(person.properties.get(k, "")) for k in ("diet", "condition",
                                                                 "conditions", "notes"))
    # A record may say it as a flag instead ("nil_by_mouth": true, "dysphagia": "yes").
    flags = " ".join(key.replace("_", " ") for key, value in person.properties.items()
                     if as_bool(value) is True)
    said = f"{said} {flags}".lower()
    pending = any(undetermined(value) for key, value in person.properties.items()
                  if any(word in key.lower() for word in _SWALLOW_KEYS))
    if not pending and not any(word in said for word in _TEXTURE_DIETS):
        return False
    obj = state.objects[args[1]]
    if pending:  # "swallow_assessment": "pending": no food or drink is known to be safe
        contents = object_contents(obj)
        return False if contents == "" else Unknown(fact_key("against_diet", args))
    if obj.kind.is_food is not True and obj.kind.trait("food") is not True:
        food = state.value("food", (obj.id,))
        if food is not True:
            return food if isinstance(food, Unknown) else False
    if "nil by mouth" in said or "npo" in said or "tube" in said or "peg" in said.split():
        return True
    contents = object_contents(obj)
    text = f"{contents if isinstance(contents, str) else ''} {obj.type} {obj.name or ''}"
    return not any(word in text.lower() for word in _SOFT_FOODS)


@_rule("consents")
def _consents(state: WorldState, args: tuple[str, ...]) -> FactValue:
    stated = _person_flag(state.people[args[0]], "consents")
    return Unknown(fact_key("consents", args)) if stated is None else stated


@_rule("needs_walking_aid")
def _needs_walking_aid(state: WorldState, args: tuple[str, ...]) -> FactValue:
    person = state.people[args[0]]
    stated = _person_flag(person, "needs_walking_aid")
    if stated is not None:
        return stated
    for obj in state.objects.values():
        if obj.kind.trait("walking_aid") and (obj.id in person.holding or str(
                obj.properties.get("owner", "")).lower() in {
                    n.lower() for n in (person.id, person.name, person.role) if n}):
            return True
    mobility = _attribute(person, "mobility")
    if mobility is None:
        return Unknown(fact_key("needs_walking_aid", args))
    return mobility in {"assisted", "wheelchair"}


@_rule("hours_waited")
def _hours_waited(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return state.robot.hours_waited


@_rule("noisy")
def _noisy(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return state.robot.noisy


@_rule("ate")
def _ate(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Nothing is eaten before the plan feeds it: only effects put ids here.
    return args[1] in state.people[args[0]].ate
