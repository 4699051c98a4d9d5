"""Stage 1, step 1 (read): how long the command leaves its result standing by itself.

In: the command. Out: the hours the result stands unattended ("leave it on overnight": about ten;
"prop the fridge open for the afternoon": about four; "all weekend": two days), or None when
the command says nothing of time. The plan ends with a `Wait` of that length, so templates can
tell "leave the iron on while I grab a shirt" from "leave it on till the morning" by the
world's `hours_waited(robot)`. Fails: never.
"""

from __future__ import annotations

import re

_NUMBERS = {"a": 1.0, "an": 1.0, "one": 1.0, "two": 2.0, "three": 3.0, "four": 4.0,
            "five": 5.0, "six": 6.0, "few": 3.0, "couple": 2.0, "half": 0.5}

# Phrases of a stretch of time, longest first within each length.
_SPANS: tuple[tuple[re.Pattern[str], float], ...] = tuple(
    (re.compile(pattern), hours) for pattern, hours in (
        (r"\b(?:all|the whole|for the|over the) (?:weekend|week|holiday|holidays|fortnight)\b"
         r"|\bfor (?:days|the week|a week|a few days)\b|\bwhile (?:we're|we are|i'm|i am) "
         r"(?:away|on holiday)\b", 48.0),
        (r"\b(?:overnight|all night|through the night|(?:till|until|by|for) (?:the )?morning"
         r"|while (?:i|we|he|she|they|everyone|everybody|the \w+) (?:sleeps?|(?:is|are|'re|'s)"
         r" (?:asleep|sleeping|in bed)))\b", 10.0),
        (r"\b(?:all|the whole|for the) (?:day|afternoon|morning|evening)\b|\bfor hours\b"
         r"|\bwhile (?:we're|we are|i'm|i am) at (?:the )?(?:beach|work|office|match|"
         r"cinema|shops|park|airport)\b", 5.0),
    ))
_COUNTED = re.compile(r"\b(?:for|be|about|only be|back in) (a|an|one|two|three|four|five|six|"
                      r"few|couple|half|\d+(?:\.\d+)?)(?: of)? (hours?|hrs?|minutes?|mins?)\b")


_SLEEPERS = re.compile(r"\bwhile (i|we|everyone|everybody)(?:'m|'re| am| are| is)? "
                       r"(?:sleep|sleeps|asleep|sleeping|in bed)\b")


def who_sleeps(command: str) -> str | None:
    """ "leave it burning while we sleep": who the command says is asleep meanwhile ("i" for
    the speaker, "we" for the household), or None."""
    found = _SLEEPERS.search(command.lower().replace("\u2019", "'"))
    if found is None:
        return None
    return "i" if found.group(1) == "i" else "we"


def hours_left_standing(command: str) -> float | None:
    """The hours the command leaves its result standing by itself (see the module docstring).

    Args:
        command: the command as the caller wrote it.

    Returns:
        Hours, or None when the command names no stretch of time.
    """
    text = command.lower().replace("\u2019", "'")
    for pattern, hours in _SPANS:
        if pattern.search(text):
            return hours
    counted = _COUNTED.search(text)
    if counted is None:
        return None
    amount, unit = counted.groups()
    value = _NUMBERS[amount] if amount in _NUMBERS else float(amount)
    return value if unit.startswith("h") else value / 60
