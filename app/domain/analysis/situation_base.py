"""Shared reading of a whole command for the situation rules: phrases, people named, departures.

In: a `Context` (the normalised command text, the scene view, the parsed steps) and the
hand-written situation knowledge in `knowledge/hazard_situations.json`. Out: small predicates the
rule modules `situations_people.py` and `situations_home.py` combine: whether a phrase group
occurs (whole words), which scene people the command names, whether everyone leaves the home or
the robot leaves the room, who stays behind awake. These read the whole command so that a rule
still fires when a clause was not parsed into a step. Fails: `load_situations` raises
`FileNotFoundError`/`json.JSONDecodeError`/`KeyError` if the data file is missing or broken.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import cache, lru_cache
from pathlib import Path
from typing import Any

from app.domain.analysis.context import Context
from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR, Knowledge
from app.domain.analysis.scene_view import PersonView
from app.domain.analysis.word_filter import TEXT_MEMO_SIZE, candidates, may_occur

_PRONOUNS = {"her": "female", "she": "female", "she's": "female", "herself": "female",
             "him": "male", "he": "male", "he's": "male", "his": "male", "himself": "male"}
_GROUP_WORDS = ("everyone", "everybody", "everyone's", "every bedroom", "all the residents",
                "each resident", "each person", "every resident", "all of them")


@dataclass(frozen=True, slots=True)
class Situations:
    """The situation tables: phrase groups (tuples) and structured records (dicts)."""

    phrases: dict[str, tuple[str, ...]]
    records: dict[str, Any]

    def group(self, name: str) -> tuple[str, ...]:
        return self.phrases.get(name, ())


@cache
def load_situations(directory: Path = KNOWLEDGE_DIR) -> Situations:
    """Read `hazard_situations.json` (cached per directory).

    Args:
        directory: the knowledge folder.

    Returns:
        The `Situations` tables.
    """
    raw = json.loads((directory / "hazard_situations.json").read_text(encoding="utf-8"))
    phrases = {k: tuple(str(w).lower() for w in v) for k, v in raw.items()
               if isinstance(v, list) and all(isinstance(w, str) for w in v)}
    records = {k: v for k, v in raw.items() if k not in phrases and not k.startswith("_")}
    return Situations(phrases=phrases, records=records)


@lru_cache(maxsize=TEXT_MEMO_SIZE)
def _tokens(text: str) -> tuple[str, frozenset[str]]:
    """The padded text and its words, each also without a possessive ending."""
    words = text.split()
    bare = {w[:-2] if w.endswith("'s") else w[:-1] if w.endswith("'") else w for w in words}
    return f" {text} ", frozenset(words) | bare


def contains(text: str, phrase: str) -> bool:
    """Whether `phrase` occurs in normalised `text` as whole words (a possessive 's allowed).

    Normalised text has its punctuation split off into tokens, so a word-set or padded
    substring test is a whole-word test, with no regular expression per phrase.
    """
    padded, words = _tokens(text)
    if " " not in phrase:
        return phrase in words
    return any(f" {phrase}{tail} " in padded for tail in ("", "'s", "'"))


def contained(text: str, phrases: tuple[str, ...]) -> list[str]:
    """The phrases of the group that `contains` finds in the text, in group order."""
    return [phrase for phrase in candidates(text, phrases) if contains(text, phrase)]


def any_phrase(text: str, phrases: tuple[str, ...] | list[str]) -> str | None:
    """A phrase of the group found in the text (the leftmost occurrence), or None."""
    group = tuple(phrases)
    if not group or not may_occur(text, group):
        return None
    match = _group_pattern(group).search(text)
    return match.group(1) if match else None


@lru_cache(maxsize=512)
def _group_pattern(phrases: tuple[str, ...]) -> re.Pattern[str]:
    """One compiled alternation per phrase group, longest phrases first."""
    alternatives = "|".join(re.escape(p) for p in sorted(set(phrases), key=len, reverse=True))
    return re.compile(rf"(?<![\w'])({alternatives})(?:'s|')?(?![\w'-])")


def person_words(ctx: Context, person: PersonView) -> set[str]:
    """Lower-case words and phrases that name a person in a command."""
    words: set[str] = {person.id.lower()}
    if person.name:
        name = person.name.lower()
        words.add(name)
        parts = name.split()
        if len(parts) > 1 and parts[0] not in ("mr", "mrs", "ms", "miss", "dr"):
            words.add(parts[0])
    if person.role:
        words.add(person.role)
        words.add(person.role + "s")
    for word, role in ctx.knowledge.role_index.get(person.role_class or "", ()):
        if role.is_user:
            continue
        if role.name in ("guest", "adult", "child", "sibling"):
            continue  # too broad: "friend" does not name a particular resident
        if role.gender and person.gender and role.gender != person.gender:
            continue
        words.add(word)
    return {w for w in words if w}


def named_people(ctx: Context, text: str | None = None) -> list[PersonView]:
    """Scene people the text names (by name, role word, "everyone", or an unambiguous pronoun).

    Args:
        ctx: the analysis context.
        text: the text to read (the whole command by default).

    Returns:
        The people, in scene order, without the user unless named as "me".
    """
    text = ctx.text if text is None else text
    known = ctx.named_in.get(text)
    if known is None:
        known = ctx.named_in[text] = _named_people(ctx, text)
    return list(known)


def _named_people(ctx: Context, text: str) -> list[PersonView]:
    people = [p for p in ctx.view.real_people() if not p.is_user]
    if contained(text, _GROUP_WORDS):
        return people
    found = [p for p in people if any(contains(text, w) for w in person_words(ctx, p))]
    if found:
        return found
    genders = {g for w, g in _PRONOUNS.items() if contains(text, w)}
    if genders:
        matching = [p for p in people if p.gender in genders or p.gender is None]
        if len(matching) == 1:
            return matching
    return []


def everyone_leaves(ctx: Context) -> bool:
    """Whether the command has the user (and robot) leave the home."""
    return any_phrase(ctx.text, ctx.knowledge.cues.get("leaving", ())) is not None or any_phrase(
        ctx.text, load_situations().group("departure_phrases")) is not None


def robot_leaves_room(ctx: Context) -> bool:
    """Whether the command sends the robot away from where it is working (or out of the home)."""
    return everyone_leaves(ctx) or any_phrase(ctx.text, load_situations().group(
        "room_departure_phrases")) is not None


def awake_carer_stays(ctx: Context) -> bool | None:
    """True if an awake adult other than the user stays home, False if not, None if unknown."""
    if not ctx.view.people_known:
        return None
    return any(not p.is_user and not p.asleep and p.age_group in ("adult", "teen", None)
               and p.cognitive_state != "impaired" for p in ctx.view.real_people())


def has_condition(ctx: Context, person: PersonView, condition: str) -> bool:
    """Whether a person has a named condition, from scene properties or the command's words."""
    record = load_situations().records["conditions"][condition]
    props = person.properties
    truthy = (True, "true", "yes", 1)
    if any(props.get(key) in truthy for key in record["properties"]):
        return True
    values: list[Any] = []
    for key in ("conditions", "diagnoses", "needs", "notes"):
        value = props.get(key)
        values += value if isinstance(value, list) else [value] if value else []
    listed = " ".join(str(v).lower() for v in values)
    if contained(listed, (*record["words"], *record["properties"])):
        return True
    return bool(contained(ctx.text, tuple(record["words"]))) and person.id in {
        p.id for p in named_people(ctx)}


_NEGATORS = frozenset({"no", "without", "not", "never", "non", "instead"})


@lru_cache(maxsize=16)
def _substance_lexicon(knowledge: Knowledge) -> tuple[tuple[str, ...], re.Pattern[str]]:
    """The substance words, longest first, and one whole-word pattern for all of them."""
    words = tuple(sorted(knowledge.substance_words, key=len, reverse=True))
    return words, re.compile(r"(?<![\w'])(" + "|".join(re.escape(w) for w in words)
                             + r")(?![\w'-])")


def substances_in(ctx: Context, text: str) -> list[str]:
    """Substances whose words occur in the text (not negated: "no nuts", "peanut-free").

    Args:
        ctx: the analysis context (for the substance lexicon).
        text: normalised text.

    Returns:
        Substance names, in order of first occurrence, without repeats.
    """
    table = ctx.knowledge.substance_words
    words, pattern = _substance_lexicon(ctx.knowledge)
    if not may_occur(text, words):
        return []
    found: list[str] = []
    for match in pattern.finditer(text):
        before = text[:match.start()].split()[-2:]
        if any(w in _NEGATORS for w in before):
            continue
        name = table[match.group(1)]
        if name not in found:
            found.append(name)
    return found


def is_softened(text: str, food: str, softening: tuple[str, ...]) -> bool:
    """Whether a food word is made safe to swallow nearby ("mashed banana", "grapes, quartered")."""
    padded = f" {text} "
    start = padded.find(f" {food} ")
    while start >= 0:
        window = padded[max(0, start - 30): start + len(food) + 32]
        if any_phrase(window.strip(), softening):
            return True
        start = padded.find(f" {food} ", start + 1)
    return False
