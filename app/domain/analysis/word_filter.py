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
from dataclasses import dataclass
from functools import lru_cache

# Memos keyed by a text (a command, a clause, an object's words) serve the many rules that
# read the same text within one request; they are kept this small so that a later request with
# the same command is analysed afresh, not answered from this one's work.
TEXT_MEMO_SIZE = 64

_WORD_RUN = re.compile(r"\w+")
_LEADING_RUN = re.compile(r"\w*")


@dataclass(frozen=True, slots=True)
class _GroupIndex:
    by_word: dict[str, tuple[str, ...]]  # leading word run -> the phrases it opens
    leading: frozenset[str]  # by_word's keys, for set operations with the text's words
    unfiltered: tuple[str, ...]  # phrases with no leading word run: never ruled out


def may_occur(text: str, phrases: tuple[str, ...]) -> bool:
    """Whether some phrase of the group could occur in `text` as whole words."""
    index = _index(phrases)
    return bool(index.unfiltered) or not index.leading.isdisjoint(_word_runs(text))


def candidates(text: str, phrases: tuple[str, ...]) -> tuple[str, ...]:
    """The phrases of the group that could occur in `text` as whole words, in group order."""
    index = _index(phrases)
    hits = index.leading & _word_runs(text)
    if not hits:
        return index.unfiltered
    found = {phrase for word in hits for phrase in index.by_word[word]}.union(index.unfiltered)
    return tuple(phrase for phrase in phrases if phrase in found)


@lru_cache(maxsize=TEXT_MEMO_SIZE)
def _word_runs(text: str) -> frozenset[str]:
    return frozenset(_WORD_RUN.findall(text))


@lru_cache(maxsize=4096)
def _index(phrases: tuple[str, ...]) -> _GroupIndex:
    grouped: dict[str, list[str]] = {}
    unfiltered: list[str] = []
    for phrase in phrases:
        found = _LEADING_RUN.match(phrase)
        word = found.group(0) if found else ""
        if word:
            grouped.setdefault(word, []).append(phrase)
        else:
            unfiltered.append(phrase)
    return _GroupIndex({w: tuple(ps) for w, ps in grouped.items()}, frozenset(grouped),
                       tuple(unfiltered))
