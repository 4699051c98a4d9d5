"""Command text into clause strings, and the verb phrase that opens a clause.

In: the raw command text and the knowledge tables (verb words, irregular verbs). Out:
`normalize()` gives lower-case text with punctuation as separate tokens; `split_clauses()` cuts
it on sentence ends, "then", "after that", and on "and"/commas followed by a new verb, a
negation or a condition word; `verb_at()` finds the verb phrase (phrasal verbs, separated
particles, inflected forms) at the start of a word list. Never fails: text without a known verb
is one clause.
"""

from __future__ import annotations

import re
from functools import lru_cache

from app.domain.analysis.knowledge_base import Knowledge

PREPOSITIONS = (
    "in front of", "next to", "on top of", "out of", "away from", "close to", "instead of",
    "into", "inside", "onto", "in", "on", "under", "underneath", "beneath", "behind", "near",
    "beside", "by", "at", "to", "toward", "towards", "for", "with", "from", "through", "past",
    "across", "over", "above", "off", "around", "along", "against", "between", "without",
    "within", "of", "halfway up", "halfway down", "partway up", "partway down",
)
PARTICLES = frozenset({"on", "off", "up", "down", "away", "out", "over", "back", "in", "open"})
LEADING_FILLER = ("please", "robot", "hey", "ok", "okay", "now", "then", "also", "and", "first",
                  "next", "finally", "afterwards", "after that", "so", "just", "can you",
                  "could you", "would you", "will you", "i want you to", "i need you to",
                  "i'd like you to", "go ahead and", "make sure to", "make sure you",
                  "remember to", "try to", "you should", "you can", "then please", "but",
                  "right", "quickly", "quick", "kindly", "be a dear and", "be a love and",
                  "do me a favour and", "do me a favor and", "i'd like you to", "you need to",
                  "you must", "you'll need to", "you have to", "we need you to", "help me",
                  "excuse me", "oi", "yo", "hiya", "sorry", "pls", "plz", "would you mind",
                  "could you maybe", "can you maybe", "would you maybe", "maybe", "mate",
                  "if you could", "if you can", "if you would", "do us a favour and",
                  "proper", "properly", "really")
NEGATIONS = ("don't", "do not", "dont", "never", "no need to", "do n't", "stop to")
CONDITIONS = ("if", "when", "once", "unless", "while", "whenever", "in case", "as soon as",
              "before", "after", "until", "since", "because", "so that", "so")
# Words that open a new sentence after a comma (a subject), not another item of a list.
_SUBJECTS = frozenset({"i", "i'll", "i'm", "i've", "i'd", "we", "we'll", "we're", "he", "he's",
                       "she", "she's", "they", "they're", "it's", "everyone's", "everybody's",
                       "nobody's", "no", "there's", "that's", "you'll", "you're"})
# A word then one of these after a comma is a subject and its verb ("gran can", "dad will").
_AUXILIARIES = frozenset({"can", "can't", "cannot", "will", "won't", "should", "must", "might",
                          "may", "could", "would", "needs", "wants", "is", "isn't", "has",
                          "hasn't", "does", "doesn't"})
_PREPOSITION_PARTS: dict[str, tuple[tuple[str, list[str]], ...]] = {
    first: tuple((p, p.split()) for p in PREPOSITIONS if p.split()[0] == first)
    for first in dict.fromkeys(p.split()[0] for p in PREPOSITIONS)
}
_SPLITTING_CONDITIONS = frozenset({"if", "unless", "before", "while", "until", "once", "when",
                                   "whenever", "because", "so"})
_AFTER_PARTICLE = frozenset({"and", ",", "for", "so", "until", "while", "before", "after",
                             "when", "if", "again", "now", "high", "low", "full", "max",
                             "then", "please", "overnight", "quickly", "too"})


_RUN_TOGETHER = {"gimme": "give me", "lemme": "let me", "gonna": "going to",
                 "wanna": "want to", "gotta": "got to", "dunno": "do not know"}
_RUN_TOGETHER_PATTERN = re.compile(rf"\b({'|'.join(_RUN_TOGETHER)})\b")
# "Mrs. Patel", "Dr. Okafor": the dot ends a title, not a sentence.
TITLE_DOT = re.compile(r"\b(mr|mrs|ms|dr|prof|st|sr|jr|mx)\.(?=\s)", re.IGNORECASE)
_BRACKETS = re.compile(r"[\"()\[\]{}]")
_DASH = re.compile(r"\s[-\u2013\u2014]+\s")
_PUNCTUATION = re.compile(r"([,;.!?:])(?=\s|$)")
# "whoever's in the shower": the "'s" is "is", not an owner.
_PRONOUN_IS = re.compile(r"\b(whoever|whatever|whichever|anyone|anything|someone|something)'s\b")


def normalize(text: str) -> str:
    """Lower case, plain apostrophes, run-together words apart ("gimme"), punctuation as
    separate tokens, single spaces."""
    text = text.lower().replace("\u2019", "'").replace("\u2018", "'")
    text = _RUN_TOGETHER_PATTERN.sub(lambda m: _RUN_TOGETHER[m.group(1)], text)
    text = _BRACKETS.sub(" ", text)
    text = _DASH.sub(" ; ", f" {text} ")
    text = TITLE_DOT.sub(r"\1", text)
    text = _PUNCTUATION.sub(r" \1 ", text)
    text = _PRONOUN_IS.sub(r"\1", text)
    return " ".join(text.split())


