"""What the words for people imply: the age group a role names ("toddler", "grandma", "dad").

In: a person's role or name as a scene gives it. Out: `implied_age_group(role, name)` -> one of
the spec's age groups when the word itself implies it, else None ("daughter", "guest" and
"friend" imply no age). The table (`data/people.json`) also gives gender for pronouns.
Fails: never.
"""

from __future__ import annotations

import json
import re
from functools import cache
from pathlib import Path
from typing import Any

_DATA = Path(__file__).with_name("data") / "people.json"
_NON_WORD = re.compile(r"[^a-z' ]+")


@cache
def people_table() -> dict[str, Any]:
    """The raw people table: roles with their words, gender words, state words."""
    table: dict[str, Any] = json.loads(_DATA.read_text())
    return table


@cache
def _ages() -> dict[str, str]:
    return {word: row["age_group"] for row in people_table()["roles"].values()
            if row.get("age_group") for word in row["words"]}


def implied_age_group(*words: str | None) -> str | None:
    """The age group the first word that implies one names, else None.

    Args:
        words: a role, a name... (any may be None).

    Returns:
        `infant`, `child`, `teen`, `adult` or `older_adult`, or None.
    """
    ages = _ages()
    for word in words:
        if not word:
            continue
        key = " ".join(_NON_WORD.sub(" ", word.lower().replace("_", " ")).split())
        if key in ages:
            return ages[key]
        for part in key.split():
            if part in ages and part not in ("one", "ones"):
                return ages[part]
    return None
