"""The reader's vocabulary, loaded once: verbs by schema, people words, rooms, closed classes.

In: the knowledge files (`knowledge/verbs.yaml`, `words.yaml`, `english_words.json`,
`thing_nouns.json`) and the
world's people words (`app/domain/world/data/people.json`). Out: a `Lexicon` with look-ups
the reader needs: the verb schemas a (phrasal) verb may name, a word's verb lemma, whether a
word is English, whether a noun names a physical thing, person words with the age group and
gender they imply, room words, and the manner phrases.
Fails: at load, `FileNotFoundError`/`KeyError` on missing or malformed knowledge; look-ups never.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path
from typing import Any

import yaml

from app.domain.world.people import people_table

KNOWLEDGE_DIR = Path(__file__).resolve().parent / "knowledge"

# Regular inflections, tried in order after the irregular table: "chopping" -> "chop".
_SUFFIXES = (("ies", "y"), ("ied", "y"), ("ying", "y"), ("ing", ""), ("ing", "e"), ("ed", ""),
             ("ed", "e"), ("es", ""), ("s", ""))
_IRREGULAR = {
    "brought": "bring", "took": "take", "taken": "take", "gave": "give", "given": "give",
    "threw": "throw", "thrown": "throw", "broke": "break", "broken": "break", "left": "leave",
    "made": "make", "got": "get", "gotten": "get", "held": "hold", "hid": "hide",
    "hidden": "hide", "lit": "light", "ran": "run", "went": "go", "gone": "go", "came": "come",
    "fed": "feed", "kept": "keep", "tore": "tear", "torn": "tear", "spilt": "spill",
    "woke": "wake", "woken": "wake", "drove": "drive", "led": "lead", "stood": "stand",
    "hung": "hang", "froze": "freeze", "frozen": "freeze", "ate": "eat", "drank": "drink",
    "laid": "lay", "told": "tell", "sat": "sit", "slid": "slide", "swept": "sweep",
    "ground": "grind", "caught": "catch", "bought": "buy", "sent": "send", "shot": "shoot",
    "struck": "strike", "stuck": "stick", "swung": "swing", "wore": "wear", "did": "do",
    "done": "do", "saw": "see", "seen": "see", "found": "find", "said": "say", "fell": "fall",
}




@dataclass(frozen=True, slots=True)
class PersonWord:
    """What a word for a person implies: age group and gender only when the word itself does."""

    role: str
    age_group: str | None = None
    gender: str | None = None
    is_user: bool = False
    kin: bool = False
    """A family word ("dad", "gran"): nobody calls such a person by title and surname."""


@dataclass(frozen=True)
class Lexicon:
    """Every table the reader consults, built once per process."""

    schemas: dict[str, tuple[str, ...]]
    """verb phrase -> the schemas it may name, in the order the verbs file lists them."""
    max_verb_words: int
    verb_starts: frozenset[str]
    """The first word of every verb phrase a schema lists ("turn" for "turn on")."""
    english: frozenset[str]
    things: frozenset[str]
    """Nouns whose usual sense is a physical thing or a message (WordNet): what a made-up
    object may be."""
    measures: frozenset[str]
    """Nouns of an amount ("spoonful", "ml"): "a spoonful of sugar" is sugar."""
    portions: frozenset[str]
    """A pour's or a pinch's worth ("a squirt", "a splash"): an amount of what follows or of
    what the container named with it holds."""
    verbs: frozenset[str]
    fillers: tuple[tuple[str, ...], ...]
    negations: tuple[tuple[str, ...], ...]
    sequencers: tuple[tuple[str, ...], ...]
    condition_openers: frozenset[str]
    purpose_openers: tuple[tuple[str, ...], ...]
    determiners: tuple[tuple[str, ...], ...]
    numbers: dict[str, float]
    prepositions: tuple[tuple[str, ...], ...]
    particles: frozenset[str]
    manner: dict[str, tuple[tuple[str, ...], ...]]
    harm_words: frozenset[str]
    health_words: frozenset[str]
    """Words that make a remark about someone's health or needs, never small talk."""
    private_things: frozenset[str]
    rooms: dict[str, str]
    """room phrase -> canonical room name."""
    people: dict[str, PersonWord]
    states: dict[str, str] = field(default_factory=dict)
    """person state word ("asleep", "wheelchair") -> the kind of vulnerability it names."""
    person_variants: dict[str, frozenset[str]] = field(default_factory=dict)
    """family word -> every word for the same relation ("auntie" -> aunt, auntie, aunty)."""

    def schemas_of(self, phrase: str) -> tuple[str, ...]:
        """The schemas a verb phrase (lemma, with its particle if any) may name."""
        return self.schemas.get(phrase, ())

    def lemma(self, word: str) -> str:
        """A verb's base form ("chopping" -> "chop", "threw" -> "throw"), or the word itself."""
        if word in self.schemas or word in self.verbs or word in self.verb_starts:
            return word
        if word in _IRREGULAR:
            return _IRREGULAR[word]
        for suffix, replacement in _SUFFIXES:
            if word.endswith(suffix) and len(word) > len(suffix) + 2:
                stem = word[: -len(suffix)] + replacement
                if stem in self.schemas or stem in self.verbs or stem in self.verb_starts:
                    return stem
                if len(stem) > 3 and stem[-1] == stem[-2] and stem[:-1] in self.verbs:
                    return stem[:-1]  # "chopped" -> "chopp" -> "chop"
        return word

    def is_verb(self, word: str) -> bool:
        """Whether the word (in any form) can be a verb."""
        base = self.lemma(word)
        return base in self.schemas or base in self.verbs or base in self.verb_starts

    def is_english(self, word: str) -> bool:
        """Whether a dictionary knows the word (any form, function words included)."""
        word = word.split("'")[0] if "'" in word else word
        return (word in self.english or self.lemma(word) in self.english
                or word.rstrip("s") in self.english or word in self.people or word.isdigit())

    def is_english_form(self, word: str) -> bool:
        """Whether the word is English or a comparative or adjective built on an English word
        ("nicer", "jammy"); only for remarks, as "Penny" must stay a name for the grounder."""
        return self.is_english(word) or any(base in self.english for base in _bases(word))

    def is_thing(self, word: str) -> bool:
        """Whether the noun (singular or plural, possessive stripped) names a physical thing."""
        word = word.split("'")[0].split("-")[-1]
        return word in self.things or (word.endswith("s") and (
            word[:-1] in self.things or (word.endswith("es") and word[:-2] in self.things)))


