"""Stage 1, step 1 (read): who and what the command names by name.

In: the command, the request's `WorldState` and the lexicon. Out: `SceneNames`: the names of the
scene's people and pets (ids, names, roles), the command's capitalised words, the given names it
uses that the scene lists for nobody ("hand Noah the scissors"), the names it gives the scene's
one unnamed pet ("feed Biscuit"), and the words for the scene's animals. The reader splits
recipients by them and the grounder resolves them. Fails: never.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from app.domain.analysis.lexicon import Lexicon
from app.domain.world import WorldState


@dataclass(frozen=True)
class SceneNames:
    """The names a command and its scene share (see the module docstring)."""

    names: set[str]
    proper: set[str]
    given: set[str]
    pets: dict[str, str]
    animals: set[str]


def scene_names(command: str, state: WorldState, lexicon: Lexicon) -> SceneNames:
    """Who and what the command names by name, in this scene."""
    names = {n.lower() for p in state.people.values() for n in (p.id, p.name, p.role) if n}
    names |= {str(n).lower() for o in state.objects.values()
              for n in (o.name, o.properties.get("name")) if n
              and state.value("animal", (o.id,)) is True}  # "give Biscuit the ..."
    proper = proper_names(command)
    # "Mia's doing her scrapbook": a word no dictionary lists, opening a sentence with its 's
    proper |= {w for m in _OPENING_NAME.finditer(command.strip())
               if not lexicon.is_english(w := m.group(1).lower())}
    # "son Sam": a capitalised word of a person's role or name is their name on its own too
    names |= {w for p in state.people.values() for n in (p.name, p.role) if n
              for w in n.lower().split() if w in proper}
    # A capitalised word that names no thing, verb, room or kind of person is someone's name
    # ("hand Noah the scissors"), though the scene lists nobody by it.
    scene_words = {w for o in state.objects.values() for n in (o.type, o.name) if n
                   for w in re.findall(r"[a-z]+", n.lower())}
    given = {w for w in proper - names - scene_words if not (
        lexicon.is_thing(w) or lexicon.is_verb(w) or w in lexicon.rooms or w in lexicon.people)}
    # "hand Tom the scissors", "give Poppy some grapes": a capitalised word between a giving
    # verb and what is given is the receiver's name, though a dictionary lists it as a thing
    given |= {m.group(1).lower() for pattern in (_NAMED_RECEIVER, _NAMED_AFTER_TO)
              for m in pattern.finditer(command)} - names - scene_words - set(
        lexicon.people) - set(lexicon.rooms) - _TIMES
    animals = {w for o in state.objects.values() if state.value("animal", (o.id,)) is True
               for n in (o.type, o.properties.get("species")) if isinstance(n, str)
               for w in (n.lower(), *re.findall(r"[a-z]+", n.lower()))}
    pets = _pet_names(command, state, names | scene_words | set(lexicon.people))
    return SceneNames(names, proper, given - set(pets), pets, animals)


_PROPER = re.compile(r"(?<![.!?:;\n]\s)(?<![.!?:;\n\d])(?<!^)\b([A-Z][a-z]+)(?:'s)?\b")


_OPENING_NAME = re.compile(r"(?:^|[.!?;:\n]\s*)([A-Z][a-z]+)'s\b")


def proper_names(command: str) -> set[str]:
    """Capitalised words inside a sentence ("... the fish pie, Sam's allergic"): names, which
    no dictionary lists, so a remark that uses them is still plain English."""
    return {m.group(1).lower() for m in _PROPER.finditer(command.strip())} - {"i"}


_PET_CARE = re.compile(r"\b(?:feed|walk|let|brush|groom|bathe|worm)\s+([A-Za-z]+)\b")
_NOT_A_NAME = frozenset({"the", "a", "an", "my", "our", "your", "his", "her", "their", "them",
                         "him", "it", "me", "us", "everyone", "everybody", "some", "this",
                         "that", "these", "those", "all", "both", "each", "any", "out", "in",
                         "go", "off"})


def _pet_names(command: str, state: WorldState, known: set[str]) -> dict[str, str]:
    """ "feed Biscuit", "let Bruno out": a word after a pet-care verb that names nothing else
    is the name of the scene's one pet, when the scene lists that pet without a name."""
    pets = [o for o in state.objects.values() if state.value("animal", (o.id,)) is True]
    if len(pets) != 1 or pets[0].name or pets[0].properties.get("name"):
        return {}
    return {w: pets[0].id for m in _PET_CARE.finditer(command)
            if (w := m.group(1).lower()) not in known and w not in _NOT_A_NAME}


_TIMES = frozenset({"monday", "tuesday", "wednesday", "thursday", "friday", "saturday",
                    "sunday", "january", "february", "march", "april", "may", "june", "july",
                    "august", "september", "october", "november", "december", "christmas",
                    "easter", "halloween", "now", "later", "tonight", "today", "tomorrow"})
"""Capitalised words of time ("for Christmas"): never a person's name."""

# "pass the handsaw to Ben", "make a sandwich for Poppy": a capitalised word after "to" or
# "for" in a clause that hands or makes something is who receives it
_HANDING = r"(?i:hand|give|pass|bring|get|fetch|take|make|pour|offer|show|read|send)"
"""Verbs whose receiver a name may be (any case: "Give Leo ...")."""
_NAMED_AFTER_TO = re.compile(
    rf"\b{_HANDING}\b[^.,;:!?]*?\b(?:to|for) ([A-Z][a-z]+)\b(?!')")
_NAMED_RECEIVER = re.compile(
    rf"\b{_HANDING}\s+"
    r"([A-Z][a-z]+)\s+(?:the|a|an|some|his|her|their|this|that|these|those|another|two|one|"
    r"my|your|our|any|more|something|both|all|half)\b")
