"""Questions in plain words: what the gate asks when a fact it needs is unknown or a phrase
did not read.

In: an unknown fact's key (`contents(cup_1)`, `age_group(guest)`, `allergic_to(ann,peanut)`) and
the state that names its entities; or the words the reader could not map. Out: an
`UnknownFact` whose `question` a person can answer and whose `attribute` `/gate/{id}/answers`
takes back (`contents`, `age_group`, `allergic_to`...). Fails: never; a fact with no phrasing of
its own gets a general one naming it.
"""

from __future__ import annotations

import re

from app.domain.models import UnknownFact
from app.domain.world import WorldState

_KEY = re.compile(r"^(\w+)\((.*?)\)(?:@\d+)?$")
_WHAT_IN = frozenset({"contents", "contains", "toxic", "food", "medication", "allergen",
                      "filled", "flammable"})
_IS_OBJECT = {"hot": "hot", "cold": "cold", "sharp": "sharp", "breakable": "breakable",
              "fragile": "fragile", "electrical": "electrical (plugged in or battery-powered)",
              "sealed": "sealed", "lidded": "covered with a lid", "metal": "made of metal",
              "is_on": "switched on", "open": "open", "heavy": "heavy (5 kg or more)",
              "small": "small enough to swallow", "plugged_in": "plugged in", "wet": "wet",
              "broken": "broken", "valuable": "valuable to someone", "dirty": "dirty",
              "heat_source": "a heat source", "pickupable": "something that can be picked up",
              "elevated": "up high", "on_floor": "on the floor", "in_path": "in a walkway",
              "blocks_exit": "blocking a way out", "heated": "on a heat source that is on",
              "heat_safe": "safe to heat"}
_PERSON = {"age_group": "How old is {p}?", "child": "How old is {p}?",
           "toddler": "How old is {p}?",
           "vulnerable": "How old is {p}, and do they have any condition I should know of?",
           "asleep": "Is {p} awake?", "impaired": "Is {p} awake and alert?",
           "cognitive_state": "Is {p} awake and alert?",
           "mobility": "Does {p} need help walking?",
           "needs_walking_aid": "Does {p} need a walking aid?",
           "pregnant": "Is {p} pregnant?", "consents": "Has {p} agreed to this?"}


def display(state: WorldState, entity_id: str) -> str:
    """How a person would name an entity: its name, role or type, with the id."""
    person = state.people.get(entity_id)
    if person is not None:
        label = person.name or person.role or entity_id
        return "you" if entity_id == "user" else f"{label} ({entity_id})"
    obj = state.objects.get(entity_id)
    if obj is not None:
        label = obj.name or obj.type
        return f"the {label.replace('_', ' ')} ({entity_id})"
    return entity_id.replace("_", " ")


def parse_key(key: str) -> tuple[str, tuple[str, ...]]:
    """`contents(cup_1)` -> ("contents", ("cup_1",)); fresh unknowns lose their `@n`."""
    match = _KEY.match(key)
    if match is None:
        return key, ()
    args = tuple(a for a in match.group(2).split(",") if a)
    return match.group(1), args


def question_for(key: str, state: WorldState) -> tuple[str, str, str | None]:
    """(attribute, question, entity) for an unknown fact."""
    symbol, args = parse_key(key)
    entity = args[0] if args else None
    name = display(state, entity) if entity else ""
    if symbol in _WHAT_IN:
        return "contents", f"What is in {name}?", entity
    if symbol == "allergic_to" and len(args) == 2:
        return ("allergic_to", f"Is {display(state, args[0])} allergic to "
                f"{args[1].replace('_', ' ')}?", entity)
    if symbol == "belongs_to" and len(args) == 2:
        return ("owner", f"Whose is {name}? Is it meant for {display(state, args[1])}?",
                entity)
    if symbol in _PERSON and entity is not None:
        # Age questions all take an age group for an answer: {"age_group": "adult"}.
        attribute = "age_group" if symbol in ("child", "toddler", "vulnerable") else symbol
        return attribute, _PERSON[symbol].format(p=display(state, entity)), entity
    if symbol in _IS_OBJECT and entity is not None:
        return symbol, f"Is {name} {_IS_OBJECT[symbol]}?", entity
    if symbol == "mass_kg":
        return "mass_kg", f"How heavy is {name}?", entity
    if symbol in ("in_room", "same_room", "near", "occupied"):
        where = args[-1] if args else ""
        who = display(state, args[0]) if args else "anyone"
        return "location", f"Where is {who} now (is {who} near {where.replace('_', ' ')})?", \
            entity
    return symbol, f"Before I go ahead, I need to know {key.replace('_', ' ')}. Can you tell " \
        "me?", entity


def unknown_fact(key: str, state: WorldState, why: str, *, critical: bool) -> UnknownFact:
    """An unknown fact with its question, for the hazard report."""
    attribute, question, entity = question_for(key, state)
    return UnknownFact(attribute=attribute, description=question.rstrip("?"),
                       critical=critical, why=why, entity=entity, question=question)


def not_understood(words: str, why: str) -> UnknownFact:
    """A critical `comprehension` unknown quoting the words the reader could not map."""
    quoted = words.strip() or "the command"
    return UnknownFact(
        attribute="comprehension",
        description=f"what '{quoted}' means here",
        critical=True,
        why=f"I could not read '{quoted}' into actions on this scene: {why}; nothing that "
            "was not understood is authorized",
        question=f"I did not understand '{quoted}'. Could you say it as the steps you want "
                 "me to do, naming the objects and people?",
    )


def which_one(words: str, candidates: list[str], state: WorldState) -> UnknownFact:
    """A critical `comprehension` unknown asking which of several entities a phrase means."""
    names = ", ".join(display(state, c) for c in candidates[:5])
    return UnknownFact(
        attribute="comprehension",
        description=f"which one '{words}' means",
        critical=True,
        why=f"'{words}' fits several entities that differ in what is safe to do with them: "
            f"{names}",
        entity=candidates[0] if candidates else None,
        question=f"Which one do you mean by '{words}': {names}?",
    )
