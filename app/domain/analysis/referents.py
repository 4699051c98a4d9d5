"""What a phrase of a command names: the `Referent` (ids of objects, people or a room, or
candidates when several fit) and the `Gap` for words that name nothing. Shared by the grounding
of things and of people. Fails: never.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from app.domain.analysis.phrases import NounPhrase
from app.domain.world.concepts import singular

USER_ID = "user"
GENERIC_WORDS = frozenset({"the", "a", "object", "thing", "person", "room", "on", "off", "it",
                           "is"})
_SPLIT = re.compile(r"[^a-z0-9]+")
MAX_GROUP = 6


@dataclass(frozen=True, slots=True)
class Referent:
    """What a phrase names: `ids` chosen; `candidates` when several fit and differ."""

    phrase: NounPhrase
    kind: str  # object | person | room | substance | none
    ids: tuple[str, ...] = ()
    candidates: tuple[str, ...] = ()
    new: bool = False
    substance: str | None = None

    @property
    def id(self) -> str | None:
        return self.ids[0] if self.ids else None


@dataclass(frozen=True, slots=True)
class Gap:
    """Words the reader could not map: quoted back in the comprehension question."""

    words: str
    why: str


def words_of(*texts: str | None) -> set[str]:
    found: set[str] = set()
    for text in texts:
        if text:
            found |= {w for w in _SPLIT.split(text.lower().replace("_", " ")) if w}
            found |= {singular(w) for w in found}
    return found
