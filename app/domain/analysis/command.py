"""The command, read into ordered steps, temporal facts and what was not understood.

In: the command text, the knowledge tables and the scene's lower-case names. Out:
`read_command()` gives a `ParsedCommand`:
  - `steps`: `Step`s in command order (see `clause_roles`). Clauses split on sentence ends,
    "then", "after that", and on "and"/commas followed by a new verb (`clauses`); a leading
    "don't"/"never" marks a step negated; an "if/when/while ..." clause becomes the condition
    of the step that follows it (or precedes it). Colloquial wording is first rewritten into
    plain clauses (`idioms`): "run this to X" = carry, "nip upstairs" = go, "yank X off Y" =
    remove, "tell X off" = scold, "put X in at 200" = oven + switch on, "plug the sink" =
    stopper in, "go wake X" = wake X, "keep telling X off" = repeated.
  - `facts`: `CommandFacts` (see `command_facts`): `leaves_home`, `people_asleep`,
    `unattended_for`, `time_of_day`, `clock`, `robot_leaves_room`, `leaves_at_step`,
    `person_left_alone`, `repeated`, and the derived `unattended`.
  - `not_understood`: `Gap`s (see `comprehension`): instruction-shaped clauses whose verb no
    verb class covers, and object phrases no lexicon, dictionary or scene name knows. A rule
    should fail closed on a gap whose clause involves a hazard or a person.
  - `devices`: per step, the device its verb implies when the command names none (boil ->
    hob, bake -> oven, fill the sink -> tap), as a step index -> device word map.
`parse_command()` returns just the steps (kept for existing callers). Never fails: a clause
without a known verb gives a step with `action=None` (and maybe a gap).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Collection
from dataclasses import dataclass, field
from functools import lru_cache

from app.domain.analysis.clause_roles import Step, parse_clause
from app.domain.analysis.clauses import (
    CONDITIONS,
    LEADING_FILLER,
    NEGATIONS,
    normalize,
    split_clauses,
    strip_leading,
    verb_at,
)
from app.domain.analysis.command_facts import CommandFacts, command_facts
from app.domain.analysis.comprehension import Gap, find_gaps
from app.domain.analysis.idioms import rewrite
from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.language import Language, load_language

__all__ = ["CommandFacts", "Gap", "ParsedCommand", "Step", "normalize", "parse_command",
           "read_command"]


# A capitalised word inside a sentence (a sentence's first word is capitalised anyway).
_CAPITALISED = re.compile(r"(?<=[\w,'] )[A-Z][a-z]+")
_TIME_NOUNS = frozenset({"dinner", "lunch", "breakfast", "tea", "supper", "school", "work",
                         "bedtime", "midnight", "dark", "that", "lunchtime", "teatime",
                         "dinnertime", "bed", "dawn", "sunset", "noon", "this"})
_LEADING_TIMES = frozenset({"tonight", "tomorrow", "later", "today", "afterwards", "meanwhile",
                            "overnight", "now", "eventually", "soon"})
_CLOCK_WORDS = frozenset({"am", "pm", "a.m.", "p.m.", "o'clock", "sharp"})


@dataclass(frozen=True, slots=True)
class ParsedCommand:
    """Everything the reader understood (and did not) about one command."""

    steps: tuple[Step, ...]
    facts: CommandFacts
    text: str  # the command as `normalize` gives it (the rules read this, not the raw one)
    not_understood: tuple[Gap, ...] = ()
    devices: dict[int, str] = field(default_factory=dict)


def parse_command(command: str, knowledge: Knowledge, names: Collection[str] = ()
                  ) -> list[Step]:
    """Read a command into steps (the steps of `read_command`).

    Args:
        command: the natural-language command.
        knowledge: the lexicon tables.
        names: lower-case names and ids of the scene's people and objects.

    Returns:
        The steps in command order (conditions attached, not separate steps).
    """
    return list(read_command(command, knowledge, names).steps)


def _strip_openers(words: list[str]) -> list[str]:
    """Drop what opens a clause before its verb: fillers ("oi robot, could you maybe") and stray
    punctuation, however they are stacked."""
    while True:
        before = len(words)
        words, _ = strip_leading(words, LEADING_FILLER)
        while words and not any(c.isalnum() for c in words[0]):
            words = words[1:]
        if len(words) == before:
            return words


def read_command(command: str, knowledge: Knowledge, names: Collection[str] = (),
                 language: Language | None = None) -> ParsedCommand:
    """Read a command into steps, temporal facts, implied devices and comprehension gaps.

    Args:
        command: the natural-language command.
        knowledge: the lexicon tables.
        names: lower-case names and ids of the scene's people and objects.
        language: the idiom tables (default: the packaged `language.json`).

    Returns:
        The `ParsedCommand`.
    """
    language = language or load_language()
    text = normalize(command)
    # A capitalised word no dictionary knows ("Tomas", "Calpol") is a name, not a mystery.
    names = {*names, *(w.lower() for w in _CAPITALISED.findall(command)
                       if not language.is_english(w.lower()))}
    steps: list[Step] = []
    words_by_step: list[tuple[str, ...]] = []
    chained: list[int] = []
    repeated = False
    pending_condition: str | None = None
    for clause in split_clauses(text, knowledge):
        words = _strip_openers(clause.split())
        words = _strip_time(words)
        words, condition_word = strip_leading(words, CONDITIONS)
        if condition_word and len(words) > 1 and words[0] in _TIME_NOUNS and verb_at(
                words[1:], knowledge):
            # "after dinner clear the tray": the condition is two words, the rest a step.
            pending_condition, words = f"{condition_word} {words[0]}", words[1:]
            condition_word = None
        if (condition_word and verb_at(words, knowledge) is None) or (
                condition_word and words[:1] and words[0] in knowledge.role_words):
            condition = f"{condition_word} {' '.join(words)}"
            if steps and steps[-1].condition is None and not pending_condition:
                steps[-1] = dataclasses.replace(steps[-1], condition=condition)
            else:
                pending_condition = condition
            continue
        words, negation = strip_leading(words, NEGATIONS)
        words, _ = strip_leading(words, LEADING_FILLER)
        while len(words) > 1 and words[0].endswith("ly") and verb_at(words, knowledge) is None:
            words = words[1:]  # a leading adverb ("secretly", "carefully") before the verb
        plain = rewrite(_strip_manner(words, knowledge), language, knowledge)
        repeated = repeated or plain.repeated
        for part in plain.clauses:
            if plain.robot_goes:
                chained.append(len(steps))
            steps.append(parse_clause(len(steps), clause, list(part), knowledge, names,
                                      negated=negation is not None,
                                      condition=pending_condition))
            words_by_step.append(part)
            pending_condition = None
    facts = command_facts(text, steps, language, chained=chained, repeated=repeated)
    return ParsedCommand(
        steps=tuple(steps), facts=facts, text=text,
        not_understood=find_gaps(steps, words_by_step, knowledge, language, names),
        devices=_implied_devices(steps, knowledge, language))


def _implied_devices(steps: list[Step], knowledge: Knowledge, language: Language
                     ) -> dict[int, str]:
    """Step index -> the device its verb implies ("boil the eggs" -> hob) if none is named."""
    devices: dict[int, str] = {}
    for step in steps:
        if step.verb is None or step.negated or step.destination or step.instrument:
            continue
        for rule in language.devices:
            if step.verb not in rule.verbs:
                continue
            concepts = {o.concept for o in step.objects} | {o.head for o in step.objects}
            if rule.for_objects and not concepts & rule.for_objects:
                continue
            if any(o.head == rule.device or o.concept == knowledge.noun_concept(rule.device)
                   for o in step.objects):
                continue  # "preheat the oven": the device is the object itself
            devices[step.index] = rule.device
            break
    return devices


def _strip_time(words: list[str]) -> list[str]:
    """Drop a leading time phrase ("at 3am", "tonight"): the facts read it from the text."""
    while words:
        if words[0] in _LEADING_TIMES and len(words) > 1:
            words = words[1:]
        elif words[0] == "at" and len(words) > 2 and (
                words[1][:1].isdigit() or words[1] in _TIME_NOUNS | {"night"}):
            words = words[3:] if words[2] in _CLOCK_WORDS else words[2:]
        else:
            return words
    return words


def _strip_manner(words: list[str], knowledge: Knowledge) -> list[str]:
    """Drop manner phrases ("at top speed", "as fast as you can") after the verb.

    They are cues the rules read from the whole text; left in, they would be read as objects.
    """
    text = f" {' '.join(words[1:])} "
    for phrase in _manner_phrases(knowledge):
        text = text.replace(f" {phrase} ", " ")
    return [*words[:1], *text.split()]


@lru_cache(maxsize=16)
def _manner_phrases(knowledge: Knowledge) -> tuple[str, ...]:
    """The manner cues, gathered once per `Knowledge` instead of on every clause."""
    phrases = {p for name in ("hurry", "max_speed", "careful")
               for p in knowledge.cues.get(name, ()) if " " in p or p.endswith("ly")}
    # Longest first; equal lengths alphabetically, so the order never follows a set's.
    return tuple(sorted(phrases, key=lambda p: (-len(p), p)))