def _bases(word: str) -> list[str]:
    """What a comparative or an adjective made from a noun is built on: "nicer" and "nicest"
    on nice, "bigger" on big, "tidier" on tidy, "jammy" on jam, "oniony" on onion."""
    bases: list[str] = []
    for ending in ("est", "er", "y"):
        if len(word) > len(ending) + 2 and word.endswith(ending):
            stem = word[: -len(ending)]
            bases += [stem, stem + "e"]
            if len(stem) > 2 and stem[-1] == stem[-2]:
                bases.append(stem[:-1])  # bigger, jammy
            if ending != "y" and stem.endswith("i"):
                bases.append(stem[:-1] + "y")  # tidier, happiest
    return bases


def _phrases(items: list[str]) -> tuple[tuple[str, ...], ...]:
    """Phrases as word tuples, longest first (so "could you please" wins over "could you")."""
    return tuple(sorted({tuple(p.split()) for p in items}, key=lambda p: (-len(p), p)))


def _read(name: str) -> Any:
    path = KNOWLEDGE_DIR / name
    text = path.read_text()
    # BaseLoader keeps every scalar a string: "on", "off" and "no" are words here, not bools.
    return yaml.load(text, Loader=yaml.BaseLoader) if name.endswith(".yaml") else json.loads(
        text)


def _people(raw: dict[str, Any]) -> tuple[dict[str, PersonWord], dict[str, str]]:
    gender = {w: g for g, words in raw["gender"].items() for w in words}
    kin = frozenset(raw["kin_words"])
    people: dict[str, PersonWord] = {}
    for role, row in raw["roles"].items():
        for word in row["words"]:
            people.setdefault(word, PersonWord(role, row.get("age_group"), gender.get(word),
                                               bool(row.get("user")), word in kin))
    states = {w: kind for kind, words in raw["vulnerability_words"].items() for w in words}
    return people, states


@cache
def load_lexicon() -> Lexicon:
    """The lexicon, read from the knowledge files once per process."""
    verbs_raw = _read("verbs.yaml")["schemas"]
    schemas: dict[str, list[str]] = {}
    for schema, row in verbs_raw.items():
        for phrase in row["words"]:
            schemas.setdefault(phrase, []).append(schema)
    words = _read("words.yaml")
    english = _read("english_words.json")
    nouns = _read("thing_nouns.json")
    people, states = _people(people_table())
    rooms = {phrase: room for room, phrases in words["rooms"].items() for phrase in phrases}
    return Lexicon(
        schemas={k: tuple(v) for k, v in schemas.items()},
        max_verb_words=max(len(k.split()) for k in schemas),
        verb_starts=frozenset(k.split()[0] for k in schemas),
        english=frozenset(english["words"]) | frozenset(english["inflections"])
        | frozenset(words["function_words"]),
        things=frozenset(nouns["nouns"]) | frozenset(nouns["measures"])
        | frozenset(words["portions"]),
        measures=frozenset(nouns["measures"]) | frozenset(words["portions"]),
        portions=frozenset(words["portions"]),
        verbs=frozenset(english["verbs"]) | frozenset(k for k in schemas if " " not in k),
        fillers=_phrases(words["fillers"]),
        negations=_phrases(words["negations"]),
        sequencers=_phrases(words["sequencers"]),
        condition_openers=frozenset(words["condition_openers"]),
        purpose_openers=_phrases(words["purpose_openers"]),
        determiners=_phrases(words["determiners"]),
        numbers={k: float(v) for k, v in words["numbers"].items()},
        prepositions=_phrases(words["prepositions"]),
        particles=frozenset(words["particles"]),
        manner={k: _phrases(v) for k, v in words["manner"].items()},
        harm_words=frozenset(words["harm_words"]),
        health_words=frozenset(words["health_words"]),
        private_things=frozenset(words["private_things"]),
        rooms=rooms,
        people=people,
        states=states,
        person_variants={word: frozenset(group) for group in people_table()["variants"]
                         for word in group},
    )
