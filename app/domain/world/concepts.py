"""Object concepts: what a household noun names, for objects whose type is a plain noun.

In: a noun phrase as a request or a command gives it ("chef's knife", "wallet", "credit cards").
Out: `concept_of(phrase)` -> the `Concept` it names (its AI2-THOR types, its hazard properties,
a typical mass), or None. Hand-written concepts (`data/concepts.json`) win; otherwise WordNet's
hypernyms (`data/wordnet_lexicon.json`, about 8,700 nouns placed under a concept) decide. A
phrase is tried whole, then singular, then by its head noun (its last word).
Fails: never; a phrase no table knows gives None.
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

_DATA = Path(__file__).with_name("data")
_NON_WORD = re.compile(r"[^a-z0-9' ]+")


@dataclass(frozen=True, slots=True)
class Concept:
    """A kind of household object: what it is called, what it is in AI2-THOR, what it is like."""

    name: str
    types: tuple[str, ...]
    props: frozenset[str]
    mass_kg: float | None
    word_mass: Mapping[str, float] = field(default_factory=dict, compare=False)
    """Typical masses of words that differ from the concept's (a cane is no wheelchair)."""

    def word_mass_of(self, name: str) -> float | None:
        """The typical mass of the word itself, when it differs from the concept's (a radio is
        no television); "a milk carton" weighs what a carton does, whatever it holds."""
        key = _key(name)
        return self.word_mass.get(key, self.word_mass.get(key.split(" ")[-1] if key else ""))


@cache
def _tables() -> tuple[dict[str, Concept], dict[str, Concept]]:
    """(word -> concept) from the hand-written table, and from WordNet."""
    raw = json.loads((_DATA / "concepts.json").read_text())["concepts"]
    concepts = {
        name: Concept(name, tuple(row.get("types", ())), frozenset(row.get("props", ())),
                      row.get("mass_kg"), {_key(w): float(m) for w, m in row.get(
                          "word_mass", {}).items()})
        for name, row in raw.items()
    }
    by_word: dict[str, Concept] = {}
    for concept in concepts.values():
        for word in raw[concept.name]["words"]:
            by_word.setdefault(_key(word), concept)
    wordnet = json.loads((_DATA / "wordnet_lexicon.json").read_text())["words"]
    by_wordnet = {_key(w): concepts[c] for w, c in wordnet.items() if c in concepts}
    return by_word, by_wordnet


_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])")


def _key(phrase: str) -> str:
    """Lower-case words: "HearingAid" and "hearing_aid" are "hearing aid"."""
    spaced = _CAMEL.sub(" ", phrase).replace("_", " ")
    return " ".join(_NON_WORD.sub(" ", spaced.lower()).split())


def modifier_concepts(phrase: str) -> list[Concept]:
    """The concepts the words before the head name ("solvent" in "solvent drum")."""
    by_word, by_wordnet = _tables()
    found: list[Concept] = []
    for word in _key(phrase).split()[:-1]:
        concept = by_word.get(word) or by_wordnet.get(word) or by_word.get(singular(word))
        if concept is not None:
            found.append(concept)
    return found


def singular(word: str) -> str:
    """A plural noun's singular by the regular English rules (knives -> knife, dishes -> dish)."""
    if len(word) <= 3 or word.endswith(("ss", "us", "is")):
        return word
    for ending, replacement in (("ives", "ife"), ("ies", "y"), ("ches", "ch"), ("shes", "sh"),
                                ("xes", "x"), ("oes", "o"), ("ses", "s")):
        if word.endswith(ending):
            return word[: -len(ending)] + replacement
    return word[:-1] if word.endswith("s") else word


def _forms(phrase: str) -> list[str]:
    words = phrase.split()
    if not words:
        return []
    last = singular(words[-1])
    forms = [phrase, " ".join([*words[:-1], last])]
    if len(words) > 1:
        forms += [words[-1], last]
    return list(dict.fromkeys(forms))


@cache
def concept_of(phrase: str) -> Concept | None:
    """The concept a noun phrase names, or None.

    Args:
        phrase: a noun or noun phrase, any case ("Kitchen knives", "credit_card").

    Returns:
        The concept, hand-written words first, then WordNet's placement of the words.
    """
    by_word, by_wordnet = _tables()
    forms = _forms(_key(phrase))
    for table in (by_word, by_wordnet):
        for form in forms:
            found = table.get(form)
            if found is not None:
                return found
    return None


def known_noun(phrase: str) -> bool:
    """Whether any concept table knows the phrase (or its head noun)."""
    return concept_of(phrase) is not None
