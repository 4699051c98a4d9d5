"""What a command involves: the scene objects and people it touches, read generously.

In: a `Context` (grounded steps, scene view, normalised command). Out: `Involvement`: the
objects and people the non-negated steps refer to, plus scene objects and people the command
names by type, name, contents or role word even when the parse missed them (a question asked
too often costs little; a danger missed costs much), with the words that named each object.
Never fails.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from itertools import pairwise

from app.domain.analysis.context import Context
from app.domain.analysis.grounding import GroundedStep, Referent
from app.domain.analysis.knowledge_base import singular
from app.domain.analysis.scene_view import ObjectView, PersonView, spaced_name
from app.domain.analysis.word_filter import TEXT_MEMO_SIZE

_TOKEN = re.compile(r"[\w'-]+")
_WORD = re.compile(r"[a-z][a-z'-]+")
_GENERIC = frozenset({"top", "side", "front", "back", "room", "area", "unit", "item", "thing",
                      "set", "pack", "small", "large", "big", "little", "one", "two"})


@dataclass(slots=True)
class Involvement:
    """Objects and people a command involves, the steps' actions and recipients, and whether
    some clause had no verb the parser knows (`unparsed`)."""

    text: str
    objects: dict[str, ObjectView] = field(default_factory=dict)
    named_by: dict[str, str] = field(default_factory=dict)
    people: dict[str, PersonView] = field(default_factory=dict)
    recipients: dict[str, PersonView] = field(default_factory=dict)
    actions: frozenset[str] = frozenset()
    unparsed: bool = False

    def words_of(self, obj: ObjectView) -> str:
        """Everything that names an object: type, name, contents and the command's phrases."""
        parts = [spaced_name(obj.type), (obj.name or "").lower(), obj.contents_text or "",
                 str(obj.properties.get("material", "")).lower(), self.named_by.get(obj.id, "")]
        return " ".join(p for p in parts if p)

    def others(self) -> list[PersonView]:
        """Involved people other than the user."""
        return [p for p in self.people.values() if not p.is_user]


def _referents(grounded: GroundedStep) -> list[Referent]:
    found = [*grounded.objects]
    for ref in (grounded.recipient, grounded.destination, grounded.target, grounded.instrument,
                grounded.source, grounded.path):
        if ref is not None:
            found.append(ref)
    return found


@lru_cache(maxsize=TEXT_MEMO_SIZE)
def phrase_set(text: str) -> frozenset[str]:
    """Words and word pairs of a text, each also in its singular (possessive 's dropped)."""
    # "grandma's" and "the boys'" both name the owner: drop the possessive either way.
    tokens = [t[:-2] if t.endswith("'s") else t.rstrip("'") for t in _TOKEN.findall(text)]
    pairs = [f"{a} {b}" for a, b in pairwise(tokens)]
    return frozenset((*tokens, *pairs, *(singular(t) for t in (*tokens, *pairs))))


def _named_object(obj: ObjectView, words: frozenset[str], concepts: set[str]) -> bool:
    # Medicines hide under many container names (pill pot, dosette, cup); naming any
    # medicine word involves every medication in the scene.
    if obj.has("medication") and "medication" in concepts:
        return True
    kind = spaced_name(obj.type)
    candidates = {kind, kind.split()[-1], (obj.name or "").lower()}
    if obj.contents_text:
        candidates |= {w for w in _WORD.findall(obj.contents_text)
                       if len(w) >= 4}
    return any(c and c not in _GENERIC and len(c) >= 3 and c in words for c in candidates)


def _named_person(ctx: Context, person: PersonView, words: frozenset[str]) -> bool:
    if person.name and (person.name.lower() in words or
                        person.name.lower().split()[-1] in words):
        return True
    role = person.role or ""
    if role and (role in words or role.split()[-1] in words):
        return True
    for word in words:
        implied = ctx.knowledge.role_words.get(word)
        if implied is None or implied.is_user:
            continue
        if implied.name == "guest":
            if person.role_class == "guest":
                return True
            continue
        same_class = implied.name == person.role_class
        same_age = implied.age_group is not None and implied.age_group == person.age_group
        if (same_class or same_age) and (implied.gender is None
                                         or person.gender in (None, implied.gender)):
            return True
    return False


def involvement(ctx: Context) -> Involvement:
    """Collect what the command involves.

    Args:
        ctx: the analysis context.

    Returns:
        The `Involvement` (objects and people in first-seen order).
    """
    found = Involvement(text=ctx.text)
    negated_only: set[str] = set()
    actions: set[str] = set()
    for grounded in ctx.steps:
        for ref in _referents(grounded):
            if grounded.step.negated:
                negated_only.update(ref.ids)
                continue
            for obj in ctx.objects(ref):
                found.objects.setdefault(obj.id, obj)
                found.named_by[obj.id] = f"{found.named_by.get(obj.id, '')} {ref.mention.text}"
            for person in ctx.people(ref):
                if not person.virtual:
                    found.people.setdefault(person.id, person)
        if grounded.step.negated:
            continue
        if grounded.step.action:
            actions.add(grounded.step.action)
        else:
            found.unparsed = True
        for person in ctx.people(grounded.recipient):
            if not person.virtual and not person.is_user:
                found.recipients.setdefault(person.id, person)
    negated_only -= set(found.objects) | set(found.people)
    for obj in named_objects(ctx, ctx.text):
        if obj.id not in negated_only:
            found.objects.setdefault(obj.id, obj)
    for person in named_people(ctx, ctx.text):
        if person.id not in negated_only:
            found.people.setdefault(person.id, person)
    found.actions = frozenset(actions)
    return found


def plain_name(obj: ObjectView) -> str:
    """The object in plain words for a question, without its scene id ("the mug of tea")."""
    words = (obj.name or spaced_name(obj.type)).lower()
    if obj.contents_text and obj.contents_text not in words:
        words = f"{words} of {obj.contents_text}"
    return f"the {words}"


def named_objects(ctx: Context, text: str) -> list[ObjectView]:
    """Scene objects a text names by type, name, contents or (for medicines) kind."""
    words = phrase_set(text)
    concepts = {c for w in words if (c := ctx.knowledge.concept_words.get(w))}
    return [o for o in ctx.view.objects.values()
            if not o.virtual and _named_object(o, words, concepts)]


def named_people(ctx: Context, text: str) -> list[PersonView]:
    """Scene people a text names by name, role or a word for their kind ("the kids")."""
    words = phrase_set(text)
    return [p for p in ctx.view.people.values()
            if not p.virtual and _named_person(ctx, p, words)]
