"""Which-one choices that decide whether a task is safe.

In: the `Context`, the command's `Involvement` and the `UnknownRules` tables (`choices.*`).
Out: a critical `referent` unknown when the command names one thing of a kind and the scene
holds several of that kind that differ in danger (a glass cleaner and a caustic oven cleaner,
juice and a rum punch, a fruit knife and a cleaver) and nothing in the command tells them
apart; and `open_choice_items`, the foods a store holds when the command leaves the choice of
food open ("lunch from whatever is in the fridge"), so the consumer rules weigh each of them.
Never fails.
"""

from __future__ import annotations

import re

from app.domain.analysis.context import Context
from app.domain.analysis.involvement import Involvement, phrase_set, plain_name
from app.domain.analysis.knowledge_base import singular
from app.domain.analysis.scene_view import ObjectView, spaced_name
from app.domain.analysis.traits import traits_of
from app.domain.analysis.unknown_rules import UnknownRules, has_phrase

_TRUE = ("true", "1", "yes")
_TOKEN = re.compile(r"[\w'-]+")
_MEDICINE = "medicine"


def danger_profile(ctx: Context, obj: ObjectView, rules: UnknownRules) -> frozenset[str]:
    """The dangers an object carries, from its traits, its flags and the words of its contents.

    Args:
        ctx: the analysis context (knowledge tables).
        obj: the object.
        rules: the unknowns tables.

    Returns:
        The danger traits (toxic, corrosive, alcohol, sharp, medication...), possibly empty.
    """
    wanted = rules.group("choices.danger_traits")
    traits = traits_of(ctx, obj, None)
    found = {t for t in wanted if traits.has(t)}
    for key, trait in rules.mapping("choices.danger_properties").items():
        if str(obj.properties.get(key, "")).lower() in _TRUE:
            found.add(trait)
    contents = (obj.contents_text or "").lower()
    if contents:
        knowledge = ctx.knowledge
        for word in phrase_set(contents):
            name = knowledge.substance_words.get(word)
            if name is not None:
                found |= {p for p in knowledge.substances[name].props if p in wanted}
        if has_phrase(contents, rules.group("choices.danger_content_words")):
            found.add("named_danger")
    return frozenset(found)


def same_kind_unknowns(ctx: Context, inv: Involvement, rules: UnknownRules) -> None:
    """Ask which one is meant when one named thing has candidates that differ in danger."""
    covered = {i for u in ctx.unknowns if u.attribute == "referent" and u.critical
               for i in (u.entity or "").split("|")}
    skipped = set(rules.group("choices.skipped_concepts"))
    groups: dict[str, list[ObjectView]] = {}
    for obj in inv.objects.values():
        if obj.virtual or obj.concept is None or obj.concept in skipped or obj.has("fixed"):
            continue
        # Medicines are one kind whatever holds them, and never interchangeable.
        kind = _MEDICINE if obj.has("medication") else obj.concept
        groups.setdefault(kind, []).append(obj)
    words = phrase_set(inv.text)
    everything = has_phrase(inv.text, rules.group("choices.all_words")) is not None
    for kind, candidates in groups.items():
        if len(candidates) < 2 or everything or all(c.id in covered for c in candidates):
            continue
        if kind != _MEDICINE and not _named_once(ctx, inv.text, kind):
            continue
        if told_apart(candidates, words):
            continue
        profiles = {danger_profile(ctx, c, rules) for c in candidates}
        if len(profiles) < 2 and kind != _MEDICINE:
            continue
        names = " or ".join(plain_name(c) for c in candidates[:4])
        ctx.unknown("referent", f"which of {names} is meant", critical=True,
                    why="the candidates differ in danger: one is harmful, another is not",
                    entity="|".join(c.id for c in candidates),
                    question=f"Which one do you mean: {names}?")


def _named_once(ctx: Context, text: str, concept: str) -> bool:
    """Whether the command names the kind in the singular ("the jug", not "the jugs")."""
    tokens = [t[:-2] if t.endswith("'s") else t.rstrip("'") for t in _TOKEN.findall(text)]
    words = ctx.knowledge.concept_words
    hits = [t for t in tokens if concept in (words.get(t), words.get(singular(t)))]
    return bool(hits) and all(singular(t) == t for t in hits)


def told_apart(candidates: list[ObjectView], words: frozenset[str]) -> bool:
    """Whether the command's words name what exactly one candidate is, holds or whose it is.

    Args:
        candidates: the objects one phrase may mean.
        words: the phrase set (`phrase_set`) of the command or of the naming phrase.

    Returns:
        True when exactly one candidate is singled out.
    """
    # A name that only repeats the kind ("jar" for a jar) marks nothing out.
    kind_words = {w for c in candidates for w in phrase_set(spaced_name(c.type))}

    def marks(obj: ObjectView) -> set[str]:
        found = {w for w in phrase_set(obj.contents_text or "") if len(w) >= 4}
        for label in (obj.name, obj.owner):
            if label:
                found |= phrase_set(label.lower())
        return found - kind_words
    named = [c for c in candidates if marks(c) & words]
    return len(named) == 1


def open_choice_items(ctx: Context, inv: Involvement, rules: UnknownRules) -> list[ObjectView]:
    """Foods held in an involved store when the command leaves the choice of food open.

    Args:
        ctx: the analysis context.
        inv: what the command involves.
        rules: the unknowns tables.

    Returns:
        The held foods not already involved (empty when the choice is not open).
    """
    if has_phrase(inv.text, rules.group("choices.open_choice_words")) is None:
        return []
    stores = set(inv.objects)
    return [o for o in ctx.view.objects.values()
            if not o.virtual and o.id not in inv.objects and stores & set(o.holders)
            and (o.has("food") or o.has("allergen") or o.has("consumable")
                 or o.properties.get("allergens"))]
