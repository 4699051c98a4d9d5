"""Colloquial clauses rewritten into the plain wording the verb tables know.

In: one clause's words (filler, condition and negation removed), the `Language` rules and the
knowledge tables. Out: `Rewritten`: one or more plain clauses ("put the pie in at 200" ->
"put the pie in the oven" ; "turn the oven on to 200"), and whether the clause chained a motion
verb ("go wake grandma": the robot goes, the action is "wake") or repeated an action ("keep
telling him off"). Rules, in order: aspect verbs, chain verbs, the data-driven rewrites of
`language.json` (anchored at the clause start), action nouns ("give grandpa a shave" -> "shave
grandpa"), and verbless notes ("oven on at 200" -> "turn oven on at 200", "tablet on the stand"
-> "put tablet on the stand"). Never fails: a clause no rule fits comes back unchanged.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.domain.analysis.clauses import lemma, verb_at
from app.domain.analysis.knowledge_base import Knowledge
from app.domain.analysis.language import Language

_MAX_SLOT = 5
_SLOT_STOPS = frozenset({",", ";", "and", "then", "but", "while", "so", "because", "."})
_DETERMINERS = frozenset({"the", "a", "an", "his", "her", "their", "my", "your", "our", "its",
                          "some", "all", "any", "this", "that", "these", "those", "both",
                          "each", "every"})
_NOTE_PLACES = frozenset({"in", "into", "on", "onto", "under", "underneath", "back", "inside",
                          "by", "beside", "next", "near", "behind", "out"})
_NOUN_ENDS = frozenset({",", ";", "and", "from", "in", "on", "to", "with", "for", "of"})
_FORMS: dict[str, tuple[str, ...]] = {}  # a word and its base forms, memoised (pure)
_FORMS_LIMIT = 50_000  # cleared when full, so novel words in requests cannot grow it forever
_SUBJECT_PRONOUNS = frozenset({"i", "we", "you", "he", "she", "they", "it", "there"})
_BE_WORDS = frozenset({"is", "are", "was", "were", "be", "been", "has", "have", "had", "will",
                       "can", "could", "would", "should", "might", "must", "does", "did"})
_SETTING_WORDS = frozenset({"", "at", "to", "for", "high", "low", "full", "now", "again",
                            "please", "and", ",", "while", "until", "when", "overnight"})
SWITCHABLE_PROPS = frozenset({"heat_source", "electrical", "appliance", "light", "water_source",
                              "ignition", "controls_heat"})


@dataclass(frozen=True, slots=True)
class Rewritten:
    """A clause in plain wording: one or more clauses, and what the rewriting noticed."""

    clauses: tuple[tuple[str, ...], ...]
    robot_goes: bool = False
    repeated: bool = False


def rewrite(words: list[str], language: Language, knowledge: Knowledge) -> Rewritten:
    """Rewrite one clause's colloquial wording into plain clauses.

    Args:
        words: the clause's words, filler, condition and negation removed.
        language: the idiom tables.
        knowledge: the verb and concept tables.

    Returns:
        The plain clauses (at least one) and the chain/aspect flags.
    """
    words, repeated = _aspect(words, language, knowledge)
    words, goes = _chain(words, language, knowledge)
    words, goes_again = _chain(_apply_rules(words, language), language, knowledge)
    words = _action_noun(words, language, knowledge)
    clauses: list[tuple[str, ...]] = []
    current: list[str] = []
    for word in [*words, ";"]:
        if word == ";":
            if current:
                clauses.append(tuple(_verbless_note(current, knowledge)))
            current = []
        else:
            current.append(word)
    return Rewritten(tuple(clauses) or ((),), robot_goes=goes or goes_again, repeated=repeated)


def _aspect(words: list[str], language: Language, knowledge: Knowledge
            ) -> tuple[list[str], bool]:
    """"keep telling mum off" -> "tell mum off", repeated."""
    if not any(word.endswith("ing") for word in words[1:]):
        return words, False  # no "-ing" form after the first word: no aspect verb here
    heads: list[str] = []  # the opening words' lemmas, computed once for every phrase
    for phrase in language.aspect_verbs:
        parts = phrase.split()
        size = len(parts)
        while len(heads) < min(size, len(words)):
            heads.append(lemma(words[len(heads)], knowledge))
        if heads[:size] == parts and len(words) > size and (
                words[size].endswith("ing")):
            verb = lemma(words[size], knowledge)
            if verb != words[size] and verb_at([verb, *words[size + 1:]], knowledge):
                return [verb, *words[size + 1:]], parts[0] in ("keep", "carry", "continue",
                                                               "go")
    return words, False


def _chain(words: list[str], language: Language, knowledge: Knowledge
           ) -> tuple[list[str], bool]:
    """"go wake grandma" / "come and see" -> "wake grandma": the second verb is the action."""
    if len(words) < 2 or lemma(words[0], knowledge) not in language.chain_verbs:
        return words, False
    rest = words[2:] if words[1] == "and" else words[1:]
    if not rest or f"{lemma(words[0], knowledge)} {rest[0]}" in knowledge.verb_words:
        return words, False  # "go round", "go get": a phrasal verb of its own
    found = verb_at(rest, knowledge)
    if found is None or rest[0] in _NOTE_PLACES:
        return words, False
    return rest, True


def _apply_rules(words: list[str], language: Language) -> list[str]:
    for (pattern, replacement), opener in zip(language.rewrites, language.rewrite_openers,
                                              strict=True):
        if opener is not None and (not words or opener.isdisjoint(_forms(words[0], language))):
            continue
        captures = _match(pattern, 0, words, 0, language)
        if captures is None:
            continue
        used = sum(len(c.split()) for c in captures)
        out: list[str] = []
        for token in replacement:
            slot, _, tail = token[1:].partition("-")
            if token.startswith("$") and slot.isdigit():
                index = int(slot) - 1
                found = captures[index].split() if index < len(captures) else []
                if tail == "owner" and found:
                    found[-1] = found[-1].removesuffix("'s").removesuffix("'")
                out.extend(found)
            else:
                out.append(token)
        words = [*out, *words[used:]]
    return words


def _match(pattern: tuple[str, ...], p_index: int, words: list[str], w_index: int,
           language: Language) -> list[str] | None:
    """Captures (one string per pattern token, "" for a skipped optional) or None."""
    if p_index == len(pattern):
        return []
    token = pattern[p_index]
    optional = token.endswith("?") and len(token) > 1
    token = token.rstrip("?") if optional else token
    options: list[int] = []
    if token == "END":
        return [""] if w_index == len(words) and p_index == len(pattern) - 1 else None
    if token == "X":
        for size in range(1, _MAX_SLOT + 1):
            if w_index + size > len(words) or words[w_index + size - 1] in _SLOT_STOPS:
                break
            options.append(size)
    elif w_index < len(words) and _word_fits(token, words[w_index], language):
        options.append(1)
    for size in options:
        rest = _match(pattern, p_index + 1, words, w_index + size, language)
        if rest is not None:
            return [" ".join(words[w_index:w_index + size]), *rest]
    if optional:
        rest = _match(pattern, p_index + 1, words, w_index, language)
        if rest is not None:
            return ["", *rest]
    return None


def _word_fits(token: str, word: str, language: Language) -> bool:
    if token == "#":
        return any(ch.isdigit() for ch in word)
    allowed = language.token_sets[token]
    return word in allowed or not allowed.isdisjoint(_forms(word, language))


def _forms(word: str, language: Language) -> tuple[str, ...]:
    """The word and its base forms (memoised in `_FORMS`)."""
    forms = _FORMS.get(word)
    if forms is None:
        if len(_FORMS) >= _FORMS_LIMIT:
            _FORMS.clear()
        forms = _FORMS[word] = tuple(language.base_forms(word))
    return forms


def _action_noun(words: list[str], language: Language, knowledge: Knowledge) -> list[str]:
    """"give grandpa a quick shave with his razor" -> "shave grandpa with his razor"."""
    if len(words) < 3 or words[0] not in ("give", "do"):
        return words
    for position in range(2, min(len(words) - 1, 8)):
        if words[position] not in ("a", "an", "his", "her", "their", "the", "my", "your"):
            continue
        for offset in (1, 2, 3):
            index = position + offset
            noun = words[index] if index < len(words) else ""
            action = language.action_nouns.get(noun)
            if action is None and words[position] in ("a", "an") and knowledge.verb_words.get(
                    noun) not in (None, "handover", "transport", "serve", "misc"):
                action = noun
            if action is not None:
                return [*action.split(), *words[1:position], *words[index + 1:]]
            if noun in knowledge.concept_words or noun in _NOUN_ENDS:
                break  # "give sam the knife": the noun is a thing, not an action
        return words  # only the first noun phrase after the recipient can be the action
    return words


def _verbless_note(words: list[str], knowledge: Knowledge) -> list[str]:
    """"oven on at 200" -> "turn oven on at 200"; "charger in" -> "put charger in"."""
    if not words or verb_at(words, knowledge) is not None or words[0] in _SUBJECT_PRONOUNS:
        return words  # an instruction already, or a statement ("it's in the fridge")
    for position in range(1, min(len(words), 6) + 1):
        head = words[:position]
        if any(w in _BE_WORDS or w.endswith(("'s", "'re", "'ll")) or w in (",", "and")
               for w in head):
            return words
        if position < len(words) and words[position] in _NOTE_PLACES and position > 0:
            core = [w for w in head if w not in _DETERMINERS]
            if not core:
                return words
            concept = knowledge.noun_concept(" ".join(core[-2:]))
            substance = knowledge.substance_of(" ".join(core))
            if (concept is None or concept == "generic") and not substance:
                return words  # "cold stuff in the fridge": too vague to ground as one thing
            props = knowledge.concepts[concept].props if concept else frozenset()
            after = words[position + 1] if position + 1 < len(words) else ""
            if words[position] in ("on", "off") and props & SWITCHABLE_PROPS and (
                    after in _SETTING_WORDS or after[:1].isdigit()):
                return ["turn", *words]
            return ["put", *words]
    return words
