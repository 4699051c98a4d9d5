"""A cheap test that rules a phrase group out of a text before any regular expression runs.

In: a text and a tuple of phrases. Out: `may_occur`, False when no phrase of the group can occur
in the text as whole words, True when one might (the caller's own test then decides);
`candidates`, the phrases of the group that might, in group order. The rules ask dozens of
phrase groups of every command and almost all of them are absent, so these set tests replace
most of the searches.

Why it is exact: a whole-word match (not preceded by a letter, digit, underscore or apostrophe)
starts where one of the text's word runs (`\\w+`) starts, and a phrase's own leading word run
ends where the phrase does or at a character that is not a word character; either way the
text's word run there equals the phrase's leading word run. A group holding a phrase that does
not start with a word character is never ruled out.
"""

from __future__ import annotations

import re
from functools import lru_cache

_WORD_RUN = re.compile(r"\w+")
_LEADING_RUN = re.compile(r"\w*")


def may_occur(text: str, phrases: tuple[str, ...]) -> bool:
    """Whether some phrase of the group could occur in `text` as whole words."""
    leading = _leading_words(phrases)
    return leading is None or not leading.isdisjoint(_word_runs(text))


def candidates(text: str, phrases: tuple[str, ...]) -> tuple[str, ...]:
    """The phrases of the group that could occur in `text` as whole words, in group order."""
    by_word, unfiltered = _phrases_by_leading_word(phrases)
    hits = _word_runs(text) & by_word.keys()
    if not hits:
        return unfiltered
    found = {phrase for word in hits for phrase in by_word[word]}.union(unfiltered)
    return tuple(phrase for phrase in phrases if phrase in found)


@lru_cache(maxsize=4096)
def _word_runs(text: str) -> frozenset[str]:
    return frozenset(_WORD_RUN.findall(text))


@lru_cache(maxsize=2048)
def _leading_words(phrases: tuple[str, ...]) -> frozenset[str] | None:
    leading = set()
    for phrase in phrases:
        found = _LEADING_RUN.match(phrase)
        if found is None or not found.group(0):
            return None
        leading.add(found.group(0))
    return frozenset(leading)


@lru_cache(maxsize=2048)
def _phrases_by_leading_word(phrases: tuple[str, ...]
                             ) -> tuple[dict[str, tuple[str, ...]], tuple[str, ...]]:
    """The group's phrases by leading word run, and those with none (never filtered out)."""
    grouped: dict[str, list[str]] = {}
    unfiltered: list[str] = []
    for phrase in phrases:
        found = _LEADING_RUN.match(phrase)
        word = found.group(0) if found else ""
        if word:
            grouped.setdefault(word, []).append(phrase)
        else:
            unfiltered.append(phrase)
    return {w: tuple(ps) for w, ps in grouped.items()}, tuple(unfiltered)
