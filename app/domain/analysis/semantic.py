"""The semantic layer: hazardous situations recognised by meaning, not by listed words.

In: a `Context` (the command's clauses, the scene) and a `SemanticMatcher` built once per
analyzer from `knowledge/situation_prototypes.json` (families of short descriptions of
hazardous household and care situations, each with benign contrasts, a hazard class, severity,
preventability and the scene conditions it needs) and the static encoder of `embeddings.py`.
Each clause, and the whole command, is embedded and compared with every prototype. Out, added to
the context: when an unsafe prototype is close (>= `strong`), clearly closer than every benign
contrast (by `margin`) and its conditions hold, a hazard of unknown preventability (a likeness
is not proof, so the gate asks), with the family's own preventability only when nearly identical
(>= `certain`); when close but a condition is unknown, a critical unknown with a plain question;
when only moderately close (>= `moderate`), a hazard of unknown preventability, but only if every
condition is known to hold and the command acts on an object with a property the family is about
(sharp, toxic, medication...), so ordinary chores are never deferred on a weak likeness. A list
of everyday chores serves as extra benign contrasts for every family; any condition known false
silences the family. Fails: `load_matcher` raises
`FileNotFoundError`/`KeyError`/`ValueError` on a missing or broken knowledge file or model.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

from app.domain.analysis.context import Context
from app.domain.analysis.embeddings import EMBEDDINGS_DIR, PhraseEncoder, Vectors, load_encoder
from app.domain.analysis.knowledge_base import KNOWLEDGE_DIR
from app.domain.analysis.semantic_conditions import CONDITION_NAMES, Check, check
from app.domain.models import Category, Confidence, Level, Preventability, Severity

PROTOTYPES_FILE = "situation_prototypes.json"
# Object properties that make a moderately similar clause worth a question.
_HAZARDOUS_PROPS = frozenset({"sharp", "toxic", "corrosive", "hot", "heat_source", "medication",
                              "electrical", "flammable", "allergen", "small", "walking_aid",
                              "safety_barrier", "camera", "dangerous_in_use", "alcohol"})


@dataclass(frozen=True, slots=True)
class Family:
    """One hazardous situation family and what it needs of the scene."""

    name: str
    hazard_class: str
    category: Category
    severity: Severity
    preventability: Preventability
    requires: tuple[Mapping[str, Any], ...]
    objects: frozenset[str]


@dataclass(frozen=True, slots=True)
class Thresholds:
    """Cosine-similarity cut-offs (calibrated on the benchmark's development split only)."""

    certain: float
    strong: float
    moderate: float
    margin: float


@dataclass(frozen=True, slots=True)
class Match:
    """The nearest unsafe prototype of one text, and how much nearer than any benign one."""

    text: str
    family: Family
    prototype: str
    similarity: float
    benign_similarity: float

    @property
    def margin(self) -> float:
        return self.similarity - self.benign_similarity


class SemanticMatcher:
    """Nearest-prototype search over the situation prototypes (vectors computed once)."""

    def __init__(self, encoder: PhraseEncoder, families: list[Family],
                 prototypes: list[tuple[str, int | None]], thresholds: Thresholds) -> None:
        self.encoder = encoder
        self.families = families
        self.thresholds = thresholds
        # Unsafe prototypes first, so one slice of the similarity matrix holds each kind.
        ordered = [p for p in prototypes if p[1] is not None] + [
            p for p in prototypes if p[1] is None]
        self._texts = [text for text, _ in ordered]
        self._family_of = [f for _, f in ordered if f is not None]
        self._unsafe_count = len(self._family_of)
        self._vectors: Vectors = encoder.encode(self._texts)

    def nearest(self, texts: list[str], memo: dict[str, Match] | None = None) -> list[Match]:
        """The nearest unsafe prototype of each text, with the nearest benign similarity.

        Args:
            texts: normalised clauses or commands.
            memo: matches already computed for this request (its sentence passes repeat the
                whole command's clauses); new ones are added to it.

        Returns:
            One `Match` per text, in order.
        """
        if not self._unsafe_count:
            return []
        memo = {} if memo is None else memo
        for text in texts:
            if text not in memo:
                memo[text] = self._match(text)
        return [memo[text] for text in texts]

    def _match(self, text: str) -> Match:
        # One matrix-vector product per text: a matrix product over several texts is large
        # enough for OpenBLAS to wake its thread pool, which spins on the other cores and costs
        # more CPU than the product itself.
        similarities = self._vectors @ self.encoder.encode_one(text)
        unsafe = similarities[:self._unsafe_count]
        best = int(unsafe.argmax())
        benign = (float(similarities[self._unsafe_count:].max())
                  if len(similarities) > self._unsafe_count else -1.0)
        return Match(text=text, family=self.families[self._family_of[best]],
                     prototype=self._texts[best], similarity=float(unsafe[best]),
                     benign_similarity=benign)


@cache
def load_matcher(knowledge_dir: Path = KNOWLEDGE_DIR,
                 model_dir: Path = EMBEDDINGS_DIR) -> SemanticMatcher:
    """Build the matcher from the prototype file and the static model (once per process).

    Args:
        knowledge_dir: the folder holding `situation_prototypes.json`.
        model_dir: the folder holding the static embedding model.

    Returns:
        The `SemanticMatcher`.
    """
    raw = json.loads((knowledge_dir / PROTOTYPES_FILE).read_text(encoding="utf-8"))
    families: list[Family] = []
    prototypes: list[tuple[str, int | None]] = []
    for index, record in enumerate(raw["families"]):
        requires = tuple(dict(c) for c in record.get("requires", ()))
        unknown = {k for c in requires for k in c} - CONDITION_NAMES
        if unknown:
            raise ValueError(f"family {record['family']}: unknown conditions {sorted(unknown)}")
        families.append(Family(
            name=record["family"], hazard_class=record["hazard_class"],
            category=Category(record["category"]), severity=Severity(record["severity"]),
            preventability=Preventability(record["preventability"]), requires=requires,
            objects=frozenset(record.get("objects", ()))))
        prototypes += [(t.lower(), index) for t in record["unsafe"]]
        prototypes += [(t.lower(), None) for t in record["benign"]]
    prototypes += [(t.lower(), None) for t in raw.get("everyday_benign", ())]
    limits = raw["thresholds"]
    return SemanticMatcher(load_encoder(model_dir), families, prototypes, Thresholds(
        certain=float(limits["certain"]), strong=float(limits["strong"]),
        moderate=float(limits["moderate"]), margin=float(limits["margin"])))


def semantic_hazards(ctx: Context, matcher: SemanticMatcher,
                     memo: dict[str, Match] | None = None) -> None:
    """Add the hazards (or critical unknowns) of situations the command resembles.

    Args:
        ctx: the analysis context (proposals and unknowns are appended to it).
        matcher: the analyzer's matcher.
        memo: the request's matches so far (see `SemanticMatcher.nearest`).
    """
    texts = [step.step.text for step in ctx.steps if not step.step.negated and step.step.text]
    if not any(step.step.negated for step in ctx.steps) and ctx.text not in texts:
        texts.append(ctx.text)
    limits = matcher.thresholds
    seen: set[str] = set()
    for match in matcher.nearest(list(dict.fromkeys(texts)), memo):
        if match.margin < limits.margin or match.similarity < limits.moderate:
            continue
        if match.family.name in seen:
            continue
        checks = [check(ctx, match.text, c) for c in match.family.requires]
        if any(c.holds is False for c in checks):
            continue
        seen.add(match.family.name)
        unknown = [c for c in checks if c.holds is None]
        if match.similarity >= limits.strong:
            if unknown:
                _ask(ctx, match, unknown[0])
            else:
                _propose(ctx, match, checks, match.family.preventability
                         if match.similarity >= limits.certain else Preventability.UNKNOWN)
        elif not unknown and _hazardous_objects(ctx, match.family.objects):
            _propose(ctx, match, checks, Preventability.UNKNOWN)


def _propose(ctx: Context, match: Match, checks: list[Check],
             preventability: Preventability) -> None:
    family = match.family
    person = next((c.person for c in checks if c.person), None)
    obj = next(iter(_hazardous_objects(ctx, family.objects or _HAZARDOUS_PROPS)), None)
    ctx.add(Level.DEPLOYMENT if checks else Level.TASK, family.category, family.hazard_class,
            f"the request reads like a known hazardous situation ({family.name.replace('_', ' ')}"
            f": \"{match.prototype}\", similarity {match.similarity:.2f})",
            {"obj": obj, "person": person}, family.severity, preventability,
            Confidence.UNCERTAIN)


def _ask(ctx: Context, match: Match, unknown: Check) -> None:
    situation = match.family.name.replace("_", " ")
    ctx.unknown(unknown.attribute or "situation",
                f"whether the request is a hazardous situation ({situation})",
                critical=True,
                why=f"it reads like \"{match.prototype}\" (similarity {match.similarity:.2f}), "
                    "which is unsafe only if this holds",
                entity=unknown.entity,
                question=unknown.question or "Could you tell me more about who is around?")


def _hazardous_objects(ctx: Context, props: frozenset[str]) -> list[str]:
    """Ids of the objects the command acts on that have a property the family is about."""
    return [o.id for step in ctx.steps for referent in step.objects
            for o in ctx.objects(referent) if o.props.keys() & props]
