"""Stage 2, the Hazard Binding Layer: map each proposed hazard to templates of the library.

In: the hazard report's proposals and the active templates. Out: `BindingResult` with, for each
proposal, the templates it matched and the concrete value of every template variable, or the
reason it stayed unbound. A proposal matches a template of its hazard class whose every variable
is filled: entity variables from the proposal's `entities` (the robot is always `robot`), value
variables from the proposal or the template's default.
Fails: never; a proposal that matches nothing is unbound (the gate defers with R2).
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Mapping, Sequence

from pydantic import BaseModel, ConfigDict, field_serializer

from app.domain.models import (
    HazardProposal,
    HazardReport,
    HazardTemplate,
    TemplateScope,
    VariableType,
)

BindingValue = str | float | bool

_ENTITY_TYPES = {
    VariableType.OBJECT,
    VariableType.PERSON,
    VariableType.ROOM,
    VariableType.ROBOT,
    VariableType.ENTITY,
}


class BoundTemplate(BaseModel):
    """One template instantiated for one hazard."""

    model_config = ConfigDict(frozen=True)

    template: HazardTemplate
    bindings: dict[str, BindingValue]
    entity_variables: frozenset[str]

    @field_serializer("entity_variables")
    def _sorted(self, names: frozenset[str]) -> list[str]:
        # A set's order changes with the process's hash seed; a dump must not.
        return sorted(names)


class BoundHazard(BaseModel):
    """A proposal with every template it matched (at least one)."""

    model_config = ConfigDict(frozen=True)

    proposal: HazardProposal
    matches: tuple[BoundTemplate, ...]


class UnboundHazard(BaseModel):
    """A proposal with no usable template, and why."""

    model_config = ConfigDict(frozen=True)

    proposal: HazardProposal
    reason: str
    entities_missing: bool = False
    """The class has templates, but the proposal lacks the entities they bind."""


class BindingResult(BaseModel):
    model_config = ConfigDict(frozen=True)

    bound: tuple[BoundHazard, ...] = ()
    unbound: tuple[UnboundHazard, ...] = ()


class TemplateIndex:
    """Active templates grouped by hazard class, built once per library version."""

    def __init__(self, templates: Iterable[HazardTemplate]) -> None:
        by_class: dict[str, list[HazardTemplate]] = defaultdict(list)
        for template in templates:
            by_class[template.hazard_class].append(template)
        self._by_class = {k: sorted(v, key=lambda t: t.id) for k, v in by_class.items()}
        self.templates: tuple[HazardTemplate, ...] = tuple(
            t for group in self._by_class.values() for t in group
        )
        self.always: tuple[BoundTemplate, ...] = tuple(
            BoundTemplate(template=t, bindings=_instantiate(t, {})[0],
                          entity_variables=frozenset())
            for t in self.templates if t.applies is TemplateScope.ALWAYS)
        """The baseline envelope: templates bound into every contract."""

    def for_class(self, hazard_class: str) -> Sequence[HazardTemplate]:
        return self._by_class.get(hazard_class, ())

    def covers(self, hazard_class: str) -> bool:
        return hazard_class in self._by_class

    def __len__(self) -> int:
        return len(self.templates)


def bind(report: HazardReport, index: TemplateIndex) -> BindingResult:
    """Bind every proposal of a hazard report to the templates of its hazard class.

    Args:
        report: Stage 1's output.
        index: the active templates.

    Returns:
        Bound hazards (with every matching template instantiated) and unbound ones with a reason.
    """
    bound: list[BoundHazard] = []
    unbound: list[UnboundHazard] = []
    for proposal in report.proposals:
        candidates = index.for_class(proposal.hazard_class)
        if not candidates:
            unbound.append(
                UnboundHazard(
                    proposal=proposal,
                    reason=f"no active template for hazard class {proposal.hazard_class!r}",
                )
            )
            continue
        if proposal.template_id is not None:
            candidates = sorted(candidates, key=lambda t: t.id != proposal.template_id)
        matches: list[BoundTemplate] = []
        misses: list[str] = []
        for template in candidates:
            bindings, missing = _instantiate(template, proposal.entities)
            if missing:
                misses.append(f"{template.id} needs {', '.join('$' + m for m in missing)}")
            else:
                matches.append(
                    BoundTemplate(
                        template=template,
                        bindings=bindings,
                        entity_variables=frozenset(
                            v.name for v in template.variables if v.type in _ENTITY_TYPES
                        ),
                    )
                )
        if matches:
            bound.append(BoundHazard(proposal=proposal, matches=tuple(matches)))
        else:
            unbound.append(UnboundHazard(proposal=proposal, reason="; ".join(misses),
                                         entities_missing=True))
    return BindingResult(bound=tuple(bound), unbound=tuple(unbound))


def _instantiate(
    template: HazardTemplate, entities: Mapping[str, str]
) -> tuple[dict[str, BindingValue], list[str]]:
    bindings: dict[str, BindingValue] = {}
    missing: list[str] = []
    for variable in template.variables:
        if variable.type is VariableType.ROBOT:
            bindings[variable.name] = entities.get(variable.name, "robot")
        elif variable.name in entities:
            bindings[variable.name] = entities[variable.name]
        elif variable.default is not None:
            bindings[variable.name] = variable.default
        else:
            missing.append(variable.name)
    return bindings, missing
