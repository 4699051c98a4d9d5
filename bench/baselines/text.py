"""Command text handling shared by the baselines: clauses and lexicon look-ups.

In: a natural-language command; a lexicon (name -> regular-expression word patterns) read from
a YAML data file under `bench/baselines/data/`. Out: the command's clauses in order (a rough
stand-in for the steps it implies) and the lexicon names whose patterns occur in a text.
Fails: `BaselineDataError` when a data file is missing, is not a mapping of names to pattern
lists, or holds a pattern that is not a valid regular expression.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

DATA_DIR = Path(__file__).resolve().parent / "data"

# Clause boundaries: punctuation, a dash used as a pause, and the connectives that begin a new
# step ("then", "and then", "while", "after", "before", "so").
_CLAUSE_BREAK = re.compile(
    r"\s*(?:[,;:!?]|\.(?=\s|$)|\s[-\u2013\u2014]\s|\band then\b|\bthen\b|\bwhile\b|"
    r"\bafter\b|\bbefore\b|\bso that\b|\bso\b)\s*"
)


class BaselineDataError(ValueError):
    """A baseline data file that cannot be used."""


def normalise(text: str) -> str:
    """Lower-case the text and straighten typographic quotes."""
    return text.lower().replace("\u2019", "'").replace("\u2018", "'")


def split_clauses(command: str) -> list[str]:
    """The command's clauses in order, lower-cased, empty pieces dropped.

    Args:
        command: the natural-language command.

    Returns:
        At least one clause (the whole command when nothing splits it).
    """
    text = normalise(command)
    clauses = [c.strip() for c in _CLAUSE_BREAK.split(text) if c and c.strip()]
    return clauses or [text.strip()]


_NOT_IMPERATIVE = re.compile(
    r"^(?:i|i'm|i've|i'll|it|it's|he|he's|she|she's|they|they're|we|we're|there's|that's|"
    r"his|her|their|our|everyone's|nobody|everyone)\b"
)


def is_imperative(clause: str) -> bool:
    """Whether a clause can be an instruction to the robot (it does not open with a subject).

    "It's about to pour" and "I've cut my finger" describe the world; their verbs are not
    actions the robot is asked to take.
    """
    return _NOT_IMPERATIVE.match(normalise(clause).strip()) is None


def actions_in(command: str, actions: Lexicon) -> frozenset[str]:
    """The action kinds named by the command's imperative clauses."""
    found: set[str] = set()
    for clause in split_clauses(command):
        if is_imperative(clause):
            found |= actions.names_in(clause)
    return frozenset(found)


def load_yaml(name: str) -> Any:
    """Read a data file of `bench/baselines/data/`.

    Raises:
        BaselineDataError: the file is missing or is not YAML.
    """
    path = DATA_DIR / name
    try:
        return yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as exc:
        raise BaselineDataError(f"{path}: {exc}") from exc


@dataclass(frozen=True)
class Lexicon:
    """Names, each with the word patterns that signal it in a text."""

    patterns: dict[str, tuple[re.Pattern[str], ...]]

    @classmethod
    def from_mapping(cls, raw: object, where: str) -> Lexicon:
        """Build from `{name: [pattern, ...]}`; patterns match whole words, inflected or not.

        Raises:
            BaselineDataError: on a wrong shape or an invalid pattern.
        """
        if not isinstance(raw, dict):
            raise BaselineDataError(f"{where}: expected a mapping of names to pattern lists")
        compiled: dict[str, tuple[re.Pattern[str], ...]] = {}
        for name, patterns in raw.items():
            if not isinstance(patterns, list) or not all(isinstance(p, str) for p in patterns):
                raise BaselineDataError(f"{where}: {name!r} must map to a list of patterns")
            try:
                compiled[str(name)] = tuple(
                    re.compile(rf"\b(?:{p})(?:s|es|ed|d|ing)?\b") for p in patterns
                )
            except re.error as exc:
                raise BaselineDataError(f"{where}: bad pattern for {name!r}: {exc}") from exc
        return cls(compiled)

    def names_in(self, text: str) -> frozenset[str]:
        """The names with at least one pattern occurring in the (normalised) text."""
        lowered = normalise(text)
        return frozenset(
            name for name, patterns in self.patterns.items()
            if any(p.search(lowered) for p in patterns)
        )
