"""Noun phrases: the words a clause uses for what it acts on, read into their parts.

In: the words of one argument of a clause ("grandpa's big red mug of tea", "it", "all the
glasses"). Out: a `NounPhrase`: its head noun, modifiers, possessor, the contents an "X of Y"
phrase names, a quantity, and whether it is a pronoun. `split_conjoined` splits "the plates and
the cups" into two phrases. Fails: never; words it cannot place stay modifiers.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.domain.analysis.lexicon import Lexicon
from app.domain.world.concepts import singular

OBJECT_PRONOUNS = frozenset({"it", "them", "this", "that", "these", "those", "one", "ones",
                             "everything", "something", "anything", "stuff", "things", "what",
                             "what's", "whatever", "whats", "there", "here"})
PERSON_PRONOUNS = frozenset({"me", "him", "her", "us", "you", "them", "myself", "himself",
                             "herself", "yourself", "everyone", "everybody", "someone",
                             "somebody", "anyone", "anybody", "nobody", "people"})
# A title before a name marks a person even when the scene does not list the name.
TITLES = {"mr": "male", "mrs": "female", "ms": "female", "miss": "female", "mx": None,
          "dr": None, "prof": None, "sir": "male", "madam": "female"}
POSSESSIVES = {"my": "me", "his": "him", "her": "her", "their": "them", "our": "us",
               "your": "you"}
_TRAILING = frozenset({"downstairs", "upstairs", "here", "there", "now", "too", "again",
                       "everywhere", "anyway", "outside", "inside", "please", "today",
                       "tonight", "first", "properly", "quickly", "later", "instead",
                       "quiet", "quietly", "silently", "softly", "slowly", "gently",
                       "straight", "directly"})
_PARTS = frozenset({"end", "side", "edge", "middle", "corner", "back", "front", "bottom", "rest",
                    "top", "half", "centre", "center", "inside", "outside", "surface", "remainder"})
# "a glass of water": the container holds the substance; "a slice of cake": the part is food.
_PARTITIVES = frozenset({"slice", "slices", "piece", "pieces", "bit", "bits", "spoon", "spoonful",
                         "handful", "pinch", "drop", "drops", "portion", "serving", "helping",
                         "bite", "chunk", "chunks", "lump", "sip", "dash", "splash", "bunch",
                         "pair", "couple", "lot", "lots", "box", "bag", "packet", "pack"})


@dataclass(frozen=True, slots=True)
class NounPhrase:
    """One argument of a clause as written."""

    text: str
    head: str = ""
    modifiers: tuple[str, ...] = ()
    possessor: str | None = None
    contents: str | None = None
    quantity: float | None = None
    every: bool = False
    pronoun: str | None = None

    @property
    def words(self) -> tuple[str, ...]:
        """Modifiers and head, in order: what grounding matches against names and types."""
        return (*self.modifiers, self.head) if self.head else self.modifiers

    @property
    def phrase(self) -> str:
        """Modifiers and head as one string ("big red mug")."""
        return " ".join(self.words)


def _strip_determiners(words: list[str], lexicon: Lexicon) -> tuple[list[str], float | None,
                                                                     bool, str | None]:
    quantity: float | None = None
    every = False
    possessor: str | None = None
    changed = True
    while words and changed:
        changed = False
        for phrase in lexicon.determiners:
            if tuple(words[: len(phrase)]) == phrase:
                if phrase[0] in ("all", "every", "each", "both") or "all" in phrase:
                    every = True
                if phrase[0] in POSSESSIVES and len(phrase) == 1:
                    possessor = POSSESSIVES[phrase[0]]
                words = words[len(phrase):]
                changed = True
                break
        if words and words[0] in lexicon.numbers and len(words) > 1:
            quantity = lexicon.numbers[words[0]]
            words = words[1:]
            changed = True
        elif words and words[0].isdigit() and len(words) > 1:
            quantity = float(words[0])
            words = words[1:]
            changed = True
    return words, quantity, every, possessor


_QUANTIFIERS = frozenset({"some", "any", "all", "both", "each", "few", "a", "couple", "several",
                          "most", "none", "one", "many", "lots", "plenty", "more", "rest"})
_ROUGHLY = {"couple": 2.0, "few": 3.0, "several": 3.0}
_TIME_OWNERS = frozenset({"today", "tonight", "yesterday", "tomorrow", "week", "weekend", "month",
                          "year", "monday", "tuesday", "wednesday", "thursday", "friday",
                          "saturday", "sunday", "last", "next", "this"})
_TIME_UNITS = frozenset({"minute", "minutes", "min", "mins", "hour", "hours", "second",
                        "seconds", "day", "days", "night", "nights", "morning", "evening",
                        "week", "weeks", "while", "time"})


_A_MOMENT = frozenset({"sec", "second", "secs", "seconds", "min", "minute", "mo", "moment",
                       "tick", "jiffy", "bit", "while"})


def _without_time(words: list[str]) -> list[str]:
    """ "her every ten minutes" -> "her", "the front burner a sec" -> "the front burner": how
    often or how long is no part of what is named."""
    if len(words) > 2 and words[-2] == "a" and words[-1] in _A_MOMENT and \
            words[-3] not in OBJECT_PRONOUNS:  # "give it a minute" is a wait
        words = words[:-2]
    for index, word in enumerate(words[1:], 1):
        if word in ("every", "each", "for", "until", "till") and any(
                w in _TIME_UNITS for w in words[index + 1: index + 4]):
            return words[:index]
        if word in ("overnight", "tonight", "today", "tomorrow"):
            return words[:index]
    return words


_RELATIVE = frozenset({"that", "which", "who", "whom", "whose", "should", "will", "must",
                       "might"})


def _without_relative(words: list[str], lexicon: Lexicon) -> list[str]:
    """ "the box that came this morning" -> "the box", "the microwave should do it" -> "the
    microwave": a relative clause or a predicate after a thing's noun says something of the
    thing, and its words are no part of the thing's name."""
    for index, word in enumerate(words[1:], 1):
        after = words[index + 1] if index + 1 < len(words) else None
        if not lexicon.is_thing(singular(words[index - 1])):
            continue
        if word in _RELATIVE and after is not None:
            return words[:index]
        if word.endswith("ing") and lexicon.is_verb(word) and (
                after is None or not lexicon.is_thing(singular(after))):
            return words[:index]  # "the stew ticking over": the stew (not "the roasting tin")
    return words


