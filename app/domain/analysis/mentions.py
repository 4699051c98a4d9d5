"""Noun phrases of a command: what a phrase names, before it is matched to the scene.

In: a noun-phrase string ("grandma's pills", "the big knife", "a glass of wine", "her") and the
knowledge tables. Out: a `Mention` with its head word, what kind of thing the head names
(object concept, substance, person role, room, pronoun, proper name or unknown), modifiers,
owner and contents. Never fails: a phrase nothing recognises becomes an `unknown` mention whose
head is its last word, so grounding can still try the scene's own names and types.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, field

from app.domain.analysis.knowledge_base import Knowledge, singular

DETERMINERS = frozenset({
    "the", "a", "an", "some", "any", "this", "that", "these", "those", "all", "every", "each",
    "both", "another", "other", "more", "two", "three", "few", "several", "of", "whole",
    "right", "straight", "just",
})
POSSESSIVES = {"my": "me", "our": "me", "his": "him", "her": "her", "their": "them",
               "your": "you", "its": "it"}
PERSON_PRONOUNS = frozenset({"me", "him", "her", "them", "us", "myself", "i", "we", "you",
                             "everyone", "everybody", "anyone", "anybody", "someone", "somebody",
                             "whoever", "whomever"})
OBJECT_PRONOUNS = frozenset({"it", "them", "this", "that", "these", "those", "one"})
# Words for a set of people born together: who they are depends on the scene, not the word.
_GROUP_WORDS = frozenset({"twin", "triplet", "quadruplet"})
_QUANTITY_HEADS = frozenset({"one", "ones", "rest", "pair", "bunch", "piece", "pieces", "some",
                             "all", "half", "handful", "bit", "couple", "lot", "lots", "set",
                             "sip", "sips", "spoon", "spoonful", "spoonfuls", "teaspoon",
                             "teaspoons", "tablespoon", "mouthful", "bite", "bites", "taste",
                             "drop", "drops", "dose", "doses", "dash", "splash", "capful",
                             "swig", "gulp", "dram", "shot", "measure", "dollop", "pinch",
                             "scoop", "slice", "slices", "wedge", "chunk", "square", "few"})


@dataclass(frozen=True, slots=True)
class Mention:
    """One noun phrase as the command words it."""

    text: str
    head: str
    kind: str  # object | person | room | pronoun | name | unknown
    concept: str | None = None
    substance: str | None = None
    role: str | None = None
    role_word: str | None = None
    room: str | None = None
    modifiers: tuple[str, ...] = ()
    owner: str | None = None
    contents: str | None = None
    location: tuple[str, Mention] | None = None
    hints: tuple[str, ...] = field(default=())

    @property
    def words(self) -> str:
        """Every word of the phrase, space-joined, for cue and property-word checks."""
        return " ".join((*self.modifiers, self.head))


def _matches(tokens: list[str], knowledge: Knowledge, names: Collection[str]
             ) -> list[tuple[int, int, str, str]]:
    """(start, end, kind, phrase) for every lexicon phrase, longest first at each position."""
    found: list[tuple[int, int, str, str]] = []
    index = 0
    while index < len(tokens):
        hit = None
        for length in range(min(knowledge.max_phrase_words, len(tokens) - index), 0, -1):
            phrase = " ".join(tokens[index:index + length])
            kind = _kind_of(phrase, knowledge, names, single=length == 1)
            if kind:
                hit = (index, index + length, kind, phrase)
                break
        if hit:
            found.append(hit)
            index = hit[1]
        else:
            index += 1
    return found


def _kind_of(phrase: str, knowledge: Knowledge, names: Collection[str], *, single: bool
             ) -> str | None:
    if phrase in names:
        return "name"
    if single and (phrase in PERSON_PRONOUNS or phrase in OBJECT_PRONOUNS):
        return "pronoun"
    if phrase in knowledge.role_words or singular(phrase) in _GROUP_WORDS:
        return "person"
    if phrase in knowledge.room_words:
        return "room"
    if knowledge.substance_of(phrase):
        return "substance"
    if phrase in knowledge.concept_words or singular(phrase) in knowledge.concept_words:
        return "object"
    if phrase in knowledge.wordnet_words or singular(phrase) in knowledge.wordnet_words:
        return "object"
    return None


def parse_mention(text: str, knowledge: Knowledge, names: Collection[str] = ()) -> Mention:
    """Read one noun phrase.

    Args:
        text: the phrase, lower case, without the verb or the preposition before it.
        knowledge: the lexicon tables.
        names: lower-case proper names and ids of the scene's people and objects.

    Returns:
        The `Mention`; `kind` is `unknown` when no word is recognised.
    """
    tokens = text.split()
    owner: str | None = None
    for position, token in enumerate(tokens):
        if token.endswith(("'s", "s'")) and position < len(tokens) - 1:
            owner_tokens = [t for t in tokens[:position] if t not in DETERMINERS]
            owner = " ".join([*owner_tokens, token[:-2] if token.endswith("'s") else token[:-1]])
            tokens = tokens[position + 1:]
            break
    if tokens and tokens[0] in POSSESSIVES and len(tokens) > 1:
        owner = POSSESSIVES[tokens[0]]
        tokens = tokens[1:]
    contents: str | None = None
    if "of" in tokens[1:]:
        cut = tokens.index("of", 1)
        left, right = tokens[:cut], tokens[cut + 1:]
        left_core = [t for t in left if t not in DETERMINERS]
        if not left_core or left_core[-1] in _QUANTITY_HEADS:
            tokens = right
        elif right:
            tokens, contents = left, " ".join(t for t in right if t not in DETERMINERS)
            if contents in knowledge.room_words:
                place = parse_mention(contents, knowledge, names)
                inner = parse_mention(" ".join(left), knowledge, names)
                return with_location(inner, "in", place)
    tokens = [t for t in tokens if t not in DETERMINERS] or tokens[-1:]
    if not tokens:
        return Mention(text=text, head=text, kind="unknown", owner=owner)
    matches = _matches(tokens, knowledge, names)
    if not matches:
        head = tokens[-1]
        concept = knowledge.noun_concept(head)
        return Mention(text=text, head=head, kind="object" if concept else "unknown",
                       concept=concept, modifiers=tuple(tokens[:-1]), owner=owner,
                       contents=contents, substance=_substance(contents, knowledge))
    start, end, kind, head = matches[-1]
    modifiers = tuple(tokens[:start] + tokens[end:])
    hints = tuple(phrase for _, _, _, phrase in matches[:-1])
    substance = knowledge.substance_of(head) if kind == "substance" else None
    substance = substance or _substance(contents, knowledge) or next(
        (knowledge.substance_of(h) for h in hints if knowledge.substance_of(h)), None)
    concept = knowledge.noun_concept(head) if kind in ("object", "substance") else None
    role = knowledge.role_words.get(head)
    return Mention(
        text=text, head=head,
        kind="object" if kind == "substance" else kind,
        concept=concept, substance=substance,
        role=role.name if role else None, role_word=head if role else None,
        room=knowledge.room_words.get(head), modifiers=modifiers, owner=owner,
        contents=contents, hints=hints,
    )


def _substance(phrase: str | None, knowledge: Knowledge) -> str | None:
    if not phrase:
        return None
    found = knowledge.substance_of(phrase)
    if found:
        return found
    words = phrase.split()
    return knowledge.substance_of(words[-1]) if words else None


def with_location(mention: Mention, prep: str, place: Mention) -> Mention:
    """The same mention narrowed by a place phrase ("the cup" + "on the counter")."""
    return Mention(
        text=f"{mention.text} {prep} {place.text}", head=mention.head, kind=mention.kind,
        concept=mention.concept, substance=mention.substance, role=mention.role,
        role_word=mention.role_word, room=mention.room, modifiers=mention.modifiers,
        owner=mention.owner, contents=mention.contents, location=(prep, place),
        hints=mention.hints,
    )