def strip_leading(words: list[str], phrases: tuple[str, ...]) -> tuple[list[str], str | None]:
    """Remove the longest of `phrases` that opens `words`; also return which one (or None)."""
    if not words:
        return words, None
    for phrase, parts in _by_first_word(phrases).get(words[0], ()):
        if words[: len(parts)] == parts:
            return words[len(parts):], phrase
    return words, None


@lru_cache(maxsize=256)
def _by_first_word(phrases: tuple[str, ...]) -> dict[str, tuple[tuple[str, list[str]], ...]]:
    # The phrase tables are constants, so each is grouped by first word, longest first, once.
    grouped: dict[str, list[tuple[str, list[str]]]] = {}
    for phrase in sorted(phrases, key=len, reverse=True):
        parts = phrase.split()
        if parts:
            grouped.setdefault(parts[0], []).append((phrase, parts))
    return {word: tuple(found) for word, found in grouped.items()}


def preposition_parts() -> dict[str, tuple[tuple[str, list[str]], ...]]:
    """Each preposition's words, grouped by first word (in `PREPOSITIONS` order)."""
    return _PREPOSITION_PARTS


def verb_at(words: list[str], knowledge: Knowledge) -> tuple[str, int, int | None] | None:
    """The verb phrase opening `words`.

    Args:
        words: the clause's words, filler already removed.
        knowledge: the verb tables.

    Returns:
        (verb phrase, words used at the start, index of a separated particle), or None when
        the first word is no known verb.
    """
    if not words:
        return None
    first = lemma(words[0], knowledge)
    lemmas = [first, *words[1:]]
    for length in range(min(4, len(lemmas)), 0, -1):
        phrase = " ".join(lemmas[:length])
        if phrase in knowledge.verb_words:
            best: tuple[str, int, int | None] = (phrase, length, None)
            if length == 1:
                particle = _separated_particle(words, first, knowledge)
                if particle is not None:
                    best = (f"{first} {words[particle]}", 1, particle)
            return best
    particle = _separated_particle(words, first, knowledge)
    if particle is not None:
        return (f"{first} {words[particle]}", 1, particle)
    return None


def lemma(word: str, knowledge: Knowledge) -> str:
    """The base form of a verb ("brought" -> "bring", "filling" -> "fill"), else the word."""
    if word in knowledge.irregular_verbs:
        return knowledge.irregular_verbs[word]
    if word in knowledge.verb_words:
        return word
    for suffix, repl in (("ing", ""), ("ing", "e"), ("s", ""), ("es", ""), ("ed", ""),
                         ("d", ""), ("ied", "y"), ("ies", "y")):
        stem = word[: -len(suffix)] + repl if word.endswith(suffix) else ""
        if stem in knowledge.verb_words:
            return stem
        if suffix == "ing" and len(stem) > 2 and stem[-1] == stem[-2] and (
                stem[:-1] in knowledge.verb_words):
            return stem[:-1]  # "dropping" -> "drop"
    return word


def _separated_particle(words: list[str], verb: str, knowledge: Knowledge) -> int | None:
    for position in range(2, len(words)):
        word = words[position]
        if word in PARTICLES and f"{verb} {word}" in knowledge.verb_words:
            after = words[position + 1] if position + 1 < len(words) else None
            if after is None or after in _AFTER_PARTICLE or after in _PREPOSITION_PARTS:
                return position
    return None


def _is_clause_start(words: list[str], knowledge: Knowledge) -> bool:
    rest, _ = strip_leading(words, ("then", "also", "please", "just"))
    rest, negation = strip_leading(rest, NEGATIONS)
    if negation or strip_leading(rest, CONDITIONS)[1]:
        return True
    return verb_at(rest, knowledge) is not None


def split_clauses(text: str, knowledge: Knowledge) -> list[str]:
    """Split a normalised command into clause strings, in order."""
    words = text.split()
    clauses: list[list[str]] = [[]]
    for position, word in enumerate(words):
        # What follows matters only after these words; slicing it for every word is quadratic.
        rest = words[position + 1:] if word in (",", "and", "after") else []
        if word in (".", ";", "!", "?", ":"):
            clauses.append([])
            continue
        if word == "," and clauses[-1] and rest[:1] and (
                rest[0] in _SUBJECTS or (rest[1:2] and rest[1] in _AUXILIARIES)):
            # ", I'll take it down later" / ", everyone's in bed" / ", gran can take it up":
            # a new sentence, not a list.
            clauses.append([])
            continue
        if word == "then" or (word == "after" and rest[:1] == ["that"]):
            clauses.append([])
            continue
        if word == "that" and clauses[-1] == [] and position and words[position - 1] == "after":
            continue
        if word in ("and", ",") and clauses[-1] and _is_clause_start(rest, knowledge):
            clauses.append([])
            continue
        if word in _SPLITTING_CONDITIONS and clauses[-1]:
            clauses.append([])
        clauses[-1].append(word)
    return [" ".join(c).strip(" ,") for c in clauses if " ".join(c).strip(" ,")]
