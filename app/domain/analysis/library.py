"""The template library compiled for judging traces: each condition once, its variables open.

In: `HazardTemplate`s (seed or curator-written, any version). Out: `JudgedTemplate`s whose
conditions are compiled with their value variables substituted by their defaults and their entity
variables left open as evaluation-time arguments (`$obj` is read like a guard's `@object`), so one
compiled condition serves every binding. `LibraryCache.get(template)` compiles a template version
once per process. Templates marked `analysis: declared` are bound only by declared rules and are
not judged on traces. Fails: a condition that does not parse gives `None` for that template (a
library defect the template validation reports; the judge skips it rather than guess).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from app.domain.errors import FormulaError
from app.domain.formula import ActionArg, CompiledFormula, compile_formula, parse, substitute
from app.domain.models import (
    AnalysisUse,
    ConditionKind,
    HazardTemplate,
    TemplateCondition,
    VariableType,
)

ENTITY_VARIABLE_TYPES = frozenset({VariableType.OBJECT, VariableType.PERSON, VariableType.ROOM,
                                   VariableType.ENTITY})


@dataclass(frozen=True, slots=True)
class JudgedCondition:
    """One condition, compiled with its entity variables open."""

    condition: TemplateCondition
    kind: ConditionKind
    compiled: CompiledFormula


@dataclass(frozen=True, slots=True)
class JudgedTemplate:
    """A template ready to be checked on traces under many bindings."""

    template: HazardTemplate
    variables: tuple[tuple[str, VariableType], ...]
    every_state: tuple[JudgedCondition, ...]
    guards: Mapping[str, tuple[JudgedCondition, ...]]

    @property
    def id(self) -> str:
        return self.template.id


def _compile(template: HazardTemplate) -> JudgedTemplate | None:
    variables = tuple((v.name, v.type) for v in template.variables
                      if v.type in ENTITY_VARIABLE_TYPES)
    types = {v.name: v.type.value for v in template.variables}
    bindings: dict[str, object] = {v.name: v.default for v in template.variables
                                   if v.type not in ENTITY_VARIABLE_TYPES
                                   and v.type is not VariableType.ROBOT
                                   and v.default is not None}
    bindings.update({name: ActionArg(f"${name}") for name, _ in variables})
    bindings.update({v.name: "robot" for v in template.variables
                     if v.type is VariableType.ROBOT})
    every: list[JudgedCondition] = []
    guards: dict[str, list[JudgedCondition]] = {}
    try:
        for kind, condition in template.conditions():
            formula = substitute(parse(condition.formula), bindings, variables=types)
            judged = JudgedCondition(condition, kind, compile_formula(formula))
            if kind is ConditionKind.GUARD:
                guards.setdefault(condition.action or "", []).append(judged)
            else:
                every.append(judged)
    except FormulaError:
        return None
    return JudgedTemplate(template, variables, tuple(every),
                          {k: tuple(v) for k, v in guards.items()})


def judged_in_analysis(template: HazardTemplate) -> bool:
    """Whether the judge checks the template on traces (not `analysis: declared`)."""
    return template.analysis is AnalysisUse.SIMULATE


class LibraryCache:
    """Compiled templates by (id, version); a new version is compiled on first use."""

    def __init__(self) -> None:
        self._compiled: dict[tuple[str, int], JudgedTemplate | None] = {}

    def get(self, template: HazardTemplate) -> JudgedTemplate | None:
        key = (template.id, template.version)
        if key not in self._compiled:
            self._compiled[key] = _compile(template)
        return self._compiled[key]