# Words before "'s" that make a contraction, not an owner ("it's", "that's", "what's").
_NOT_OWNERS = frozenset({"it", "that", "this", "there", "here", "what", "who", "where", "he",
                         "she", "let", "one", "everyone", "everything", "nobody", "somebody",
                         "someone", "today", "tomorrow", "tonight", "yesterday"})


def _owner(word: str, lexicon: Lexicon) -> bool:
    """Whether "<word>'s" ending a phrase names an owner ("mum's") rather than a thing that
    is something ("the door's locked", "dinner's ready")."""
    return word not in _NOT_OWNERS and (word in lexicon.people or not lexicon.is_thing(word))


def parse_phrase(words: list[str], lexicon: Lexicon) -> NounPhrase | None:
    """Read one noun phrase.

    Args:
        words: the phrase's lower-case words, punctuation removed, apostrophes kept.
        lexicon: the reader's vocabulary.

    Returns:
        The phrase, or None for an empty one.
    """
    text = " ".join(words)
    words = _without_relative(_without_time(words), lexicon)
    while len(words) > 1 and words[-1] in _TRAILING:
        words = words[:-1]
        if len(words) > 1 and words[-1] in ("real", "really", "very", "nice", "and"):
            words = words[:-1]  # "real quiet", "nice and slowly"
    if len(words) == 2 and words[1] == "else" and words[0] in OBJECT_PRONOUNS | {
            "everything", "anything", "something"}:
        words = words[:1]  # "everything else": the rest of what was named
    if not words:
        return None
    if len(words) == 1 and (words[0] in OBJECT_PRONOUNS or words[0] in PERSON_PRONOUNS):
        return NounPhrase(text, pronoun=words[0])
    words, quantity, every, possessor = _strip_determiners(list(words), lexicon)
    contents: str | None = None
    if "of" in words:
        at = words.index("of")
        before, after = words[:at], words[at + 1:]
        after, _, more, _ = _strip_determiners(after, lexicon)
        every = every or more
        if before and all(w in lexicon.numbers or w.isdigit() or w in _QUANTIFIERS
                          for w in before):
            words = after  # "two of grandad's pills", "some of the cake": the pills, the cake
            if before[-1] in lexicon.numbers:
                quantity = lexicon.numbers[before[-1]]
            elif before[-1] in _ROUGHLY:
                quantity = _ROUGHLY[before[-1]]  # "a couple of biscuits": a counted handful
        elif before and after and (before[-1] in _PARTITIVES or before[-1] in _PARTS
                                   or singular(before[-1]) in lexicon.measures
                                   or not lexicon.is_thing(before[-1])):
            # "a slice of cake" is cake; "the end of the counter" is the counter; "a stack of
            # boxes" or "a squeeze of lemon" (a measure, not a thing) is the boxes, the lemon.
            words = after
        elif before and after:
            words, contents = before, " ".join(after)  # "a glass of water"
        else:
            words = before or after
    if words and words[-1].endswith("'s") and _owner(words[-1][:-2], lexicon) and not any(
            w.endswith("'s") for w in words[:-1]):
        # "a couple of mum's", "use Grandma's instead": the owner's one of what was named
        return NounPhrase(text, possessor=words[-1][:-2], contents=contents, quantity=quantity,
                          every=every, pronoun="one")
    for index, word in enumerate(words):
        if word.endswith(("'s", "s'")) and index < len(words) - 1:
            owner = word[:-2] if word.endswith("'s") else word[:-1]
            if owner not in _TIME_UNITS and owner not in _TIME_OWNERS:
                possessor = owner  # "today's post" belongs to nobody
            words = words[index + 1:]
            break
    words = [w for w in words if w not in ("the", "a", "an")]
    if not words:
        return NounPhrase(text, possessor=possessor, contents=contents, quantity=quantity,
                          every=every, pronoun="one")
    if len(words) == 1 and words[0] in OBJECT_PRONOUNS:
        return NounPhrase(text, possessor=possessor, contents=contents, quantity=quantity,
                          every=every, pronoun=words[0])
    return NounPhrase(text, head=words[-1], modifiers=tuple(words[:-1]), possessor=possessor,
                      contents=contents, quantity=quantity, every=every)


