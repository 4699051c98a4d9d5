"""How colloquial English is read: the idiom rules and word lists of `knowledge/language.json`.

In: `knowledge/language.json` (hand-written rewrite rules, action nouns, chain and aspect
verbs, implied devices, time and fact phrases) and `knowledge/english_words.json` (derived from
WordNet by `build/build_english.py`). Out: `Language`, immutable tables loaded once per
directory (`load_language()`, cached), with `is_english()`/`is_verb()` helpers for the
comprehension check. Fails: `FileNotFoundError`/`json.JSONDecodeError`/`KeyError` when a file
is missing or malformed, at load time only.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR

_SUFFIXES = (("ies", "y"), ("es", ""), ("s", ""), ("ied", "y"), ("ed", ""), ("ed", "e"),
             ("ing", ""), ("ing", "e"), ("er", ""), ("est", ""), ("'s", ""), ("s'", ""),
             ("ly", ""), ("'ll", ""), ("n't", ""))

_DERIVATIONS = (("ifier", ""), ("ifier", "y"), ("ier", "y"), ("ier", ""), ("er", ""),
                ("er", "e"), ("or", ""), ("or", "e"), ("ion", ""), ("ion", "e"),
                ("ment", ""), ("ness", ""), ("able", ""), ("able", "e"), ("ible", ""),
                ("ful", ""), ("ity", ""), ("ist", ""), ("ism", ""), ("ette", ""),
                ("let", ""), ("ie", ""), ("y", ""), ("s", ""), ("ies", "y"))


@dataclass(frozen=True, slots=True)
class DeviceRule:
    """A device a verb implies when the command names none, limited to some object concepts."""

    verbs: frozenset[str]
    device: str
    for_objects: frozenset[str]


@dataclass(frozen=True, slots=True)
class Language:
    """The idiom and word tables the command reader uses."""

    word_sets: dict[str, frozenset[str]]
    rewrites: tuple[tuple[tuple[str, ...], tuple[str, ...]], ...]
    # Every word-list token of the rewrites ("@name", "a|b"; "?" dropped) -> the words it
    # accepts, read once at load.
    token_sets: dict[str, frozenset[str]]
    # Per rewrite, the words its first token accepts (None: a slot, a number or optional), so
    # a clause skips the rules that cannot open it without trying them.
    rewrite_openers: tuple[frozenset[str] | None, ...]
    action_nouns: dict[str, str]
    chain_verbs: frozenset[str]
    aspect_verbs: tuple[str, ...]
    devices: tuple[DeviceRule, ...]
    statement_openers: frozenset[str]
    time_words: dict[str, tuple[str, ...]]
    facts: dict[str, tuple[str, ...]]
    english: frozenset[str]
    english_verbs: frozenset[str]
    inflections: dict[str, str]

    def base_forms(self, word: str) -> list[str]:
        """The word and the plain forms its English suffixes may hide (boxes -> box)."""
        forms = [word]
        if word in self.inflections:
            forms.append(self.inflections[word])
        for suffix, replacement in _SUFFIXES:
            if word.endswith(suffix) and len(word) > len(suffix) + 1:
                stem = word[: -len(suffix)] + replacement
                forms.append(stem)
                if len(stem) > 2 and stem[-1] == stem[-2]:
                    forms.append(stem[:-1])  # "dropped" -> "drop"
        return forms

    def is_english(self, word: str) -> bool:
        """Whether WordNet or the function-word list knows the word in some form."""
        if any(ch.isdigit() for ch in word):
            return True
        return any(form in self.english for form in self.base_forms(word))

    def looks_english(self, word: str) -> bool:
        """`is_english`, or a derivation or compound of English words (humidifier, dogbowl)."""
        if self.is_english(word):
            return True
        for suffix, replacement in _DERIVATIONS:
            if word.endswith(suffix) and len(word) - len(suffix) >= 3 and self.is_english(
                    word[: -len(suffix)] + replacement):
                return True
        return any(self.is_english(word[:cut]) and self.is_english(word[cut:])
                   for cut in range(3, len(word) - 2))

    def is_verb(self, word: str) -> bool:
        """Whether the word is (an inflection of) an English verb."""
        return any(form in self.english_verbs for form in self.base_forms(word))


def _read(directory: Path, name: str) -> Any:
    return json.loads((directory / name).read_text(encoding="utf-8"))


def token_words(token: str, word_sets: dict[str, frozenset[str]]) -> frozenset[str] | None:
    """The words a rewrite pattern's token accepts: `@name` a word set, `a|b` alternatives;
    None for the tokens that are not word lists (`X` a slot, `#` a number, `END`)."""
    if token in ("X", "#", "END"):
        return None
    if token.startswith("@"):
        return word_sets.get(token[1:], frozenset())
    return frozenset(token.split("|"))


@cache
def load_language(directory: Path = KNOWLEDGE_DIR) -> Language:
    """Read `language.json` and `english_words.json` from `directory` (cached per directory).

    Args:
        directory: the folder holding the knowledge JSON files.

    Returns:
        The immutable `Language` tables.
    """
    raw = _read(directory, "language.json")
    english = _read(directory, "english_words.json")
    function_words = frozenset(raw["function_words"]["words"])
    word_sets = {name: frozenset(words) for name, words in raw["word_sets"].items()}
    rewrites = tuple((tuple(pattern.split()), tuple(replacement.split()))
                     for pattern, replacement in raw["rewrites"])
    token_sets = {token: words for pattern, _ in rewrites for token in
                  (t.rstrip("?") if t.endswith("?") and len(t) > 1 else t for t in pattern)
                  if (words := token_words(token, word_sets)) is not None}
    return Language(
        word_sets=word_sets,
        rewrites=rewrites,
        token_sets=token_sets,
        rewrite_openers=tuple(
            None if pattern[0].endswith("?") else token_sets.get(pattern[0])
            for pattern, _ in rewrites),
        action_nouns=dict(raw["action_nouns"]["words"]),
        chain_verbs=frozenset(raw["chain_verbs"]["words"]),
        aspect_verbs=tuple(raw["aspect_verbs"]["words"]),
        devices=tuple(DeviceRule(frozenset(r["verbs"]), r["device"], frozenset(r["for"]))
                      for r in raw["implied_devices"]["rules"]),
        statement_openers=frozenset(raw["statement_openers"]["words"]),
        time_words={k: tuple(v) for k, v in raw["time_words"].items() if k != "_about"},
        facts={k: tuple(v) for k, v in raw["facts"].items() if k != "_about"},
        english=frozenset(english["words"]) | function_words,
        english_verbs=frozenset(english["verbs"]),
        inflections=dict(english["inflections"]),
    )
