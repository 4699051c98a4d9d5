"""Declared rules: what a simulated trace cannot show, stated once with an id and a template.

In: the grounded clauses, the reading's manner cues and the state. Out: `Declared` proposals,
each naming the rule that fired and the template (hazard class, category and severity come from
that template, never from the words that found it). What belongs here and nowhere else: intent
(a person hit, frightened, humiliated, confined; a goal or purpose that states harm), covert
recording and deception. Everything a trace can show (a knife in a child's hand, liquid on a
laptop, an allergen eaten) is left to the templates and the simulation.
Fails: never; a rule whose template is not in the active library yields a proposal that stays
unbound (the gate then defers, R2).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from app.domain.analysis.arguments import Clause
from app.domain.analysis.lexicon import Lexicon
from app.domain.analysis.schemas import Grounded


@dataclass(frozen=True, slots=True)
class DeclaredRule:
    """A rule for what no trace shows: its hazard class (from the taxonomy,
    `templates_db/taxonomy/hazard_classes.yaml`), the template that states it, and its meaning."""

    hazard_class: str
    template_id: str
    meaning: str


RULES: dict[str, DeclaredRule] = {
    "harm_person": DeclaredRule("deliberate_harm", "intent.harm_to_person",
                                "the command tells the robot to hurt someone"),
    "frighten_person": DeclaredRule("startling", "intent.frighten_person",
                                    "the command tells the robot to frighten or startle "
                                    "someone"),
    "intimidate_person": DeclaredRule("intimidation", "intent.intimidate_person",
                                      "the command tells the robot to threaten, chase or "
                                      "crowd someone"),
    "humiliate_person": DeclaredRule("dignity_violation", "intent.humiliate_person",
                                     "the command tells the robot to mock, scold or shame "
                                     "someone"),
    "restrain_person": DeclaredRule("confinement", "intent.restrain_person",
                                    "the command tells the robot to confine or hold someone "
                                    "against their will"),
    "covert_surveillance": DeclaredRule("surveillance", "intent.covert_surveillance",
                                        "the command tells the robot to watch, record or "
                                        "search someone's things covertly"),
    "private_information": DeclaredRule("privacy_intrusion", "privacy.private_information_read",
                                        "the command has the robot read, record or pass on "
                                        "another person's private things"),
    "harmful_goal": DeclaredRule("harmful_intent", "intent.harmful_goal",
                                 "the command states harm as its goal"),
    "harmful_purpose": DeclaredRule("harmful_intent", "intent.harmful_purpose",
                                    "a step is done for a harmful purpose"),
    "deception": DeclaredRule("dignity_violation", "intent.deception",
                              "the command hides what the robot does from the person it is "
                              "done to"),
}
_SCHEMA_RULES = {"harm": "harm_person", "frighten": "frighten_person",
                 "intimidate": "intimidate_person", "humiliate": "humiliate_person",
                 "restrain": "restrain_person", "spy": "covert_surveillance"}
_PERSON_ACTING = frozenset({"give", "feed", "fetch", "put", "mix", "make", "record", "find",
                            "assist", "spy", "go", "pour"})
# Getting rid of someone else's things behind their back ("bin grandad's letters, he won't
# notice") deceives them as much as doing something to them does.
_DISPOSING = frozenset({"discard", "remove", "throw", "break"})
_SEARCHING = frozenset({"record", "find", "spy", "go"})


def _someone_elses(item: Grounded) -> bool:
    """Whether the things, or where they are kept ("in grandpa's drawer"), are someone
    else's."""
    places = [r for r in (item.source, item.destination) if r is not None]
    return any(r.phrase.possessor not in (None, "me", "us") for r in (*item.objects, *places))


@dataclass(frozen=True, slots=True)
class Declared:
    """A declared rule that fired, with what it is about."""

    rule: str
    template_id: str
    entities: dict[str, str]
    words: str


def _words(text: str) -> set[str]:
    return set(text.replace("'", " ").split())


_PROTECTIVE = frozenset({"not", "no", "nobody", "never", "avoid", "safe", "safely", "prevent",
                         "without", "nothing", "none", "stop", "cannot"})


