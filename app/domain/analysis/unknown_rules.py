"""The data behind the unknowns rules: which missing facts decide, per class of thing.

In: `knowledge/unknowns.json` (hand-written general knowledge: word lists, word-to-word
tables, mass ranges, patterns). Out: `UnknownRules`, immutable lookup tables, built once per
directory and cached by `load_unknown_rules`; `has_phrase` tests whole-word phrase membership
in a text.
Fails: `FileNotFoundError`/`json.JSONDecodeError`/`KeyError` when the file is missing or
malformed, so the analyzer never runs with half of this knowledge.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cache, lru_cache
from pathlib import Path
from typing import Any

from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR
from app.domain.analysis.word_filter import TEXT_MEMO_SIZE, candidates

_TOKEN = re.compile(r"[\w'-]+")


@dataclass(frozen=True, slots=True)
class MassRange:
    """The typical mass of a class of object (or of a container holding some contents)."""

    words: tuple[str, ...]
    low_kg: float
    high_kg: float


@dataclass(frozen=True, slots=True)
class Appliance:
    """An appliance that heats what is put in it, and the materials that must not go in."""

    name: str
    words: tuple[str, ...]
    unsafe: tuple[str, ...]
    known_safe: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class UnknownRules:
    """Every table the unknowns rules read; the word groups are keyed section.name."""

    words: dict[str, tuple[str, ...]]
    appliances: tuple[Appliance, ...]
    object_masses: tuple[MassRange, ...]
    contents_masses: tuple[MassRange, ...]
    left_alone: tuple[re.Pattern[str], ...]
    maps: dict[str, dict[str, str]] = field(default_factory=dict)

    def group(self, name: str) -> tuple[str, ...]:
        """The phrases of one word group ("section.key"); a missing group is a KeyError."""
        return self.words[name]

    def mapping(self, name: str) -> dict[str, str]:
        """One word-to-word table ("section.key"); a missing table is a KeyError."""
        return self.maps[name]


def has_phrase(text: str, phrases: Iterable[str]) -> str | None:
    """The first phrase that occurs in `text` as whole words, or None.

    Args:
        text: lower-case text (a command, or an object's type, name and contents).
        phrases: lower-case phrases.

    Returns:
        The matching phrase, or None.
    """
    padded = _padded_text(text)
    # The rule tables are tuples: only the phrases whose first word the text has are tried.
    possible = candidates(text, phrases) if isinstance(phrases, tuple) else phrases
    for phrase in possible:
        if _padded_phrase(phrase) in padded:
            return phrase
    return None


# Token matching instead of one regex per phrase: Python's regex cache is small and the
# analyzer has thousands of phrases, so compiled patterns would be rebuilt every request.
# A phrase table's paddings are kept for good; a text's only while one request reads it again
# (TEXT_MEMO_SIZE), so no request is answered from work done for an earlier one.
def _pad(text: str) -> str:
    return " " + " ".join(_TOKEN.findall(text)) + " "


_padded_phrase = lru_cache(maxsize=8192)(_pad)
_padded_text = lru_cache(maxsize=TEXT_MEMO_SIZE)(_pad)


def _ranges(records: list[dict[str, Any]]) -> tuple[MassRange, ...]:
    return tuple(MassRange(tuple(r["words"]), float(r["kg"][0]), float(r["kg"][1]))
                 for r in records)


@cache
def load_unknown_rules(directory: Path = KNOWLEDGE_DIR) -> UnknownRules:
    """Read `unknowns.json` from `directory` (cached per directory).

    Args:
        directory: the knowledge folder.

    Returns:
        The immutable `UnknownRules`.
    """
    raw = json.loads((directory / "unknowns.json").read_text(encoding="utf-8"))
    words: dict[str, tuple[str, ...]] = {}
    maps: dict[str, dict[str, str]] = {}
    for section, body in raw.items():
        if not isinstance(body, dict):
            continue
        for key, value in body.items():
            if isinstance(value, list) and all(isinstance(v, str) for v in value):
                words[f"{section}.{key}"] = tuple(v.lower() for v in value)
            elif isinstance(value, dict) and value and all(
                    isinstance(v, str) for v in value.values()):
                maps[f"{section}.{key}"] = {k.lower(): v.lower() for k, v in value.items()}
    heating = raw["heating"]
    appliances = tuple(
        Appliance(name, tuple(r["words"]), tuple(r["unsafe"]),
                  tuple(heating["known_safe_holders"].get(name, ())))
        for name, r in heating["appliances"].items())
    return UnknownRules(
        words=words, appliances=appliances,
        object_masses=_ranges(raw["mass"]["objects"]),
        contents_masses=_ranges(raw["mass"]["contents"]),
        left_alone=tuple(re.compile(p) for p in raw["condition"]["left_alone_patterns"]),
        maps=maps)