def split_conjoined(words: list[str]) -> list[list[str]]:
    """Split "the plates, the cups and the forks" into its phrases (never inside "X of Y")."""
    parts: list[list[str]] = [[]]
    for word in words:
        if word in ("and", "&", "plus", "or", ",") and parts[-1]:
            parts.append([])
        elif word != ",":
            parts[-1].append(word)
    return [p for p in parts if p]


# "a 40 degree cycle", "the eco programme": a run of a washing machine or dishwasher.
TIME_UNITS = frozenset({"second", "seconds", "sec", "secs", "minute", "minutes", "min", "mins",
                        "hour", "hours", "hr", "hrs"})
"""Words for a length of time ("for two minutes", ", 3 mins"): how long, never a place."""
PROGRAM_NOUNS = frozenset({"cycle", "programme", "program", "wash", "setting", "mode"})

BODY_PARTS = frozenset({
    "arm", "arms", "hand", "hands", "elbow", "wrist", "shoulder", "shoulders", "leg", "legs",
    "foot", "feet", "knee", "knees", "head", "face", "neck", "back", "waist", "hip", "hips",
    "finger", "fingers", "ankle", "ankles", "body", "chest", "hair", "cheek", "ear", "ears"})
"""Body parts: "her arm" names the person, touched, never a thing to fetch."""
