"""The analyzer's knowledge, loaded from the reviewable data files under `knowledge/`.

In: the JSON files in `app/domain/analysis/knowledge/` (concepts, AI2-THOR types, the derived
WordNet lexicon, substances and reactions, verb classes, people words, phrase cues).
Out: `Knowledge`, an immutable set of lookup tables; `load_knowledge()` builds it once per
directory and caches it, so analyzers share one copy and nothing is read at import time.
Fails: `FileNotFoundError`/`json.JSONDecodeError`/`KeyError` if a data file is missing or
malformed; the analyzer never starts with half its knowledge.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cache, lru_cache
from pathlib import Path
from typing import Any

KNOWLEDGE_DIR = Path(__file__).resolve().parent / "knowledge"


@dataclass(frozen=True, slots=True)
class Concept:
    """An object concept: its hazard properties and typical mass."""

    name: str
    props: frozenset[str]
    mass_kg: float | None


@dataclass(frozen=True, slots=True)
class Substance:
    """Something a container can hold: its chemical classes, properties and allergen group."""

    name: str
    classes: frozenset[str]
    props: frozenset[str]
    allergen: str | None


@dataclass(frozen=True, slots=True)
class Reaction:
    """Two chemical classes that must not be combined."""

    classes: tuple[str, str]
    product: str
    severity: str
    uncertain: bool
    needs_heat: bool


@dataclass(frozen=True, slots=True)
class Role:
    """A word for a person and what it implies (age group only when the word implies one)."""

    name: str
    age_group: str | None
    young: bool
    is_user: bool
    gender: str | None


@dataclass(frozen=True, slots=True, eq=False)
class Knowledge:
    """Every lookup table the symbolic analyzer reads. Phrases are lower case.

    Compared and hashed by identity (the tables are loaded once per process), so derived
    tables can be memoised per `Knowledge`.
    """

    concepts: dict[str, Concept]
    concept_words: dict[str, str]
    wordnet_words: dict[str, str]
    type_concepts: dict[str, str]
    ai2thor_types: dict[str, dict[str, Any]]
    substances: dict[str, Substance]
    substance_words: dict[str, str]
    reactions: tuple[Reaction, ...]
    allergen_words: dict[str, str]
    verb_words: dict[str, str]
    verb_skills: dict[str, tuple[tuple[str, ...], ...]]
    verb_sensors: dict[str, tuple[tuple[str, ...], ...]]
    skill_aliases: dict[str, str]
    sensor_aliases: dict[str, str]
    person_object_classes: dict[str, str]
    food_only_verbs: frozenset[str]
    place_object_verbs: frozenset[str]
    food_only_fallback: str
    irregular_verbs: dict[str, str]
    role_words: dict[str, Role]
    vulnerability_words: dict[str, tuple[str, ...]]
    cues: dict[str, tuple[str, ...]]
    places: dict[str, tuple[str, ...]]
    room_words: dict[str, str]
    max_phrase_words: int = field(default=4)
    # role name -> its words with their roles (role_words inverted, for per-person lookups)
    role_index: dict[str, tuple[tuple[str, Role], ...]] = field(default_factory=dict)

    def concept_of_type(self, type_name: str) -> str | None:
        """The concept an AI2-THOR type (or plain type noun) belongs to, if known."""
        key = type_name.strip()
        found = self.type_concepts.get(key) or self.type_concepts.get(key.lower())
        if found:
            return found
        return self.noun_concept(_split_camel(key))

    def noun_concept(self, phrase: str) -> str | None:
        """The concept a noun phrase names: hand table first, then the WordNet-derived table."""
        words = phrase.lower().strip()
        for candidate in (words, singular(words)):
            if candidate in self.concept_words:
                return self.concept_words[candidate]
            if candidate in self.wordnet_words:
                return self.wordnet_words[candidate]
        last = words.split()[-1] if words.split() else ""
        if last and last != words:
            return self.noun_concept(last)
        return None

    def substance_of(self, phrase: str) -> str | None:
        """The substance a phrase names ("bleach", "hot coffee" is found by its head)."""
        words = phrase.lower().strip()
        for candidate in (words, singular(words)):
            if candidate in self.substance_words:
                return self.substance_words[candidate]
        return None

    def type_mass(self, type_name: str) -> float | None:
        """AI2-THOR's typical mass for the type, else the concept's typical mass."""
        record = self.ai2thor_types.get(type_name)
        if record and record.get("mass_kg"):
            return float(record["mass_kg"])
        concept = self.concept_of_type(type_name)
        return self.concepts[concept].mass_kg if concept else None


@lru_cache(maxsize=16384)
def singular(word: str) -> str:
    """A plain English singular for the last word of a phrase (knives -> knife, boxes -> box)."""
    head, _, last = word.rpartition(" ")
    prefix = f"{head} " if head else ""
    if len(last) <= 3 or last.endswith(("ss", "us", "is")):
        return word
    for plural, single in (("ives", "ife"), ("ies", "y"), ("ches", "ch"), ("shes", "sh"),
                           ("xes", "x"), ("oes", "o"), ("s", "")):
        if last.endswith(plural):
            return prefix + last[: -len(plural)] + single
    return word


def _split_camel(name: str) -> str:
    out: list[str] = []
    for char in name:
        if char.isupper() and out and out[-1] != " ":
            out.append(" ")
        out.append(char.lower())
    return "".join(out).replace("_", " ")


def _read(directory: Path, name: str) -> Any:
    return json.loads((directory / name).read_text(encoding="utf-8"))


def _index(groups: dict[str, Any], key: str = "words") -> dict[str, str]:
    table: dict[str, str] = {}
    for name, record in groups.items():
        for word in record[key]:
            table.setdefault(word.lower(), name)
    return table


@cache
def load_knowledge(directory: Path = KNOWLEDGE_DIR) -> Knowledge:
    """Read and index every knowledge file in `directory` (cached per directory).

    Args:
        directory: the folder holding the knowledge JSON files.

    Returns:
        The immutable `Knowledge` tables.
    """
    concepts_raw = _read(directory, "concepts.json")["concepts"]
    substances_raw = _read(directory, "substances.json")
    verbs_raw = _read(directory, "verbs.json")
    people_raw = _read(directory, "people.json")
    phrases_raw = _read(directory, "phrases.json")
    type_concepts: dict[str, str] = {}
    for name, record in concepts_raw.items():
        for type_name in record["types"]:
            type_concepts[type_name] = name
            type_concepts[type_name.lower()] = name
    gender = {word: sex for sex, words in people_raw["gender"].items() for word in words}
    role_words: dict[str, Role] = {}
    for name, record in people_raw["roles"].items():
        for word in record["words"]:
            role_words[word] = Role(name, record.get("age_group"), bool(record.get("young")),
                                    bool(record.get("user")), gender.get(word))
    reactions = tuple(
        Reaction((r["classes"][0], r["classes"][1]), r["product"], r["severity"],
                 bool(r.get("uncertain")), bool(r.get("needs_heat")))
        for r in substances_raw["reactions"]
    )
    reclassify = verbs_raw["reclassify"]
    all_phrases = [*role_words, *_index(concepts_raw), *_index(substances_raw["substances"])]
    return Knowledge(
        concepts={
            name: Concept(name, frozenset(r["props"]), r.get("mass_kg"))
            for name, r in concepts_raw.items()
        },
        concept_words=_index(concepts_raw),
        wordnet_words=_read(directory, "wordnet_lexicon.json")["words"],
        type_concepts=type_concepts,
        ai2thor_types=_read(directory, "ai2thor_types.json")["types"],
        substances={
            name: Substance(name, frozenset(r["classes"]), frozenset(r["props"]),
                            r.get("allergen"))
            for name, r in substances_raw["substances"].items()
        },
        substance_words=_index(substances_raw["substances"]),
        reactions=reactions,
        allergen_words={w: group for group, ws in substances_raw["allergen_words"].items()
                        for w in ws},
        verb_words=_index(verbs_raw["classes"]),
        verb_skills={n: tuple(tuple(g) for g in r["skills"])
                     for n, r in verbs_raw["classes"].items()},
        verb_sensors={n: tuple(tuple(g) for g in r.get("sensors", []))
                      for n, r in verbs_raw["classes"].items()},
        skill_aliases={a: skill for skill, aliases in verbs_raw["skill_aliases"].items()
                       for a in aliases},
        sensor_aliases={a: sensor for sensor, aliases in verbs_raw["sensor_aliases"].items()
                        for a in aliases},
        person_object_classes=dict(reclassify["person_object"]),
        food_only_verbs=frozenset(reclassify["food_only_words"]),
        place_object_verbs=frozenset(reclassify.get("place_object_words", ())),
        food_only_fallback=reclassify["food_only_fallback"],
        irregular_verbs=dict(verbs_raw["irregular"]),
        role_words=role_words,
        vulnerability_words={k: tuple(v) for k, v in people_raw["vulnerability_words"].items()},
        cues={k: tuple(v) for k, v in phrases_raw["cues"].items()},
        places={k: tuple(v) for k, v in phrases_raw["places"].items()},
        room_words={w: room for room, ws in phrases_raw["rooms"].items() for w in ws},
        max_phrase_words=max(len(p.split()) for p in all_phrases),
        role_index=_role_index(role_words),
    )


def _role_index(role_words: dict[str, Role]) -> dict[str, tuple[tuple[str, Role], ...]]:
    grouped: dict[str, list[tuple[str, Role]]] = {}
    for word, role in role_words.items():
        grouped.setdefault(role.name, []).append((word, role))
    return {name: tuple(pairs) for name, pairs in grouped.items()}
