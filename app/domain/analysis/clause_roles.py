"""One clause read into a `Step`: its verb class and the roles of its noun phrases.

In: a clause's words (filler, condition and negation already removed, idioms already
rewritten), the knowledge tables and the scene's lower-case names. Out: a `Step` with the verb
class (`action`), direct objects, recipient, destination (and its preposition), target,
instrument, source, away-from and path phrases as unresolved `Mention`s. Never fails: a clause
without a known verb gives a step with `action=None` whose `objects` are the people and things
its subject names (so a later "it" can point back).
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

from app.domain.analysis.clauses import preposition_parts, verb_at
from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.mentions import Mention, parse_mention, with_location

_PLACE_PREPS = frozenset({"into", "inside", "onto", "in", "on", "under", "underneath",
                          "beneath", "behind", "near", "beside", "by", "next to", "in front of",
                          "on top of", "against", "over", "close to", "within", "halfway up",
                          "halfway down", "partway up", "partway down"})
_CARRYING_DESTINATIONS = frozenset({"to", "into", "onto"})
_CARRYING_ACTIONS = frozenset({"transport", "handover", "serve", "remove", "pick"})
_PLACING_ACTIONS = frozenset({"place", "transport", "pour", "throw", "mix", "remove", "push",
                              "block", "heat", "clean", "handover", "serve"})
_PERSON_FIRST = frozenset({"me", "him", "her", "them", "us"})
_DETERMINER_WORDS = frozenset({"a", "an", "the", "some", "his", "her", "their", "my", "your",
                               "this", "that", "these", "those", "one", "two", "three", "more",
                               "another", "any", "something", "anything", "everything"})
_THING_PREPS = frozenset({"with", "of", "about"})
_MOTION_ACTIONS = frozenset({"navigate", "transport"})
_PERSON_QUANTIFIERS = frozenset({"each", "every", "all", "both"})
_PLACE_ADVERBS = frozenset({"upstairs", "downstairs", "outside", "inside", "indoors",
                            "outdoors", "home", "here", "there", "back", "out", "up", "down",
                            "over", "round", "around", "away", "off", "in", "along", "next door",
                            "right", "straight", "now", "again", "too", "everywhere", "somewhere",
                            "anywhere", "elsewhere", "close", "closely", "quickly", "slowly",
                            "loudly", "quietly", "gently", "carefully", "right away", "later"})
_PURPOSE_OPENERS = frozenset({"check", "see", "make", "help", "stop", "keep", "let", "get",
                              "find", "air", "steady", "feed", "cool", "dry", "warm", "boil",
                              "simmer", "soak", "cook", "heat", "wake", "calm", "show", "teach",
                              "scare", "frighten", "save", "stay", "catch", "block", "hold"})
_GIVING_ACTIONS = frozenset({"handover", "transport", "serve", "pour", "pick", "heat"})


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
    purpose: str | None = None


def _segments(words: list[str]) -> list[tuple[str | None, list[str]]]:
    segments: list[tuple[str | None, list[str]]] = [(None, [])]
    position = 0
    by_first_word = preposition_parts()
    while position < len(words):
        for prep, parts in by_first_word.get(words[position], ()):
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


_WHAT_IS = frozenset({"what's", "whatever's", "what", "whatever"})
_OBJECT_PRONOUNS = frozenset({"him", "her", "them", "me", "us"})
_ADVERBIAL_OPENERS = frozenset({"the", "all", "round", "around", "about", "everywhere", "close",
                                "closely", "constantly", "nonstop", "non-stop", "day", "every",
                                "whenever", "wherever", "when", "while", "until", "till"})


def _bare_pronoun(mention: Mention, knowledge: Knowledge, names: Collection[str]) -> Mention:
    """"film her the whole time", "follow him round the house": the person is the pronoun
    alone; what follows says how or where, not which thing (unlike "her bag")."""
    words = mention.text.split()
    if len(words) > 1 and words[0] in _OBJECT_PRONOUNS and words[1] in _ADVERBIAL_OPENERS:
        return parse_mention(words[0], knowledge, names)
    return mention


def _person_like(mention: Mention) -> bool:
    return mention.kind in ("person", "name") or (
        mention.kind == "pronoun" and mention.head in _PERSON_FIRST | {"everyone", "everybody"})


def parse_clause(index: int, clause: str, words: list[str], knowledge: Knowledge,
                 names: Collection[str], *, negated: bool, condition: str | None) -> Step:
    """Read one clause into a step (see the module docstring)."""
    found = verb_at(words, knowledge)
    if found is None:
        # "The toaster's smoking!": no action, but its subject is what a later "it" means.
        subject = _subject_of(words)
        heard = [parse_mention(" ".join(subject), knowledge, names)] if subject else []
        heard += [parse_mention(w.removesuffix("'s"), knowledge, names) for w in words
                  if w.removesuffix("'s") in names or w.removesuffix("'s") in knowledge.role_words]
        # "Lily wants to play with the bleach tablet, pass it to her": "it" is the tablet.
        heard += [m for m in (parse_mention(" ".join(t), knowledge, names)
                              for p, t in _segments(words)[1:] if p in _THING_PREPS and t)
                  if m.kind == "object" and m.concept not in (None, "generic")]
        return Step(index, clause, None, None, negated=negated, condition=condition,
                    objects=tuple(m for m in heard if m.kind in ("object", "person", "name")))
    verb, used, particle = found
    rest = [w for i, w in enumerate(words[used:], start=used) if i != particle]
    action = knowledge.verb_words[verb]
    keeps = verb.split()[0] in ("leave", "keep") or verb.endswith(" open")

    def mention(tokens: list[str]) -> Mention:
        return parse_mention(" ".join(tokens), knowledge, names)

    segments, purpose = _purpose(_segments(rest), knowledge)
    segments[0] = (segments[0][0], _without_as_phrase(segments[0][1]))
    if action == "switch_off" and verb.split()[0] in _SETTING_OUT_VERBS and any(
            p in _SET_OUT_PLACES for p, _ in segments[1:]):
        # "put the pills out on the table": setting something out, not putting it out
        action = knowledge.verb_words.get(verb.split()[0], action)
    place_word = _place_adverb(segments[0][1])
    if place_word is not None:
        segments = [(None, []), *segments[1:]]
        if place_word and action in _MOTION_ACTIONS and not any(
                p in ("to", "into") for p, _ in segments):
            segments.append(("to", [place_word]))  # "nip upstairs": where the robot goes
    objects = [mention(t.split()) for t in _split_list(segments[0][1])]
    recipient: Mention | None = None
    if action in _GIVING_ACTIONS and segments[0][1]:
        first = segments[0][1]
        lead = _leading_person(first, knowledge, names)
        possessive = first[0] == "her" and len(first) > 1 and action not in (
            "handover", "serve") and first[1] not in _DETERMINER_WORDS
        if first[0] in _PERSON_FIRST and len(first) > 1 and not possessive and not any(
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
    objects = [_bare_pronoun(m, knowledge, names) for m in objects]
    first_words = objects[0].text.split() if objects else []
    if action == "assist" and (lead := _leading_person(first_words, knowledge, names)):
        objects[0] = mention(first_words[:lead])  # "help dad up the stairs": dad
    if action in ("serve", "handover") and recipient is None and len(objects) == 1 and (
            _person_like(objects[0])):
        recipient, objects = objects[0], []  # "feed her": the person is fed, not handed over
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
            if prep in allowed and verb in _FILLING_VERBS and prep in _LOCATING_PREPS and (
                    segments[position - 1][0] in _SOURCE_PREPS):
                continue  # "fill the bottle from the jug in the fridge": where the jug is
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
        elif prep in _SOURCE_PREPS:
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
    # "film what's on the screen": the thing meant is the screen.
    objects = [m.location[1] if m.head in _WHAT_IS and m.location else m for m in objects]
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
                path=parts.get("path"), keeps_state=keeps, purpose=purpose)


# The thing filled is the verb's object, so a place after its source locates the source.
_FILLING_VERBS = frozenset({"fill", "fill up", "refill", "top up"})
_LOCATING_PREPS = frozenset({"in", "on", "inside", "at"})
_SOURCE_PREPS = frozenset({"from", "out of", "off"})
# "Put out" / "set out" is switching off ("put the candle out") unless a place follows.
_SETTING_OUT_VERBS = frozenset({"put", "set", "lay"})
_SET_OUT_PLACES = frozenset({"on", "onto", "in", "into", "by", "beside", "next to", "near",
                             "at"})
_LINKING = frozenset({"is", "are", "was", "were", "has", "have", "keeps", "can", "can't",
                      "cannot", "will", "won't", "should", "must", "might", "may", "needs",
                      "looks", "seems", "isn't", "aren't", "wasn't", "doesn't", "does"})
_NOUN_PHRASE_OPENERS = frozenset({"the", "that", "this", "these", "those", "my", "our", "your",
                                  "his", "her", "their"})


def _subject_of(words: list[str]) -> list[str]:
    """The noun phrase opening a statement ("the toaster's smoking", "that stair gate drives me
    mad"): the words before its verb, so a later "it" can point back to it."""
    for position, word in enumerate(words):
        if word in _LINKING:
            return words[:position]
        if word.endswith("'s") and position + 1 < len(words) and words[position + 1] not in (
                "a", "an", "the"):
            return [*words[:position], word[:-2]]
        if (position >= 2 and words[0] in _NOUN_PHRASE_OPENERS and word.endswith("s")
                and not word.endswith(("ss", "'s"))):
            return words[:position]  # "the dog needs", "that gate drives": a verb in -s
    return []


def _leading_person(words: list[str], knowledge: Knowledge, names: Collection[str]) -> int:
    """How many leading words name a person ("aisha", "grandad", "mr osei"), 0 if none."""
    skipped = 0
    while skipped < len(words) - 1 and words[skipped] in _PERSON_QUANTIFIERS:
        skipped += 1  # "give each resident ...", "take all the kids ..."
    for length in (3, 2, 1):
        if len(words) <= skipped + length:
            continue
        phrase = " ".join(words[skipped:skipped + length])
        length += skipped
        if phrase in names or phrase in knowledge.role_words:
            return length
        if length > 1 and words[skipped] in ("mr", "mrs", "ms", "miss", "dr") and phrase in names:
            return length
    return 0


def _purpose(segments: list[tuple[str | None, list[str]]], knowledge: Knowledge
             ) -> tuple[list[tuple[str | None, list[str]]], str | None]:
    """Cut a trailing "to <verb> ..." ("to check they're breathing") off as the purpose."""
    for position, (prep, tokens) in enumerate(segments[1:], start=1):
        if prep != "to" or not tokens:
            continue
        first = tokens[0]
        if first in _PURPOSE_OPENERS or (first in knowledge.verb_words and first not in (
                knowledge.concept_words) and first not in knowledge.room_words):
            rest = [" ".join(t) if p is None else f"{p} {' '.join(t)}"
                    for p, t in segments[position:]]
            return segments[:position], " ".join(rest)
    return segments, None


def _without_as_phrase(words: list[str]) -> list[str]:
    """Cut "as a treat", "as well" off the object words: what the thing is for, not the thing."""
    for position in range(1, len(words) - 1):
        if words[position] == "as" and words[position + 1] in ("a", "an", "well", "usual"):
            return words[:position]
    return words


def _place_adverb(words: list[str]) -> str | None:
    """A first segment that is only an adverb of place or manner ("upstairs", "right")."""
    if not words or any(w not in _PLACE_ADVERBS for w in words):
        return None
    places = [w for w in words if w in ("upstairs", "downstairs", "outside", "inside", "home",
                                       "indoors", "outdoors", "next door", "here", "there")]
    return places[-1] if places else ""
