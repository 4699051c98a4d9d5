"""Reading a clause's arguments: what a verb acts on, for whom, where, and in what state.

In: the verb the reader found at a clause's start, the words after it, the lexicon, and the
scene's names and pets. Out: a `Clause`: direct objects, a second object ("give *grandma* the
cup"), prepositional roles, a complement ("leave it *open*"), and the schemas its words imply
("set the dryer going" switches it on, "give the table a wipe" wipes it, "give his face a squirt
of the cleaner" sprays it). `reader.py` splits the command into clauses and finds their verbs.
Fails: never; words that fit nothing stay in the phrases, for grounding to judge.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.phrases import (
    BODY_PARTS,
    PERSON_PRONOUNS,
    PROGRAM_NOUNS,
    TITLES,
    NounPhrase,
    parse_phrase,
    split_conjoined,
)

_PICTURES = frozenset({"photo", "photos", "picture", "pictures", "pic", "pics", "video",
                       "videos", "selfie", "snapshot", "snap", "image", "images", "shot"})
_PICTURE_VERBS = frozenset({"take", "snap", "get", "shoot", "grab", "make", "send", "film"})
_PLACING = frozenset({"in", "into", "inside", "on", "onto", "on top of", "back in", "back on",
                      "back into"})
COMPLEMENTS = frozenset({"open", "shut", "closed", "on", "off", "running", "unlocked",
                          "locked", "empty", "full", "clean", "dirty", "out", "ready",
                          "going", "plugged", "charging", "burning", "lit"})
# A thing and its state, said without a verb ("lights off"): the action the state asks for.
DIRECTIVE_STATES = {"off": "turn off", "on": "turn on", "open": "open", "shut": "close",
                     "closed": "close", "locked": "lock", "unlocked": "unlock",
                     "running": "turn on", "going": "turn on"}
_DEGREES = frozenset({"wide", "fully", "right", "half", "slightly", "partly", "properly"})
# "leave the iron switched on": the participle before a state word belongs to the state.
_STATE_PARTICIPLES = frozenset({"switched", "turned", "plugged", "left", "kept", "propped",
                                "wedged", "standing"})
SETTINGS = frozenset({"high", "low", "medium", "full", "max", "maximum", "min", "minimum",
                       "medium-high", "medium-low", "full-whack", "simmer", "loud", "quiet",
                       "warm", "hot", "cool"})  # never "soft": "put him on soft ground"


@dataclass(frozen=True, slots=True)
class Clause:
    """One clause of a command, read."""

    text: str
    verb: str | None
    schemas: tuple[str, ...]
    kind: str = "step"  # step | condition | purpose | heading (a title before a colon)
    negated: bool = False
    objects: tuple[NounPhrase, ...] = ()
    second: NounPhrase | None = None
    roles: tuple[tuple[str, NounPhrase], ...] = ()
    manner: frozenset[str] = frozenset()
    complement: str | None = None
    opener: str | None = None

    def role(self, *prepositions: str) -> NounPhrase | None:
        """The first argument introduced by one of the prepositions."""
        return next((np for prep, np in self.roles if prep in prepositions), None)


def match_phrase(words: list[str], at: int, phrases: tuple[tuple[str, ...], ...]) -> int:
    """The length of the longest phrase starting at `at`, or 0."""
    for phrase in phrases:
        if tuple(words[at: at + len(phrase)]) == phrase:
            return len(phrase)
    return 0


def schemas_go(lexicon: Lexicon, verb: str) -> bool:
    """Whether the verb moves the robot somewhere ("do laps of the lounge")."""
    return bool(lexicon.schemas_of(verb)) and lexicon.schemas_of(verb)[0] == "go"


class ArgumentReader:
    """Reads a clause's arguments with one lexicon and one scene's names."""

    def __init__(self, lexicon: Lexicon, names: Collection[str],
                 animals: Collection[str]) -> None:
        """Args:
            lexicon: the reader's vocabulary.
            names: the names, ids and roles of the scene's people and pets (lower case).
            animals: the kinds of the scene's pets ("dog", "cat"), which may receive a thing.
        """
        self.lexicon = lexicon
        self.names = frozenset(names)
        self.animals = frozenset(animals)

    def read(self, text: str, verb: str, words: list[str], negated: bool,
             manner: frozenset[str]) -> Clause:
        """The clause a verb and the words after it make: its objects, a second object, its
        prepositional roles, the state it leaves things in, and the schemas its settings or
        processes imply ("set the dryer going" is switched on)."""
        lexicon = self.lexicon
        chunks: list[tuple[str, list[str]]] = [("", [])]
        index = 0
        while index < len(words):
            if words[index] in _INTENSIFIERS and match_phrase(
                    words, index + 1, lexicon.prepositions) and words[index + 1] != "to" and \
                    not (index and words[index - 1] in _DETERMINERS):
                index += 1  # "stick right behind her": behind her ("right to the top" is full)
                continue
            length = match_phrase(words, index, lexicon.prepositions)
            if length == 1 and index and words[index - 1] in ("the", "a", "an") and \
                    index + 1 < len(words) and words[index + 1] not in _DETERMINERS:
                length = 0  # "the round tin": an adjective after an article
            # "of" and a preposition inside "cup of tea" stay in the phrase.
            if length and not (length == 1 and words[index] in ("up", "down", "out", "over",
                                                                   "back") and
                               index + 1 < len(words) and words[index + 1] not in ("the", "a")
                               and not match_phrase(words, index + 1, lexicon.prepositions)):
                chunks.append((" ".join(words[index: index + length]), []))
                index += length
                continue
            chunks[-1][1].append(words[index])
            index += 1
        object_words = chunks[0][1]
        if "of" in object_words[1:3] and schemas_go(self.lexicon, verb):
            at = object_words.index("of")
            chunks.insert(1, ("to", object_words[at + 1:]))
            object_words = object_words[:at]
            chunks[0] = ("", object_words)
        if verb in _PICTURE_VERBS and _PICTURES & set(object_words):
            # "take a picture of the fridge": photograph the fridge
            at = max(i for i, w in enumerate(object_words) if w in _PICTURES)
            rest = object_words[at + 1:]
            verb, object_words = "photograph", rest[1:] if rest[:1] == ["of"] else rest
            chunks[0] = ("", object_words)
        if verb == "give":
            sprayed = _sprayed_with(object_words)
            rewritten = sprayed or self._action_noun(object_words)
            if rewritten is not None:
                verb, object_words = rewritten[:2]
            if sprayed is not None:  # "give his face a squirt of the cleaner": sprayed with it
                chunks.insert(1, ("with", sprayed[2]))
        complement: str | None = None
        if verb in ("leave", "keep"):
            object_words, complement = _kept_state(object_words)
        if complement is None and object_words and len(object_words) > 1 and (
                object_words[-1] in COMPLEMENTS or (
                    verb in STARTING_VERBS and object_words[-1] in _PROCESSES
                    and object_words[-2] not in _DETERMINERS)):
            complement = object_words.pop()
            if len(object_words) > 1 and object_words[-1] in _STATE_PARTICIPLES:
                object_words.pop()
        elif complement is None and object_words and object_words[-1] in _STATE_PARTICIPLES \
                and chunks[1:2] and chunks[1][0] in ("on", "off", "in") and not [
                    w for w in chunks[1][1] if w != ","]:
            object_words.pop()  # "the iron switched on, on the board": "on" then a place
            complement = chunks.pop(1)[0]
        while complement is not None and len(object_words) > 1 and object_words[-1] in _DEGREES:
            object_words.pop()  # "leave it wide open": how open, not part of the thing
        setting = next((i for i, (prep, chunk) in enumerate(chunks[1:], 1) if prep == "on"
                        and _names_setting(chunk)), None)
        if setting is not None:
            # "leave the oven on low", "put the heater on full": a setting, not a place
            complement = complement or chunks[setting][0]
            chunks.pop(setting)
        second: NounPhrase | None = None
        objects_words = split_conjoined(object_words)
        carries = {"fetch", "give", "pick"} & set(lexicon.schemas_of(verb)) and "make" not in \
            lexicon.schemas_of(verb)
        if len(objects_words) == 1 or (objects_words and carries):
            # "grandma the cup"; "Mr Grey his fags and lighter": the person, then every thing
            # (but "make us a tea, milk and two sugars" lists what goes in the tea)
            first, rest = self._recipient_split(objects_words[0])
            if first == ["her"] and any(prep in ("to", "into", "back to") and chunk
                                        for prep, chunk in chunks[1:]):
                first = None  # "take her frame to the office": her frame, taken there
            if first is not None and rest:
                second, objects_words = parse_phrase(first, lexicon), [rest, *objects_words[1:]]
        objects = tuple(p for w in objects_words if (p := parse_phrase(w, lexicon)) is not None)
        roles = tuple((prep, np) for prep, chunk in chunks[1:] for part in split_conjoined(chunk)
                      if (np := parse_phrase(part, lexicon)) is not None)
        # A preposition left without its noun ("put the soap in") points back: "in it".
        if verb in ("leave", "keep") and complement is None and any(
                not chunk and prep in ("on", "off") for prep, chunk in chunks[1:]):
            # "leave the landing light on for Dad": the state it stays in, not a place
            complement = next(p for p, c in chunks[1:] if not c and p in ("on", "off"))
            chunks = [(p, c) for p, c in chunks if c or p != complement]
        roles += tuple((prep, NounPhrase("", pronoun="it")) for prep, chunk in chunks[1:]
                       if not chunk and prep in _PLACING)
        schemas = lexicon.schemas_of(verb)
        if (setting is not None or complement in _PROCESSES) and \
                verb in _SETTING_VERBS | STARTING_VERBS and objects and not any(
                    prep in _PLACING and chunk for prep, chunk in chunks[1:]):
            # "set the dryer going", "put the heater on full": switched on
            schemas = lexicon.schemas_of("turn on") or schemas
        elif complement in _HEATING and verb in _SETTING_VERBS | STARTING_VERBS and objects:
            # "get the chip pan heating on the big ring": put there and the ring switched on
            schemas = lexicon.schemas_of("heat") or schemas
        if verb in ("keep", "leave") and complement in DIRECTIVE_STATES and objects:
            # "keep the oven on at 200", "leave the porch light on": bring about that state,
            # and leave it so (no switching off or closing afterwards)
            schemas = lexicon.schemas_of(DIRECTIVE_STATES[complement]) or schemas
            manner = manner | {"leave"}
        return Clause(text, verb, schemas, "step", negated, objects, second, roles, manner,
                      complement)

    def _action_noun(self, words: list[str]) -> tuple[str, list[str]] | None:
        """ "give the table a wipe" -> ("wipe", ["the", "table"]); "give it a stir"."""
        for index in range(1, len(words) - 1):
            if words[index] in ("a", "an", "another", "the") and len(words) - index <= 4 \
                    and words[index - 1] != "of":  # "one of the custard creams": a thing
                pair = " ".join(words[-2:])  # "give the mower a hose down"
                if len(words) - index > 2 and self.lexicon.schemas_of(pair):
                    return pair, words[:index]
                noun = words[-1]
                base = _ACTION_NOUNS.get(noun) or self.lexicon.lemma(noun)
                if self.lexicon.schemas_of(base) and base not in ("give", "go", "hand"):
                    return base, words[:index]
        return None

    def _recipient_split(self, words: list[str]) -> tuple[list[str] | None, list[str]]:
        """ "grandma the cup" -> (["grandma"], ["the", "cup"]): a person before a second noun
        phrase is the recipient of a double-object verb."""
        if len(words) < 2:
            return None, words
        lexicon = self.lexicon
        for length in (3, 2, 1):
            head = words[:length]
            phrase = " ".join(head)
            rest = words[length:]
            if not rest:
                continue
            person = (phrase in PERSON_PRONOUNS or phrase in lexicon.people
                      or phrase in self.names or (head[0] in ("the", "my", "our", "your")
                                                  and " ".join(head[1:]) in lexicon.people)
                      or (length == 2 and head[0] in TITLES and not head[1].endswith("'s"))
                      # "hand uncle ray the keys": a kin word and a name
                      or (length == 2 and head[0] in lexicon.people and head[1] not in
                          _DETERMINERS and rest[0] in _DETERMINERS and not head[1].endswith(
                              "'s")))
            # "give the dog a treat": a pet of the scene, by its kind, before a determiner
            pet = head[0] in ("the", "my", "our", "your") and length > 1 and \
                " ".join(head[1:]) in self.animals and rest[0] in _DETERMINERS
            person = person or pet
            adverb = len(rest) == 1 and rest[0].endswith("ly")  # "shake him properly"
            if head == ["her"] and rest[0] in BODY_PARTS:
                return None, words  # "hold her arm": her arm, not the arm handed to her
            if person and not adverb and (
                    rest[0] in _DETERMINERS or len(rest) <= 3):
                return head, rest
        return None, words


_DETERMINERS = frozenset({"a", "an", "the", "some", "his", "her", "their", "my", "this", "that",
                          "those", "these", "two", "one"})
_INTENSIFIERS = frozenset({"right", "just", "straight", "directly", "smack", "bang"})
_WHEN = frozenset({"tonight", "overnight", "today", "tomorrow", "all", "till", "until", "for",
                   "while", "when", "after", "before", "then", "now"})


# Nouns for an action that no verb spells ("give the rug a going-over").
_ACTION_NOUNS = {"going-over": "clean", "once-over": "clean", "spruce": "clean",
                 "tidy-up": "tidy", "wipe-down": "wipe"}
# A washing machine's or dishwasher's programmes ("start it on eco"): a setting, not a place.
_PROGRAMME_NAMES = frozenset({"eco", "economy", "quick", "intensive", "delicate", "delicates",
                              "cotton", "cottons", "wool", "synthetics", "normal", "auto",
                              "rinse", "spin"})
_SETTING_VERBS = frozenset({"put", "set", "pop", "stick", "have", "get"})
# "start the sink filling", "get the bath running": what a started thing goes on doing.
STARTING_VERBS = frozenset({"start", "set", "get"})
_HEATING = frozenset({"heating", "boiling", "warming", "cooking", "frying", "simmering"})
_PROCESSES = _HEATING | frozenset({"going", "running", "filling", "preheating", "draining",
                                   "spinning"})


def _sprayed_with(words: list[str]) -> tuple[str, list[str], list[str]] | None:
    """ "his face a good squirt of the cleaner" -> ("spray", his face, the cleaner): a dose of
    a spray given to something is that thing sprayed with it."""
    if "of" not in words[2:]:
        return None
    of = words.index("of", 2)
    article = next((i for i in range(of - 1, 0, -1) if words[i] in ("a", "an", "another")),
                   None)
    if article is None or of - article > 3 or words[of - 1] not in _SPRAY_DOSES:
        return None
    return "spray", words[:article], words[of + 1:]


_SPRAY_DOSES = frozenset({"blast", "squirt", "spray", "spritz", "shot", "mist"})


def _names_setting(chunk: list[str]) -> bool:
    """ "on low", "on eco", "on the quick cycle", "on nice and loud": how a machine is set,
    not where a thing goes."""
    if chunk[:2] in (["nice", "and"], ["good", "and"]):
        chunk = chunk[2:]  # "nice and loud": loud
    words = [w for w in chunk if w not in ("the", "a", "its", "their", ",")]
    return bool(words) and (_is_setting(chunk[0]) or (
        words[-1] in PROGRAM_NOUNS and len(words) <= 3))


def _is_setting(word: str) -> bool:
    """A word naming how high an appliance is set ("low", "full", "180")."""
    return word in SETTINGS or word in _PROGRAMME_NAMES or (word.isdigit() and int(word) >= 30)


def _kept_state(words: list[str]) -> tuple[list[str], str | None]:
    """What "leave/keep X <state>" keeps, when the state is followed only by a time or a
    comma ("leave it open tonight", "keep the door shut, the dog gets out")."""
    at = next((i for i, w in enumerate(words) if i and w in COMPLEMENTS), None)
    if at is None or at == len(words) - 1:
        return words, None
    after = words[at + 1:]
    if after[0] == ",":
        return words[:at] + after, words[at]
    if after[0] in _WHEN:
        return words[:at], words[at]
    return words, None
