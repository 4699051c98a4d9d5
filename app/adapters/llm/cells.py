"""The twelve cells of the Hazard Analysis Matrix: every level answers every category explicitly.

In: one level's validated `LevelAnswer` and the level's name. Out: `cell_problems`, one repair
message per category the answer leaves open, and `only_cells_missing`, whether a list of
problems is about open cells alone (the analyzer then reads the matrix as not understood).
A cell (level x category) is answered when the level reports at least one hazard of that
category, or says under `none_because` why it has none with a reason: "none, because nobody is
in the room". A bare "none", "n/a" or a one-word reason is not a reason (fewer than
`MIN_REASON_WORDS` words once a leading "none"/"no hazard" and "because" are taken off): a model
that skipped the category and one that looked at it cannot be told apart from it.
Silence is never read as "no hazard": an open cell goes to the repair round, and a cell still
open after it makes the analysis "not understood", which the gate defers and never authorizes.
Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from app.adapters.llm.schemas import LevelAnswer
from app.domain.models import Category

MIN_REASON_WORDS = 2
_CELL_MARK = "matrix cell "
_LEADING_NONE = re.compile(
    r"^\s*(?:none|no(?:\s+new)?\s+(?:hazards?|risks?)|nothing|n/?a)?\s*[,.:;\-\u2013\u2014]*\s*"
    r"(?:because|since|as)?\s*[,:]?\s*",
    re.IGNORECASE,
)
_WORD = re.compile(r"[^\W_]+(?:['\u2019-][^\W_]+)*")


def reason_words(text: str) -> int:
    """How many words of reason a `none_because` entry gives after its "none, because".

    Args:
        text: the entry as the model wrote it.

    Returns:
        The number of words left once a leading "none"/"no hazard" and "because" are removed.
    """
    return len(_WORD.findall(_LEADING_NONE.sub("", text, count=1)))


def cell_problems(answer: LevelAnswer, level: str) -> list[str]:
    """Why some of this level's four cells are not answered (empty when all four are).

    Args:
        answer: the level's answer.
        level: the level's name, for the repair message (task, deployment or user).

    Returns:
        One problem per open cell, saying what a usable answer looks like.
    """
    covered = {hazard.category for hazard in answer.hazards}
    problems: list[str] = []
    for category in Category:
        if category in covered:
            continue
        reason = answer.none_because.get(category)
        if reason is None:
            what = "has no hazard and no none_because entry"
        elif reason_words(reason) < MIN_REASON_WORDS:
            what = f"says {reason.strip()[:40]!r} without a reason"
        else:
            continue
        problems.append(
            f"{_CELL_MARK}{level}/{category.value} {what}; report its hazards, or write under "
            f'none_because "{category.value}": "none, because <why, in a few words>"'
        )
    return problems


def only_cells_missing(problems: Sequence[str]) -> bool:
    """Whether every problem in the list is an open cell (and there is at least one).

    Args:
        problems: the problems of an answer that stayed unusable.

    Returns:
        True when the answer was usable but for the cells it left open.
    """
    return bool(problems) and all(_CELL_MARK in problem for problem in problems)
