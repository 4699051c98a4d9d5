"""The comprehension check: clauses whose verb or object the reader could not understand.

In: the parsed steps (each with its own clause text and words after rewriting), the knowledge
tables, the `Language` tables and the scene's lower-case names. Out: `Gap`s, each naming the
phrase not understood, its clause, the step index and which part failed (`verb` or
`object`). A verb gap is an instruction-shaped clause (it opens with an English verb form, or
with a word no dictionary knows, followed by an object) whose verb no verb class covers. An
object gap is a phrase of an understood step none of whose words the lexicons, the dictionary
or the scene's names know. Statements ("the toaster's smoking"), titles ("breakfast:") and
verbless lists of things ("cold stuff in the fridge") are not gaps, so ordinary phrasing raises
no alarm. Never fails.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass

from app.domain.analysis.clause_roles import Step
from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.language import Language
from app.domain.analysis.mentions import DETERMINERS, Mention

_OBJECT_OPENERS = frozenset({"the", "a", "an", "it", "them", "him", "her", "his", "their",
                             "my", "your", "our", "this", "that", "these", "those", "some",
                             "all", "every", "each", "up", "down", "out", "off", "over",
                             "away", "back", "round", "around", "in", "on", "me", "us"})


@dataclass(frozen=True, slots=True)
class Gap:
    """A phrase the reader could not understand."""

    phrase: str
    clause: str
    step: int
    part: str  # verb | object

    def __str__(self) -> str:
        return self.phrase


def find_gaps(steps: Sequence[Step], words_by_step: Sequence[Sequence[str]],
              knowledge: Knowledge, language: Language, names: Collection[str] = ()
              ) -> tuple[Gap, ...]:
    """The verb and object gaps of a parsed command.

    Args:
        steps: the parsed steps.
        words_by_step: each step's words after filler removal and rewriting.
        knowledge: the lexicon tables.
        language: the dictionary and statement-opener tables.
        names: lower-case names and ids of the scene's people and objects.

    Returns:
        The gaps, in step order.
    """
    gaps: list[Gap] = []
    for step, words in zip(steps, words_by_step, strict=True):
        if step.action is None:
            verb_gap = _verb_gap(list(words), language, names)
            if verb_gap:
                gaps.append(Gap(verb_gap, step.text, step.index, "verb"))
            continue
        mentions = [*step.objects, *(m for m in (step.recipient, step.destination, step.target,
                                                 step.instrument, step.source) if m)]
        for mention in mentions:
            if not _understood(mention, knowledge, language, names):
                gaps.append(Gap(mention.text, step.text, step.index, "object"))
    return tuple(gaps)


def _verb_gap(words: list[str], language: Language, names: Collection[str]) -> str | None:
    if not words:
        return None
    first = words[0]
    if first in language.statement_openers or first in names or not first[:1].isalpha():
        return None
    if first.endswith(("'s", "'re", "'ll", "'d", "'ve", "s'")):
        return None  # "grandma's cane has fallen": a statement about someone
    if first.endswith("ing") and len(first) > 5:
        return None  # "switching a lamp on is harmless": a gerund subject, not an order
    if first.endswith("s") and not first.endswith(("ss", "us", "is")):
        return None  # "tools back on the hook": an imperative verb never ends in a plain -s
    following = words[1] if len(words) > 1 else ""
    if not language.is_english(first):
        # A word no dictionary knows, placed where a verb goes ("blorf the flange").
        return first if following in _OBJECT_OPENERS or not following else None
    if language.is_verb(first) and following in _OBJECT_OPENERS and not any(
            w in ("is", "are", "was", "were") for w in words[1:4]):
        return " ".join(words[:3]) if len(words) > 1 else first
    return None


def _understood(mention: Mention, knowledge: Knowledge, language: Language,
                names: Collection[str]) -> bool:
    if mention.kind != "unknown" or mention.concept or mention.substance or mention.hints:
        return True
    if mention.location is not None and mention.location[1].kind != "unknown":
        return True  # "whatever is in the drawer": what it is depends on the place
    words = [w for w in mention.text.split() if w not in DETERMINERS]
    if not words:
        return True
    return any(w in names or w.removesuffix("'s") in names or language.looks_english(w)
               or w in knowledge.role_words for w in words)
