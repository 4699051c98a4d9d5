"""Reading a command: clauses, each with its verb, its schemas and its arguments.

In: the command text, the lexicon, and the scene's names (ids, names and roles, lower case, so
"give Tom the cup" reads Tom as a person). Out: `read(text)` -> `Reading`: `Clause`s in command
order. A clause is a step (imperative), a condition ("while she naps") or a purpose ("so she
can't get up"); it carries its verb lemma (phrasal verbs joined: "turn on"), the schemas that
verb may name, its direct objects, a second object ("give *grandma* the cup"), its prepositional
roles, negation and manner cues. How: sentences split at . ! ? ; and new lines, then at
sequencers ("then", "after that") and at "and"/commas before a verb; fillers ("could you
please") are dropped; subordinate clauses are cut off at their openers; what follows a clause's
verb is read by `arguments.py`. Fails: never; a clause whose verb no schema covers keeps
`schemas=()` and the analyzer treats it as not understood.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from dataclasses import dataclass, replace

from app.domain.analysis.arguments import (
    COMPLEMENTS,
    DIRECTIVE_STATES,
    SETTINGS,
    ArgumentReader,
    Clause,
    match_phrase,
    schemas_go,
)
from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.phrases import (
    PERSON_PRONOUNS,
    POSSESSIVES,
)

_CONTRACTIONS = (("won't", "will not"), ("can't", "cannot"), ("n't", " not"), ("'re", " are"),
                 ("'ll", " will"), ("'ve", " have"), ("'m", " am"), ("'d", " would"))
_KEEP_CONTRACTED = ("don't", "doesn't", "won't", "can't", "it's", "that's", "there's",
                    "let's", "i'm", "we're", "you're", "she's", "he's")
_TOKEN = re.compile(r"[a-z0-9]+(?:_[a-z0-9]+)*(?:['\u2019-][a-z0-9]+)*|[,&]")
_SENTENCE = re.compile(
    r"[.!?;:()\[\]]+|\n\s*(?:[-*•]|\d+[.)])\s*|\s-{1,2}\s|\s+\d+[.)]\s+|^\d+[.)]\s+")
_LINE = re.compile(r"\s*\n\s*")
_ADVERB_PAIRS = frozenset({("upside", "down"), ("inside", "out"), ("right", "away"),
                           ("handle", "first"), ("handle-first", "first"),
                           ("straight", "away"), ("right", "now"), ("for", "now"),
                           ("at", "once"), ("as", "usual"), ("face", "down"),
                           ("face", "up"), ("face", "first"), ("as", "is")})
_STRAY = frozenset({"handle-first", "blade-first", "point-first", "pls", "plz", "please",
                    "thanks", "thx", "ty", "cheers", "lol", "haha", "ugh", "hey", "oh", "ok",
                    "okay", "btw", "asap", "ta"})
_SUBJECTS = frozenset({"it's", "its", "she's", "he's", "they're", "i'm", "we're", "there's",
                       "that's", "i", "she", "he", "they", "we", "you're", "i've", "i'll",
                       "it", "this", "there", "im", "theyre", "shes", "hes", "thats"})
_SOMEONE = frozenset({"nobody", "noone", "everyone", "everybody", "someone", "somebody",
                      "anyone", "anybody"})
_OBJECT_STARTS = frozenset({"it", "them", "the", "a", "an", "my", "your", "his", "her", "our",
                            "their", "this", "that", "these", "those", "up", "down", "off",
                            "out", "away", "back", "everything", "all"})
_AUXILIARIES = frozenset({"is", "are", "was", "were", "has", "have", "had", "will", "can",
                          "could", "should", "would", "won't", "doesn't", "don't", "isn't",
                          "aren't", "wasn't", "needs", "wants", "likes", "keeps", "gets",
                          "love", "loves", "like", "hate", "hates", "enjoy", "enjoys", "know",
                          "knows", "think", "thinks", "want", "need", "seem", "seems"})
@dataclass(frozen=True, slots=True)
class Reading:
    """A whole command read into clauses."""

    text: str
    clauses: tuple[Clause, ...]
    manner: frozenset[str]


_INFORMAL = {"u": "you", "ur": "your", "r": "are", "im": "i'm", "dont": "don't",
             "cant": "can't", "wont": "won't", "didnt": "didn't", "doesnt": "doesn't",
             "isnt": "isn't", "thats": "that's", "theres": "there's", "whats": "what's",
             "n": "and", "&": "and", "+": "and", "w": "with", "b4": "before", "2": "to"}


_ABBREVIATION = re.compile(r"\b(mr|mrs|ms|mx|dr|prof|st|sr|jr|no|approx|vs|etc)\.(?=\s+\w)")
_DECIMAL = re.compile(r"(?<=\d)\.(?=\d)")
_TIME_OF_DAY = re.compile(r"\b([ap])\.m\.?")


def _unabbreviated(text: str) -> str:
    """ "Mrs. Okafor's walker", "meeting room 2.04", "9 a.m.": full stops that end no
    sentence."""
    text = _TIME_OF_DAY.sub(r"\1m", text)
    text = _DECIMAL.sub("_", text)
    text = _PLUG_PULLED.sub("unplug ", text)
    return _ABBREVIATION.sub(r"\1", text)


# "Pull the plug on the fridge", "take the plug out of the telly": unplug it.
_PLUG_PULLED = re.compile(
    r"\b(?:pull|take|yank|whip)(?: out)? the plug (?:on|of|out of|from|out from) ")


_ASSURE = (("make", "sure"), ("ensure",), ("see", "that"), ("check", "that"))


def _assured(words: list[str]) -> list[str]:
    """ "make sure the hob and oven are off" -> "the hob and oven off": a state to bring
    about, read as the verbless directive it amounts to."""
    for at in range(len(words)):
        length = match_phrase(words, at, _ASSURE)
        if not length:
            continue
        start = at + length + (words[at + length: at + length + 1] == ["that"])
        for copula in range(start + 1, min(len(words) - 1, start + 8)):
            state_at = copula + 1
            if words[copula] in ("is", "are") and words[state_at] in DIRECTIVE_STATES and (
                    state_at + 1 == len(words) or words[state_at + 1] in (",", "and")):
                return [*words[:at], *words[start:copula], *words[state_at:]]
    return words


def _heat_setting(verb: str, rest: list[str]) -> tuple[str, list[str]]:
    """ "put it on high", "turn the pan to medium", "the casseroles in at 220": a heat setting
    names heating, not a place to put things."""
    for at, word in enumerate(rest):
        after = rest[at + 1: at + 3]
        setting = after[:1] and (after[0] in SETTINGS or (after[0].isdigit() and int(
            after[0]) >= 50) or after == ["gas", "mark"])
        if word in ("on", "to", "at") and setting:
            kept = rest[:at]
            while kept and kept[-1] in ("in", "on", "into"):
                kept.pop()  # "in at 220": in the oven the setting implies
            return "heat", kept
    return verb, rest


def _titles(clause: Clause, words: list[str]) -> bool:
    """Whether a clause before a colon (or a first dash) is a title: a few words naming no
    action ("End of day job:", "Milk time -"), not an order in words the robot lacks."""
    return clause.kind == "step" and not clause.schemas and len(words) <= 6 and (
        clause.verb is None or len(words) < 2 or words[1] not in _OBJECT_STARTS)


_OVER_BY = re.compile(r"\bover (by|near|beside|next to)\b")


def _words(text: str) -> list[str]:
    # "the first aid kit": a compound, never the sequence word "first"; "over by the boiler"
    # is by it
    lowered = _OVER_BY.sub(r"\1", text.lower().replace("\u2019", "'").replace(
        "first aid", "first-aid"))
    words = _TOKEN.findall(lowered)
    # "can u go check if im in bed": everyday shorthand read as the words it stands for
    # ("2" only between words, where it is "to").
    return [_INFORMAL.get(w, w) if w != "2" or (0 < i < len(words) - 1 and
            not words[i - 1].isdigit() and not words[i + 1].isdigit() and
            words[i + 1] not in ("minutes", "hours", "mins", "seconds")) else w
            for i, w in enumerate(words)]


_REQUESTS = (("could", "i", "trouble", "you", "for"), ("can", "i", "trouble", "you", "for"),
             ("can", "i", "have"), ("could", "i", "have"), ("may", "i", "have"),
             ("can", "i", "get"), ("could", "i", "get"), ("can", "we", "have"),
             ("could", "we", "have"), ("can", "we", "get"), ("i'd", "like"), ("i", "would",
             "like"), ("i'd", "love"), ("i", "want"), ("i", "need"), ("we", "need"),
             ("i'll", "have"), ("i'll", "take"), ("get", "me"), ("fetch", "me"))


def _indirect_request(words: list[str]) -> list[str]:
    """ "Could I trouble you for a glass of water", "I'd like the remote": bring it to me."""
    for pattern in _REQUESTS:
        if tuple(words[: len(pattern)]) == pattern and len(words) > len(pattern):
            rest = words[len(pattern):]
            if rest[0] in ("to", "you"):
                return words  # "I want to...", "I need you to..." are not things wanted
            return ["bring", "me", *rest]
    return words


_NEXT_AS_ADJECTIVE = frozenset({"the", "a", "this", "that", "my", "your", "our", "his", "her",
                                "their", "its", "out"})
_ADVERBIAL_PARTICLES = frozenset({"up", "away", "down", "off", "out", "together"})


_ASPECT = frozenset({"finish", "start", "begin", "keep", "continue", "resume"})


def _aspect_dropped(words: list[str], lexicon: Lexicon) -> list[str]:
    """ "Finish loading the dishwasher", "keep stirring the soup": the task is the -ing verb;
    "start it filling": what it then does is no thing to act on."""
    if len(words) > 1 and words[0] in _ASPECT and words[1].endswith("ing") and \
            lexicon.schemas_of(lexicon.lemma(words[1])):
        return [lexicon.lemma(words[1]), *words[2:]]
    for index in range(1, len(words) - 1):
        after = words[index + 1]
        if words[index] in ("it", "them") and after.endswith("ing") and \
                after not in COMPLEMENTS and lexicon.is_verb(after) and (
                    index + 2 == len(words) or words[index + 2] in ("and", ",", "for", "so")):
            return words[:index + 1] + words[index + 2:]
    return words


def _past_tense(word: str, lexicon: Lexicon) -> bool:
    """A regular past form ("dropped", "spilled"): never the verb of an order."""
    return word.endswith("ed") and lexicon.lemma(word) != word and word not in (
        "need", "feed", "bleed", "speed", "weed", "seed", "shed", "bed", "red")


def sounds_like_statement(text: str) -> bool:
    """Whether a clause reads as a remark ("the kettle's been screaming", "my hands are all
    oniony") rather than an order: a subject, an auxiliary or a contraction near its start."""
    words = text.split()
    return bool(words) and (words[0] in _SUBJECTS or words[0] in POSSESSIVES or any(
        w in _AUXILIARIES or w.endswith(("'s", "'re", "'ve", "'ll", "'d", "'m"))
        for w in words[:4]))


_TIMES = re.compile(r"^(?:(?:a )?couple(?: of)?|a few|few|several|two|three|four|five|"
                    r"\d+|many|a dozen|a number of) times?$")


def _without_repetitions(words: list[str]) -> list[str]:
    """Drop how often ("a couple of times", "twice"): it names no thing."""
    text = " ".join(words)
    for size in (4, 3, 2):
        for start in range(len(words) - size + 1):
            if _TIMES.match(" ".join(words[start:start + size])):
                return _without_repetitions(words[:start] + words[start + size:])
    kept = [w for w in words if w not in ("twice", "thrice")]
    return kept if kept or not text else words


_AS_IT_IS = frozenset({("as", "it", "is"), ("as", "they", "are"), ("as", "it", "comes")})


def _without_adverb_pairs(words: list[str]) -> list[str]:
    """Drop two-word adverbs ("upside down", "right away") that name no thing."""
    words = _without_repetitions(words)
    for start in range(len(words) - 2):
        if tuple(words[start:start + 3]) in _AS_IT_IS:  # "in the oven as it is"
            words = words[:start] + words[start + 3:]
            break
    kept: list[str] = []
    for word in words:
        if kept and (kept[-1], word) in _ADVERB_PAIRS:
            kept.pop()
            continue
        kept.append(word)
    return kept


def _manner(words: list[str], lexicon: Lexicon) -> tuple[list[str], frozenset[str]]:
    """Remove manner phrases, returning the rest of the words and the cues found."""
    found: set[str] = set()
    kept: list[str] = []
    index = 0
    while index < len(words):
        for cue, phrases in lexicon.manner.items():
            length = match_phrase(words, index, phrases)
            if length and cue in ("fast", "slow", "covert", "hurry") and (
                    length == 1 and index == 0 and lexicon.schemas_of(words[0])):
                continue  # "run the bath": the clause's verb, not a manner
            if length:
                found.add(cue)
                if cue in ("fast", "slow", "covert", "hurry"):
                    index += length
                    break
        else:
            kept.append(words[index])
            index += 1
            continue
    return kept, frozenset(found)


class Reader:
    """Reads commands with one lexicon and one scene's names."""

    def __init__(self, lexicon: Lexicon, names: Collection[str] = (),
                 animals: Collection[str] = ()) -> None:
        """Args:
            lexicon: the reader's vocabulary.
            names: the names, ids and roles of the scene's people and pets (lower case).
            animals: the kinds of the scene's pets ("dog", "cat"), which may receive a thing.
        """
        self.lexicon = lexicon
        self.names = frozenset(names)
        self.animals = frozenset(animals)
        self._arguments = ArgumentReader(lexicon, self.names, self.animals)

    def read(self, text: str) -> Reading:
        """Read a command into clauses (see the module docstring)."""
        clauses: list[Clause] = []
        manner: set[str] = set()
        lowered = _unabbreviated(self._lines(text.lower().replace("\u2019", "'")))
        pieces = _SENTENCE.split(lowered)
        marks = [m.group(0) for m in _SENTENCE.finditer(lowered)]
        for at, sentence in enumerate(pieces):
            mark = marks[at] if at < len(marks) else ""
            heading = ":" in mark or (not clauses and mark.strip() in ("-", "--"))
            for part, kind, opener in self._parts(_assured(_words(sentence))):
                clause = self._clause(part, kind, opener)
                if clause is not None:
                    if heading and _titles(clause, part):
                        # "End of day job:", "Milk time - ...": a title, not a task
                        clause = replace(clause, kind="heading")
                    clauses.append(clause)
                    manner |= clause.manner
        return Reading(text, tuple(clauses), frozenset(manner))

    # Splitting.
    def _lines(self, text: str) -> str:
        """A line break ends a sentence only where the next line starts a new instruction
        (a verb); elsewhere ("give the scissors to\n\nLeo") it is a space."""
        pieces = _LINE.split(text)
        joined = pieces[0]
        for piece in pieces[1:]:
            first = _words(piece)[:1]
            starts = bool(first) and self.lexicon.lemma(first[0]) in self.lexicon.verb_starts
            joined += (". " if starts else " ") + piece
        return joined

    def _parts(self, words: list[str]) -> list[tuple[list[str], str, str | None]]:
        """Split a sentence into (words, kind, opener) at sequencers, verbs after "and" or a
        comma, and subordinate openers."""
        lexicon = self.lexicon
        parts: list[tuple[list[str], str, str | None]] = [([], "step", None)]
        index = 0
        while index < len(words):
            word = words[index]
            seq = match_phrase(words, index, lexicon.sequencers)
            if seq and words[index] == "next" and (words[index + seq: index + seq + 1] == [
                    "to"] or (index and words[index - 1] in _NEXT_AS_ADJECTIVE)):
                seq = 0  # "next to the stove", "the next step": not the next instruction
            if seq:
                if parts[-1][0]:
                    parts.append(([], "step", None))
                index += seq  # ", then run out": the sequencer after a comma opens nothing new
                continue
            if word in ("and", ",", "&") and index and words[index - 1] in DIRECTIVE_STATES \
                    and words[index + 1: index + 2] and words[index + 1] in DIRECTIVE_STATES:
                parts[-1][0].append(word)  # "shut and locked": one thing's two states
                index += 1
                continue
            if word in ("and", ",", "&") and (self._starts_clause(words, index + 1) or (
                    word == "," and self._elliptic_put(words[index + 1:])) or (
                    self._whole(parts[-1][0]) and self._directive_ahead(words[index + 1:]))):
                parts.append(([], "step", None))
                index += 1
                continue
            if word in (",", "and", "but", "because", "cause") and parts[-1][0] and \
                    self._starts_statement(words, index + 1) and words[index + 1] != "so":
                # (", so he knows who's boss": the purpose opener reads that)
                parts.append(([], "step", None))  # ", it's all sticky": a statement
                index += 1
                continue
            if word == "by" and parts[-1][0] and words[index + 1: index + 2] and words[
                    index + 1].endswith("ing") and self.lexicon.is_verb(
                    self.lexicon.lemma(words[index + 1])):
                # "wake him by banging two pans": how, which is a step of its own
                parts.append(([self.lexicon.lemma(words[index + 1])], "step", None))
                index += 2
                continue
            opener = self._opener(words, index, bool(parts[-1][0]))
            if opener is not None:
                kind, length = opener
                parts.append(([], kind, " ".join(words[index: index + length])))
                index += length
                continue
            parts[-1][0].append(word)
            index += 1
        return [p for p in parts if p[0]]

    def _opener(self, words: list[str], index: int, mid_clause: bool) -> tuple[str, int] | None:
        word = words[index]
        if (word in self.lexicon.condition_openers and (
                index == 0 or mid_clause) and word not in ("as", "after", "before")) or (
                word in ("after", "before") and index + 1 < len(words)
                and words[index + 1] in ("you", "i", "we", "he", "she", "they", "it")):
            return "condition", 1
        if not mid_clause:
            return None
        length = match_phrase(words, index, self.lexicon.purpose_openers)
        if not length:
            return None
        following = words[index + length:]
        if words[index] == "to" and not (following and self.lexicon.is_verb(following[0])
                                         and not self.lexicon.rooms.get(following[0])
                                         and not following[0].endswith("ing")):
            return None  # "to the kitchen", "to recycling": a destination, not a purpose
        if words[index] == "to" and following and (following[0] in ("room", "rooms") or (
                len(following) > 1 and following[1][:1].isdigit())):
            return None  # "up to room 3.12", "to bay 4": a numbered place
        if words[index] == "so" and following and following[0] in ("much", "many"):
            return None
        return "purpose", length

    def _elliptic_put(self, words: list[str]) -> bool:
        """A list item with no verb: a noun phrase, then where it goes."""
        if self._starts_statement(words, 0) or (words and words[0] in _SUBJECTS):
            return False
        if len(words) > 1 and self.lexicon.is_verb(words[0]) and words[1] in _OBJECT_STARTS \
                and words[0] == self.lexicon.lemma(words[0]) and words[1] not in (
                    "up", "down", "off", "out", "away", "back"):
            return False  # "blare your horn in her ear": an order in a verb the robot lacks
        for index, word in enumerate(words[1:5], 1):
            if word in ("on", "in", "into", "onto", "to", "back") and not any(
                    w in _AUXILIARIES or w in _SUBJECTS for w in words[:index]):
                return not self.lexicon.is_verb(words[0]) or words[0] not in \
                    self.lexicon.verb_starts
        return False

    def _whole(self, words: list[str]) -> bool:
        """Whether the words so far make a clause of their own (an order, or a thing and its
        state), so that a directive after "and" starts another rather than finishing it."""
        return bool(words) and (self.lexicon.lemma(words[0]) in self.lexicon.verb_starts
                                or self._verbless_directive(words) is not None)

    def _directive_ahead(self, words: list[str]) -> bool:
        """Whether the words up to the next comma are a verbless directive ("..., front door
        shut and locked, ...")."""
        ends = [i for i, w in enumerate(words) if w in (",", "and")]
        return self._verbless_directive(words[:ends[0] if ends else len(words)]) is not None

    def _verbless_directive(self, words: list[str]) -> tuple[str, list[str]] | None:
        """ "Lights off downstairs", "burner three off", "back door shut and locked": a thing
        and the state it is to be left in, said without a verb; the state names the action.
        An unknown verb before its object ("wedge the door open") is not one."""
        body = [w for w in words if w not in _STRAY]
        while body and body[-1] == ",":
            body.pop()
        if len(body) < 2 or body[0] in _SUBJECTS or (
                self.lexicon.is_verb(body[0]) and body[0] == self.lexicon.lemma(body[0])
                and body[1] in _OBJECT_STARTS):
            return None
        trailing: list[str] = []
        if body[-1] in ("downstairs", "upstairs") or (
                body[-1] in self.lexicon.rooms and body[-2] in DIRECTIVE_STATES):
            trailing = ["in", body.pop()]
        if body[-1] not in DIRECTIVE_STATES:
            return None
        state = body.pop()
        if body and body[-1].endswith("'s") and body[-1] not in _SUBJECTS:
            body[-1] = body[-1][:-2]  # "the back door's locked"
            subject = " ".join(w for w in body if w not in ("the", "my", "our", "your"))
            if subject in self.names or subject in self.lexicon.people:
                return None  # "janet's off now": a person leaving, nothing to switch off
        while len(body) > 2 and body[-1] == "and" and body[-2] in DIRECTIVE_STATES:
            body = body[:-2]  # "shut and locked": the last state implies the first
        if not body or any(w in _AUXILIARIES or w in _SUBJECTS for w in body):
            return None
        return DIRECTIVE_STATES[state], [*body, *trailing]

    def _starts_statement(self, words: list[str], index: int) -> bool:
        """ "it's sticky", "the baby's crawling", "dad dozed off": a subject and a verb."""
        if index >= len(words):
            return False
        if words[index] in _SUBJECTS:
            return True
        if words[index] in _SOMEONE and index + 1 < len(words) and (
                words[index + 1] in _AUXILIARIES or words[index + 1].endswith(("s", "ed"))):
            return True  # "nobody uses it", "everyone's gone": said of people, not asked
        for position, word in enumerate(words[index: index + 4]):
            if position and word in (",", "and"):
                return False  # "fags and lighter, he's asking": the subject is past a comma
            if word in _AUXILIARIES or word.endswith(("'s", "'re", "'ll", "'ve", "'d")):
                return word not in ("let's",)
            if word.endswith("ed") and self.lexicon.is_verb(word) and word not in (
                    "red", "bed", "shed", "sled"):
                return True
        return False

    def _starts_clause(self, words: list[str], index: int) -> bool:
        if index >= len(words):
            return False
        skip = match_phrase(words, index, self.lexicon.fillers)
        skip += match_phrase(words, index + skip, self.lexicon.negations)
        if index + skip >= len(words):
            return False
        word = words[index + skip]
        following = words[index + skip + 1] if index + skip + 1 < len(words) else ""
        if self.lexicon.lemma(word) not in self.lexicon.verb_starts:
            return self.lexicon.is_verb(word) and following in _OBJECT_STARTS
        return following in _OBJECT_STARTS or word not in (
            "set", "water", "iron", "dust", "light", "stand", "rest", "plant", "file", "pack",
            "box", "bag", "bin", "park", "lap", "cover", "shower", "change", "hold", "keep")

    # One clause.
    def _clause(self, words: list[str], kind: str, opener: str | None) -> Clause | None:
        lexicon = self.lexicon
        words, manner = _manner(words, lexicon)
        negated = False
        changed = True
        while words and changed:
            changed = False
            skip = match_phrase(words, 0, lexicon.fillers)
            if skip:
                words, changed = words[skip:], True
            neg = match_phrase(words, 0, lexicon.negations)
            if neg:
                words, negated, changed = words[neg:], True, True
        if not words:
            # "He won't notice.": nothing to do, but how the rest is to be done still counts
            return Clause("", None, (), "manner", manner=manner) if manner else None
        if kind == "condition" and opener in ("while", "whilst") and len(words) > 1 and \
                words[0] == "you" and lexicon.is_verb(words[1]):
            kind, words = "step", words[1:]  # "while you go upstairs": the robot goes too
        text = " ".join(words)
        if kind != "step":
            return Clause(text, None, (), kind, negated, manner=manner, opener=opener)
        words = _indirect_request([w for w in words if w not in _STRAY])
        words = _without_adverb_pairs(words)
        if not words:
            return None
        words = _aspect_dropped(words, lexicon)
        verb, rest = self._verb(words)
        if verb is not None and verb not in ("keep", "leave") and (
                lexicon.schemas_of(verb)[:1] == ("put",) or verb in ("turn", "set", "switch",
                                                                     "crank")):
            verb, rest = _heat_setting(verb, rest)
        if verb is not None and _past_tense(words[0], lexicon) and (
                len(words) < 2 or words[1] not in ("in", "on", "off", "up", "down", "out")):
            # "Dropped my phone in the sink": said of what happened, not an order to do it.
            return Clause(text, None, (), kind, negated, manner=manner)
        if verb is not None and words[0] != lexicon.lemma(words[0]) and words[0].endswith("s"):
            # An imperative verb is never inflected: "lights off downstairs" names lights.
            directive = self._verbless_directive(words)
            if directive is not None:
                verb, rest = directive
        if (verb is None or not self.lexicon.schemas_of(verb)) and self._elliptic_put(words):
            verb, rest = "put", words  # "cushions back on the sofa": put them there
        elif verb is None or not self.lexicon.schemas_of(verb):
            directive = self._verbless_directive(words)
            if directive is not None:
                verb, rest = directive  # "burner three off", "front door shut and locked"
        if verb is None:
            return Clause(text, None, (), kind, negated, manner=manner)
        return self._arguments.read(text, verb, rest, negated, manner)

    def _verb(self, words: list[str]) -> tuple[str | None, list[str]]:
        """The verb phrase at the clause's start (longest known, then a separated particle)."""
        lexicon = self.lexicon
        first = lexicon.lemma(words[0])
        if first in ("go", "come") and len(words) > 2 and words[1] not in lexicon.particles \
                and lexicon.schemas_of(lexicon.lemma(words[1])) and words[1] != "and":
            return self._verb(words[1:])  # "go find a hanger": find one
        if not lexicon.is_verb(words[0]) and not lexicon.schemas_of(first):
            return None, words
        for length in range(min(lexicon.max_verb_words, len(words)), 1, -1):
            phrase = " ".join([first, *words[1:length]])
            if lexicon.schemas_of(phrase):
                return phrase, words[length:]
        rest = words[1:]
        # A particle after the object: "turn the stove on", "put the kettle on".
        for index, word in enumerate(rest):
            if index and word == "back" and rest[index + 1: index + 2] and lexicon.schemas_of(
                    f"{first} {rest[index + 1]}")[:1] == ("close",):
                # "screw the cap back on the bottle": screw on, and on the bottle
                return f"{first} {rest[index + 1]}", rest[:index] + rest[index + 1:]
            if word in ("and", ",") or (index and word not in lexicon.particles and match_phrase(
                    rest, index, lexicon.prepositions)):
                break
            if word in lexicon.particles and lexicon.schemas_of(f"{first} {word}") and (
                    index == 0 or word != "in" or lexicon.schemas_of(f"{first} {word}") != (
                        "go",)):
                # (a visit takes no object: "pop her in" puts her in, "pop in" visits)
                after = rest[index + 1:]
                if not after or after[0] in ("and", ",") or match_phrase(
                        after, 0, lexicon.prepositions) or after[0] in COMPLEMENTS or (
                        index == 1 and rest[0] in PERSON_PRONOUNS | {"it"}
                        and word in ("out", "up", "away", "aside")):
                    return f"{first} {word}", rest[:index] + after
        if len(rest) > 1 and rest[0] in _ADVERBIAL_PARTICLES and not schemas_go(
                lexicon, first) and not match_phrase(rest, 1, lexicon.prepositions):
            return first, rest[1:]  # "gather up the baskets": gather them
        return first, rest
