"""The command, read into ordered steps: verb class, objects, recipient, destination...

In: the command text, the knowledge tables and the scene's lower-case names. Out: `Step`s in
command order. Clauses split on sentence ends, "then", "after that", and on "and"/commas that
are followed by a new verb; a leading "don't"/"never" marks a step negated; an "if/when/unless
..." clause becomes the condition of the step that follows it (or precedes it). Never fails: a
clause without a known verb gives a step with `action=None` (the rules then see no action).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Collection
from dataclasses import dataclass

from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.mentions import Mention, parse_mention, with_location

_PREPOSITIONS = (
    "in front of", "next to", "on top of", "out of", "away from", "close to", "instead of",
    "into", "inside", "onto", "in", "on", "under", "underneath", "beneath", "behind", "near",
    "beside", "by", "at", "to", "toward", "towards", "for", "with", "from", "through", "past",
    "across", "over", "above", "off", "around", "along", "against", "between", "without",
    "within", "of",
)
_PLACE_PREPS = frozenset({"into", "inside", "onto", "in", "on", "under", "underneath",
                          "beneath", "behind", "near", "beside", "by", "next to", "in front of",
                          "on top of", "against", "over", "close to", "within"})
_CARRYING_DESTINATIONS = frozenset({"to", "into", "onto"})
_CARRYING_ACTIONS = frozenset({"transport", "handover", "serve", "remove", "pick"})
_PLACING_ACTIONS = frozenset({"place", "transport", "pour", "throw", "mix", "remove", "push",
                              "block", "heat", "clean", "handover", "serve"})
_PARTICLES = frozenset({"on", "off", "up", "down", "away", "out", "over", "back", "in", "open"})
_LEADING_FILLER = ("please", "robot", "hey", "ok", "okay", "now", "then", "also", "and", "first",
                   "next", "finally", "afterwards", "after that", "so", "just", "can you",
                   "could you", "would you", "will you", "i want you to", "i need you to",
                   "i'd like you to", "go ahead and", "make sure to", "make sure you",
                   "remember to", "try to", "you should", "you can", "then please", "but")
_NEGATIONS = ("don't", "do not", "dont", "never", "no need to", "do n't", "stop to")
_CONDITIONS = ("if", "when", "once", "unless", "while", "whenever", "in case", "as soon as",
               "before", "after", "until", "since", "because", "so that", "so")
# Words that open a new sentence after a comma (a subject), not another item of a list.
_SUBJECTS = frozenset({"i", "i'll", "i'm", "i've", "i'd", "we", "we'll", "we're", "he", "he's",
                       "she", "she's", "they", "they're", "it's", "everyone's", "everybody's",
                       "nobody's", "no", "there's", "that's", "you'll", "you're"})
_GIVE_IDIOM = frozenset({"give", "do"})
_PERSON_FIRST = frozenset({"me", "him", "her", "them", "us"})


@dataclass(frozen=True, slots=True)
class Step:
    """One action the command asks for, with its phrases still unresolved."""

    index: int
    text: str
    verb: str | None
    action: str | None
    negated: bool = False
    condition: str | None = None
    objects: tuple[Mention, ...] = ()
    recipient: Mention | None = None
    destination: Mention | None = None
    destination_prep: str | None = None
    target: Mention | None = None
    instrument: Mention | None = None
    source: Mention | None = None
    away_from: Mention | None = None
    path: Mention | None = None
    keeps_state: bool = False


def normalize(text: str) -> str:
    """Lower case, plain apostrophes, punctuation as separate tokens, single spaces."""
    text = text.lower().replace("\u2019", "'").replace("\u2018", "'")
    text = re.sub(r"[\"()\[\]{}]", " ", text)
    text = re.sub(r"\s[-\u2013\u2014]+\s", " ; ", f" {text} ")
    text = re.sub(r"([,;.!?:])", r" \1 ", text)
    return " ".join(text.split())


def _strip_leading(words: list[str], phrases: tuple[str, ...]) -> tuple[list[str], str | None]:
    for phrase in sorted(phrases, key=len, reverse=True):
        parts = phrase.split()
        if words[: len(parts)] == parts:
            return words[len(parts):], phrase
    return words, None


def _verb_at(words: list[str], knowledge: Knowledge) -> tuple[str, int, int | None] | None:
    """(verb phrase, words used at the start, index of a separated particle) or None."""
    if not words:
        return None
    first = knowledge.irregular_verbs.get(words[0], words[0])
    lemmas = [first, *words[1:]]
    for length in range(min(4, len(lemmas)), 0, -1):
        phrase = " ".join(lemmas[:length])
        if phrase in knowledge.verb_words:
            best: tuple[str, int, int | None] = (phrase, length, None)
            if length == 1:
                particle = _separated_particle(words, first, knowledge)
                if particle is not None:
                    best = (f"{first} {words[particle]}", 1, particle)
            return best
    particle = _separated_particle(words, first, knowledge)
    if particle is not None:
        return (f"{first} {words[particle]}", 1, particle)
    for suffix, repl in (("ing", ""), ("ing", "e"), ("s", ""), ("es", ""), ("ed", ""), ("d", "")):
        if first.endswith(suffix) and first[: -len(suffix)] + repl in knowledge.verb_words:
            return (first[: -len(suffix)] + repl, 1, None)
    return None


def _separated_particle(words: list[str], verb: str, knowledge: Knowledge) -> int | None:
    for position in range(2, len(words)):
        word = words[position]
        if word in _PARTICLES and f"{verb} {word}" in knowledge.verb_words:
            after = words[position + 1] if position + 1 < len(words) else None
            if after is None or after in ("and", ",", "for", "so", "until", "while", "before",
                                          "after", "when", "if", "again", "now") or any(
                    after == p.split()[0] for p in _PREPOSITIONS):
                return position
    return None


def _is_clause_start(words: list[str], knowledge: Knowledge) -> bool:
    rest, _ = _strip_leading(words, ("then", "also", "please", "just"))
    rest, negation = _strip_leading(rest, _NEGATIONS)
    if negation or _strip_leading(rest, _CONDITIONS)[1]:
        return True
    return _verb_at(rest, knowledge) is not None


def split_clauses(text: str, knowledge: Knowledge) -> list[str]:
    """Split a normalised command into clause strings, in order."""
    words = text.split()
    clauses: list[list[str]] = [[]]
    for position, word in enumerate(words):
        rest = words[position + 1:]
        if word in (".", ";", "!", "?", ":"):
            clauses.append([])
            continue
        if word == "," and clauses[-1] and rest[:1] and rest[0] in _SUBJECTS:
            # ", I'll take it down later" / ", everyone's in bed": a new sentence, not a list.
            clauses.append([])
            continue
        if word == "then" or (word == "after" and rest[:1] == ["that"]):
            clauses.append([])
            continue
        if word == "that" and clauses[-1] == [] and position and words[position - 1] == "after":
            continue
        if word in ("and", ",") and clauses[-1] and _is_clause_start(rest, knowledge):
            clauses.append([])
            continue
        if word in ("if", "unless", "before", "while", "until", "once", "when", "whenever",
                    "because", "so") and clauses[-1]:
            clauses.append([])
        clauses[-1].append(word)
    return [" ".join(c).strip(" ,") for c in clauses if " ".join(c).strip(" ,")]


def _segments(words: list[str]) -> list[tuple[str | None, list[str]]]:
    segments: list[tuple[str | None, list[str]]] = [(None, [])]
    position = 0
    while position < len(words):
        for prep in _PREPOSITIONS:
            parts = prep.split()
            if words[position:position + len(parts)] == parts:
                segments.append((prep, []))
                position += len(parts)
                break
        else:
            segments[-1][1].append(words[position])
            position += 1
    merged: list[tuple[str | None, list[str]]] = []
    for preposition, seg in segments:
        if preposition == "of" and merged and seg:
            merged[-1] = (merged[-1][0], [*merged[-1][1], "of", *seg])
        else:
            merged.append((preposition, seg))
    return merged


def _split_list(words: list[str]) -> list[str]:
    parts: list[str] = []
    current: list[str] = []
    for word in words:
        if word in ("and", ",", "or", "&"):
            if current:
                parts.append(" ".join(current))
            current = []
        else:
            current.append(word)
    if current:
        parts.append(" ".join(current))
    return parts


def _person_like(mention: Mention) -> bool:
    return mention.kind in ("person", "name") or (
        mention.kind == "pronoun" and mention.head in _PERSON_FIRST | {"everyone", "everybody"})


def parse_command(command: str, knowledge: Knowledge, names: Collection[str] = ()
                  ) -> list[Step]:
    """Read a command into steps.

    Args:
        command: the natural-language command.
        knowledge: the lexicon tables.
        names: lower-case names and ids of the scene's people and objects.

    Returns:
        The steps in command order (conditions attached, not separate steps).
    """
    steps: list[Step] = []
    pending_condition: str | None = None
    for clause in split_clauses(normalize(command), knowledge):
        words, _ = _strip_leading(clause.split(), _LEADING_FILLER)
        words, _ = _strip_leading(words, _LEADING_FILLER)
        words, condition_word = _strip_leading(words, _CONDITIONS)
        if (condition_word and _verb_at(words, knowledge) is None) or (
                condition_word and words[:1] and words[0] in knowledge.role_words):
            text = f"{condition_word} {' '.join(words)}"
            if steps and steps[-1].condition is None and not pending_condition:
                steps[-1] = dataclasses.replace(steps[-1], condition=text)
            else:
                pending_condition = text
            continue
        words, negation = _strip_leading(words, _NEGATIONS)
        words, _ = _strip_leading(words, _LEADING_FILLER)
        while len(words) > 1 and words[0].endswith("ly") and _verb_at(words, knowledge) is None:
            words = words[1:]  # a leading adverb ("secretly", "carefully") before the verb
        words = _verb_noun_idiom(words, knowledge)
        step = _parse_clause(len(steps), clause, words, knowledge, names,
                             negated=negation is not None, condition=pending_condition)
        pending_condition = None
        steps.append(step)
    return steps


def _parse_clause(index: int, clause: str, words: list[str], knowledge: Knowledge,
                  names: Collection[str], *, negated: bool, condition: str | None) -> Step:
    found = _verb_at(words, knowledge)
    if found is None:
        # "The toaster's smoking!": no action, but its subject is what a later "it" means.
        subject = _subject_of(words)
        heard = [parse_mention(" ".join(subject), knowledge, names)] if subject else []
        heard += [parse_mention(w.removesuffix("'s"), knowledge, names) for w in words
                  if w.removesuffix("'s") in names or w.removesuffix("'s") in knowledge.role_words]
        return Step(index, clause, None, None, negated=negated, condition=condition,
                    objects=tuple(m for m in heard if m.kind in ("object", "person", "name")))
    verb, used, particle = found
    rest = [w for i, w in enumerate(words[used:], start=used) if i != particle]
    action = knowledge.verb_words[verb]
    keeps = verb.split()[0] in ("leave", "keep") or verb.endswith(" open")

    def mention(tokens: list[str]) -> Mention:
        return parse_mention(" ".join(tokens), knowledge, names)

    segments = _segments(rest)
    objects = [mention(t.split()) for t in _split_list(segments[0][1])]
    recipient: Mention | None = None
    if action in ("handover", "transport", "serve", "pour", "pick", "heat") and segments[0][1]:
        first = segments[0][1]
        lead = _leading_person(first, knowledge, names)
        if first[0] in _PERSON_FIRST and len(first) > 1 and not any(
                p == "to" for p, _ in segments[1:]):
            recipient, objects = mention(first[:1]), [mention(t.split())
                                                      for t in _split_list(first[1:])]
        elif lead and not any(p == "to" for p, _ in segments[1:]):
            # "give Aisha one of the cookies", "take Grandad a whisky": the person comes first.
            recipient = mention(first[:lead])
            objects = [mention(t.split()) for t in _split_list(first[lead:])]
        else:
            cut = next((i for i, w in enumerate(first[1:], 1)
                        if w in ("the", "a", "an", "some", "his", "her", "their", "my")), None)
            if cut:
                head = mention(first[:cut])
                if _person_like(head):
                    recipient = head
                    objects = [mention(t.split()) for t in _split_list(first[cut:])]
    if not objects and any(p == "of" for p, _ in segments[1:]):
        objects = [mention(next(seg for p, seg in segments[1:] if p == "of"))]
    parts: dict[str, Mention] = {}
    destination_prep: str | None = None
    placing = action in _PLACING_ACTIONS
    dest_index = None
    if placing:
        for position in range(len(segments) - 1, 0, -1):
            prep = segments[position][0]
            allowed = (_CARRYING_DESTINATIONS if action in _CARRYING_ACTIONS
                       else _PLACE_PREPS | {"to", "at"} if action in ("place", "block")
                       else _PLACE_PREPS | {"to"})
            if prep in allowed:
                candidate = mention(segments[position][1])
                if prep == "to" and _person_like(candidate):
                    continue
                dest_index = position
                earlier = segments[position - 1][0] if position > 1 else None
                if candidate.kind == "room" and earlier in allowed and prep in ("in", "inside"):
                    # "on the floor in the living room": the room locates the place before it.
                    dest_index = position - 1
                break
    previous: str = "object"
    for position, (prep, tokens) in enumerate(segments[1:], start=1):
        if not tokens or prep is None:
            continue
        phrase = mention(tokens)
        if position == dest_index:
            parts["destination"], destination_prep, previous = phrase, prep, "destination"
        elif prep in ("to", "for") and _person_like(phrase) and recipient is None:
            recipient, previous = phrase, "recipient"
        elif prep == "to" and "destination" not in parts:
            parts["destination"], destination_prep, previous = phrase, prep, "destination"
        elif prep in ("at", "toward", "towards") and action in (
                "throw", "pour", "clean", "record", "scare", "intimidate", "navigate", "push"):
            parts["target"], previous = phrase, "target"
        elif prep == "with":
            parts["instrument"], previous = phrase, "instrument"
        elif prep in ("from", "out of", "off"):
            parts["source"], previous = phrase, "source"
        elif prep == "away from":
            parts["away_from"], previous = phrase, "away_from"
        elif prep in ("through", "past", "across", "around", "along", "between"):
            parts["path"], previous = phrase, "path"
        elif prep in _PLACE_PREPS or prep in ("to", "for", "at"):
            if action == "navigate" and _person_like(phrase) and "target" not in parts:
                parts["target"], previous = phrase, "target"  # "roll up behind Kevin"
            elif previous == "object" and objects:
                objects[-1] = with_location(objects[-1], prep, phrase)
            elif previous == "recipient" and recipient is not None:
                recipient = with_location(recipient, prep, phrase)
            elif previous in parts:
                parts[previous] = with_location(parts[previous], prep, phrase)
    if objects and action in knowledge.person_object_classes and _person_like(objects[0]):
        action = knowledge.person_object_classes[action]
    if action == "throw" and "target" not in parts and destination_prep in (
            "in", "into", "on", "onto", "inside"):
        action = "place"  # "chuck the peel in the bin": put it there, not a throw at anyone
    if action == "pour" and objects and not any(
            o.substance or o.contents or (o.concept and "container" in knowledge.concepts[
                o.concept].props) for o in objects):
        action = "place"  # "dump the basket on the landing": nothing liquid is poured
    if verb in knowledge.food_only_verbs and not any(
            o.substance or (o.concept and "food" in knowledge.concepts[o.concept].props)
            for o in objects):
        action = knowledge.food_only_fallback
    return Step(index, clause, verb, action, negated=negated, condition=condition,
                objects=tuple(objects), recipient=recipient,
                destination=parts.get("destination"), destination_prep=destination_prep,
                target=parts.get("target"), instrument=parts.get("instrument"),
                source=parts.get("source"), away_from=parts.get("away_from"),
                path=parts.get("path"), keeps_state=keeps)


def _verb_noun_idiom(words: list[str], knowledge: Knowledge) -> list[str]:
    """"give the table a wipe" -> "wipe the table": the noun after "a" is the real action."""
    if len(words) < 4 or words[0] not in _GIVE_IDIOM:
        return words
    for position in range(2, len(words) - 1):
        if words[position] in ("a", "an"):
            noun = words[position + 1]
            adjective_noun = words[position + 2] if position + 2 < len(words) else ""
            for candidate in (noun, adjective_noun):
                action = knowledge.verb_words.get(candidate)
                if action and action not in ("handover", "transport", "serve", "misc"):
                    tail = words[position + 2:] if candidate == noun else words[position + 3:]
                    return [candidate, *words[1:position], *tail]
            return words
    return words


def _subject_of(words: list[str]) -> list[str]:
    """The noun phrase before "is"/"'s"/"are" in a verbless sentence ("the toaster's smoking")."""
    for position, word in enumerate(words):
        if word in ("is", "are", "was", "were", "has", "keeps"):
            return words[:position]
        if word.endswith("'s") and position + 1 < len(words) and words[position + 1] not in (
                "a", "an", "the"):
            return [*words[:position], word[:-2]]
    return []


def _leading_person(words: list[str], knowledge: Knowledge, names: Collection[str]) -> int:
    """How many leading words name a person ("aisha", "grandad", "mr osei"), 0 if none."""
    for length in (3, 2, 1):
        if len(words) <= length:
            continue
        phrase = " ".join(words[:length])
        if phrase in names or phrase in knowledge.role_words:
            return length
        if length > 1 and words[0] in ("mr", "mrs", "ms", "miss", "dr") and phrase in names:
            return length
    return 0
