"""The live Hazard Template Library as the LLM sees it: the classes it may propose, and checks.

In: the active templates the pipeline passes to the analyzer (seed and curator-written alike).
Out: `LibraryView`: one prompt line per hazard class (category, a one-line meaning, the entity
variables its templates bind), the set of known classes, whether a hazard's entities bind any of
its class's templates (`lacks_ids`), a digest for cache keys, and `class_problems`, the repair
message for a class the library does not hold. A curator's new class is offered on the very next
request.
The unknowns' attribute names are held to the list `/answers` applies (`ANSWERABLE_ATTRIBUTES`):
`attributes_text` offers them, `attribute_problems` sends any other name back for repair.
Fails: never; an empty library gives an empty view, and then no class can be checked (every
hazard stays unbound and the gate defers with R2).
"""

from __future__ import annotations

import difflib
import hashlib
from collections import defaultdict
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

from app.adapters.llm.schemas import ENTITY_NAMES, MatrixHazard, MatrixUnknown
from app.domain.analysis.answers import ANSWERABLE_ATTRIBUTES
from app.domain.models import HazardTemplate, TemplateStatus, VariableType

_MEANING_CHARS = 100
_BINDABLE = {VariableType.OBJECT, VariableType.PERSON, VariableType.ROOM, VariableType.ENTITY}


def _needed_entities(template: HazardTemplate) -> frozenset[str]:
    return frozenset(
        v.name for v in template.variables if v.type in _BINDABLE and v.default is None
    )


def _meaning(group: Sequence[HazardTemplate]) -> str:
    # The templates' titles name the situations a class covers, in a few words each; their
    # descriptions would triple the prompt for little the class name does not already say.
    titles = list(dict.fromkeys(" ".join(t.name.split()) for t in group))
    line = "; ".join(titles)
    if len(line) > _MEANING_CHARS:
        line = line[: _MEANING_CHARS - 1].rstrip(" ;,") + "…"
    return line


@dataclass(frozen=True)
class LibraryView:
    """What the analyzer tells the model about the library and checks its answers against."""

    lines: tuple[str, ...]
    classes: frozenset[str]
    needed: dict[str, tuple[frozenset[str], ...]]
    """Per class, the entity variables each of its templates needs filled."""

    @classmethod
    def of(cls, templates: Iterable[HazardTemplate]) -> LibraryView:
        """Build the view of the active templates.

        Args:
            templates: the library as the pipeline passed it.

        Returns:
            The view; classes in category order, then alphabetically.
        """
        by_class: dict[str, list[HazardTemplate]] = defaultdict(list)
        for template in templates:
            if template.status is TemplateStatus.ACTIVE:
                by_class[template.hazard_class].append(template)
        lines: list[str] = []
        needed_by_class: dict[str, tuple[frozenset[str], ...]] = {}
        category = ""
        for hazard_class in sorted(by_class, key=lambda c: (by_class[c][0].category.value, c)):
            # Templates matched by the task before the always-on baseline: they say more.
            group = sorted(by_class[hazard_class],
                           key=lambda t: (t.applies.value != "matched", t.id))
            needed = [_needed_entities(t) for t in group]
            needed_by_class[hazard_class] = tuple(needed)
            names = sorted(set().union(*needed) & set(ENTITY_NAMES))
            if group[0].category.value != category:
                category = group[0].category.value
                lines.append(f"{category}:")
            binds = f" [{', '.join(names)}]" if names else ""
            lines.append(f"- {hazard_class}: {_meaning(group)}{binds}")
        return cls(tuple(lines), frozenset(by_class), needed_by_class)

    def lacks_ids(self, hazard_class: str, entities: Mapping[str, str]) -> bool:
        """Whether a hazard of a library class cannot bind any template with these entities.

        Args:
            hazard_class: the hazard's class.
            entities: the entity variables it fills.

        Returns:
            True when the class has templates and each needs an entity the hazard lacks.
        """
        needed = self.needed.get(hazard_class, ())
        return bool(needed) and not any(n <= entities.keys() for n in needed)

    def prompt_text(self) -> str:
        """The class list for the system prompt."""
        return "\n".join(self.lines) or "- (the library is empty: every class is new)"

    @property
    def digest(self) -> str:
        """A short digest of the class list, part of the analysis cache key."""
        return hashlib.sha256("\n".join(self.lines).encode()).hexdigest()[:12]

    def class_problems(self, hazards: Sequence[MatrixHazard]) -> list[str]:
        """Why some hazards' classes cannot be used as written (empty when all can).

        A class outside the library is accepted only when the model marks it `new_class`,
        so a misspelling is sent back for repair instead of deferring as a library gap.

        Args:
            hazards: one level's hazards.

        Returns:
            One problem per unusable class, with the closest library classes.
        """
        if not self.classes:
            return []
        problems: list[str] = []
        for number, hazard in enumerate(hazards):
            if hazard.hazard_class in self.classes or hazard.new_class:
                continue
            close = difflib.get_close_matches(hazard.hazard_class, sorted(self.classes), n=3)
            hint = f" (closest: {', '.join(close)})" if close else ""
            problems.append(
                f"hazards[{number}].hazard_class = {hazard.hazard_class!r} is not a class of the "
                f"library{hint}; use a listed class, or set new_class to true if none fits"
            )
        return problems


def attributes_text() -> str:
    """The unknown attributes the model may use, by what they are about, for the prompt."""
    by_subject: dict[str, list[str]] = defaultdict(list)
    for attribute, subject in ANSWERABLE_ATTRIBUTES.items():
        by_subject[subject].append(attribute)
    return "\n".join(f"- about {subject}: {', '.join(sorted(names))}"
                     for subject, names in sorted(by_subject.items()))


def attribute_problems(unknowns: Sequence[MatrixUnknown], *, scene: bool) -> list[str]:
    """Why some unknowns cannot be asked as written (empty when all can).

    Args:
        unknowns: one level's unknowns.
        scene: whether the level sees the scene (then an object's unknown must name its id).

    Returns:
        One problem per unusable unknown.
    """
    problems: list[str] = []
    for number, unknown in enumerate(unknowns):
        subject = ANSWERABLE_ATTRIBUTES.get(unknown.attribute)
        if subject is None:
            close = difflib.get_close_matches(unknown.attribute, list(ANSWERABLE_ATTRIBUTES), n=3)
            hint = f" (closest: {', '.join(close)})" if close else ""
            problems.append(f"unknowns[{number}].attribute = {unknown.attribute!r} is not one of "
                            f"the listed attributes{hint}")
        elif subject == "object" and scene and not unknown.entity:
            problems.append(f"unknowns[{number}].entity: name the object id that "
                            f"{unknown.attribute!r} is about")
    return problems
