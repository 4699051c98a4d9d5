"""Facts about when and with whom a command runs: who leaves, who sleeps, for how long.

In: the normalised command text, its parsed steps, what rewriting noticed (a chained "go and
..." per step, a repeated action) and the `Language` phrase tables. Out: `CommandFacts`, the
structured temporal facts consequential-state rules need: the home empties (`leaves_home`),
the people will be asleep (`people_asleep`), how long things stay unattended
(`unattended_for`), the time of day (`time_of_day`, `clock`), whether the robot moves away or
takes up another job while an earlier step's state persists (`robot_leaves_room`,
`leaves_at_step`), whether a person is left on their own (`person_left_alone`), and whether an
action is repeated (`repeated`). `unattended` is true when any of these leaves the scene without
a watcher. Never fails: a phrase it does not know leaves the fact at its default (False/None),
so rules must treat a missing fact as "not stated", never as "safe".
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache

from app.domain.analysis.clause_roles import Step
from app.domain.analysis.language import Language
from app.domain.analysis.word_filter import may_occur

_CLOCK = re.compile(r"(?<![\w'])(\d{1,2})(?::(\d\d))? ?(am|pm|a\.m\.|p\.m\.|o'clock)(?![\w'])")
_AWAY_ACTIONS = frozenset({"navigate"})
_STAYING_VERBS = frozenset({"stay", "wait", "park", "stand", "hang", "hold", "remain"})
# "lock up" with no object of its own: the house is being secured, so everyone is going.
_LOCK_UP = re.compile(r"(?<![\w'])lock(?:ing)? up(?= *(?:$|[,.;!?]|and |then |before ))")


@dataclass(frozen=True, slots=True)
class CommandFacts:
    """Temporal and attendance facts stated (or clearly implied) by a command."""

    leaves_home: bool = False
    people_asleep: bool = False
    unattended_for: str | None = None
    time_of_day: str | None = None  # night | morning | afternoon | evening
    clock: str | None = None  # "3am", "8 o'clock" as written
    robot_leaves_room: bool = False
    leaves_at_step: int | None = None
    person_left_alone: bool = False
    repeated: bool = False

    @property
    def unattended(self) -> bool:
        """Whether something the command sets up will run with nobody watching it."""
        return (self.leaves_home or self.people_asleep or self.robot_leaves_room
                or self.person_left_alone or self.unattended_for is not None)


def command_facts(text: str, steps: Sequence[Step], language: Language, *,
                  chained: Sequence[int] = (), repeated: bool = False) -> CommandFacts:
    """Read the command's temporal facts.

    Args:
        text: the normalised command text.
        steps: its steps, in order.
        language: the phrase tables.
        chained: indexes of steps whose clause began "go (and) ..." (the robot moves first).
        repeated: whether a clause was an aspect form ("keep telling ...").

    Returns:
        The `CommandFacts`.
    """
    facts = language.facts
    clock_match = _CLOCK.search(text)
    clock = clock_match.group(0) if clock_match else None
    time_of_day = _time_of_day(text, clock_match, language)
    leaves_at = _robot_leaves_at(steps, chained)
    return CommandFacts(
        leaves_home=_any(text, facts["leaves_home"]) or (
            _LOCK_UP.search(text) is not None and not _any(text, facts["asleep"])),
        people_asleep=_any(text, facts["asleep"]) or (
            time_of_day == "night" and clock is not None),
        unattended_for=_first(text, facts["away_duration"]),
        time_of_day=time_of_day,
        clock=clock,
        robot_leaves_room=leaves_at is not None,
        leaves_at_step=leaves_at,
        person_left_alone=_any(text, facts["leave_alone"]) or _leaves_person(steps),
        repeated=repeated or _any(text, facts["repeated"]),
    )


@cache
def _pattern(phrases: tuple[str, ...]) -> re.Pattern[str]:
    """One whole-word alternation for a phrase list (longest first, so it wins a tie)."""
    ordered = sorted(phrases, key=len, reverse=True)
    return re.compile(r"(?<![\w'])(?:" + "|".join(map(re.escape, ordered)) + r")(?![\w'])")


def _first(text: str, phrases: tuple[str, ...]) -> str | None:
    if not phrases or not may_occur(text, phrases):
        return None
    found = _pattern(phrases).search(text)
    return found.group(0) if found else None


def _any(text: str, phrases: tuple[str, ...]) -> bool:
    return _first(text, phrases) is not None


def _time_of_day(text: str, clock: re.Match[str] | None, language: Language) -> str | None:
    if clock is not None:
        hour = int(clock.group(1)) % 12
        suffix = clock.group(3)
        if suffix.startswith("p"):
            hour += 12
        if suffix.startswith("a") or suffix.startswith("p"):
            if hour < 6 or hour >= 21:
                return "night"
            return "morning" if hour < 12 else "afternoon" if hour < 17 else "evening"
    for name, phrases in language.time_words.items():
        if _any(text, phrases):
            return name
    return None


def _robot_leaves_at(steps: Sequence[Step], chained: Sequence[int]) -> int | None:
    """The step whose state is left behind when the robot goes away, or None."""
    for step in steps:
        condition = step.condition or ""
        if condition.startswith(("while you", "while u")) and not step.negated:
            return step.index  # "leave the iron on the shirt while you fetch a hanger"
    for step in steps[1:]:
        moving = (step.action in _AWAY_ACTIONS and (step.verb or "").split()[0] not in
                  _STAYING_VERBS) or step.index in chained
        left = steps[step.index - 1]
        if moving and not step.negated and left.action is not None and not left.negated:
            return left.index
    return None


def _leaves_person(steps: Sequence[Step]) -> bool:
    """"leave grandma in the bath", "leave them to feed themselves": a person left alone."""
    for step in steps:
        if not step.keeps_state or step.negated or step.verb is None:
            continue
        if not step.verb.startswith("leave"):
            continue
        if any(o.kind == "person" or (o.kind == "pronoun" and o.head in (
                "her", "him", "them", "everyone")) for o in step.objects):
            return True
    return False