def harm_stated(text: str, lexicon: Lexicon) -> bool:
    """Whether the words state harm as wanted ("cause property damage", "so she gets hurt"),
    not as something to avoid ("so nobody trips", "so it doesn't spill")."""
    words = _words(text)
    if words & _PROTECTIVE or any(w.endswith("n't") or (w.endswith("nt") and w in (
            "dont", "doesnt", "wont", "cant")) for w in text.split()):
        return False
    if words & lexicon.harm_words:
        return True
    return any(" " in phrase and phrase in text for phrase in lexicon.harm_words)


_READING = frozenset({"record", "communicate", "find", "spy"})
_OWN = frozenset({"me", "us", "you", "my", "our", "your", "i", "we"})


def _someone_elses_private_thing(item: Grounded, lexicon: Lexicon) -> str | None:
    """The owner named for a private thing the clause reads, records or passes on ("read
    her messages", "photograph the lodger's paperwork"), if it is not the speaker."""
    second = item.clause.second
    # "read her messages": "her" may have been read as the one read to
    ambiguous_her = second is not None and second.pronoun == "her"
    phrases = [ref.phrase for ref in item.objects]
    if item.schema in ("record", "find", "spy"):
        phrases += [np for _, np in item.clause.roles]  # "photos of whatever's on his desk"
    for phrase in phrases:
        head = (phrase.head or "").rstrip("s") if phrase.head not in lexicon.private_things \
            else phrase.head
        possessor = phrase.possessor or ("her" if ambiguous_her else None)
        if possessor and possessor not in _OWN and (
                head in lexicon.private_things or phrase.head in lexicon.private_things):
            return possessor
    return None


def _at_someone(item: Grounded) -> bool:
    """ "flash your lights in his face": the act is aimed at a person the words point to,
    even when no one of the scene could be named."""
    unresolved = [r.phrase for r in item.objects if r.kind != "object"]
    return any(p.pronoun in ("him", "her", "them") for p in unresolved) or any(
        np.pronoun in ("him", "her", "them") or np.possessor in ("him", "her")
        for _, np in item.clause.roles)


def declared(grounded: Sequence[Grounded], conditions: Sequence[Clause], manner: frozenset[str],
             lexicon: Lexicon) -> list[Declared]:
    """Every declared rule that fires on a command.

    Args:
        grounded: the command's step clauses, grounded.
        conditions: its condition and purpose clauses.
        manner: the manner cues of the whole command.
        lexicon: the reader's vocabulary (harm words, harmful purposes).

    Returns:
        The rules that fired (at most once per rule and entity).
    """
    found: dict[tuple[str, str], Declared] = {}

    def fire(rule: str, words: str, entities: dict[str, str]) -> None:
        key = (rule, ",".join(sorted(entities.values())))
        found.setdefault(key, Declared(rule, RULES[rule].template_id, entities, words))

    earlier: list[str] = []
    for item in grounded:
        rule = _SCHEMA_RULES.get(item.schema or "")
        # "creep up behind dad and blast your horn": the fright is aimed at whoever the
        # command named last.
        people = item.persons() or earlier[-1:]
        if rule is not None and (people or item.schema == "spy" or _at_someone(item)) \
                and not item.clause.negated:
            fire(rule, item.clause.text, {"person": people[0]} if people else {})
        earlier += item.persons()
        if "covert" in item.clause.manner | manner and (item.schema in _PERSON_ACTING or (
                item.schema in _DISPOSING and _someone_elses(item))):
            target = people[0] if people else None
            fire("covert_surveillance" if item.schema in _SEARCHING
                 else "deception", item.clause.text, {"person": target} if target else {})
    for item in grounded:
        if item.schema in _READING and not item.clause.negated:
            owner = _someone_elses_private_thing(item, lexicon)
            if owner is not None:
                fire("private_information", item.clause.text, {})
    for clause in conditions:
        # "so nobody trips" names the harm to avoid it; "so she can't get up" wants it.
        if clause.kind == "purpose" and (harm_stated(clause.text, lexicon) or (
                "harmful_purpose" in clause.manner and not clause.negated
                and not _words(clause.text) & _PROTECTIVE)):
            fire("harmful_purpose", clause.text, {})
    return list(found.values())
