"""The seed Hazard Template Library (`templates_db/*.yaml`) is well formed and complete.

In: every YAML file of `templates_db/` and the taxonomy table of its README. Out: pytest
verdicts. Each template must validate as a `HazardTemplate`, carry an id prefixed by its file's
family, use only canonical action names in guards, and every condition must parse and type-check
against the vocabulary. The library as a whole must cover every hazard class of the taxonomy,
all four categories, and hold at least 60 templates. With Z3, every template's invariants must be
jointly satisfiable (also across all templates of a class, since binding applies them together),
no guard may be unsatisfiable or always true, and no abort or invariant always true.
"""

from __future__ import annotations

import re
from collections import Counter
from functools import cache
from pathlib import Path
from typing import Any

import pytest
import yaml

from app.domain.formula import check, parse
from app.domain.models import Category, HazardTemplate, Preventability, VariableType
from app.domain.smt import Encoding, Outcome, encode_symbolic, satisfiable, valid
from app.domain.world import CANONICAL_ACTIONS as ACTION_NAMES

LIBRARY_DIR = Path(__file__).resolve().parents[1] / "templates_db"

CANONICAL_ACTIONS = frozenset(ACTION_NAMES)

ENTITY_VARIABLE_TYPES = frozenset(
    {VariableType.OBJECT, VariableType.PERSON, VariableType.ROOM, VariableType.ENTITY}
)
ENTITY_VARIABLE_NAMES = frozenset({"obj", "other", "person", "room", "aid"})



def _library_files() -> list[Path]:
    return sorted(LIBRARY_DIR.glob("*.yaml"))


def _load_file(path: Path) -> list[dict[str, Any]]:
    document = yaml.safe_load(path.read_text(encoding="utf-8"))
    assert isinstance(document, dict) and set(document) == {"templates"}, (
        f"{path.name} must hold exactly one key, 'templates'"
    )
    entries = document["templates"]
    assert isinstance(entries, list) and entries, f"{path.name} has no templates"
    return entries


def _raw_entries() -> list[tuple[Path, dict[str, Any]]]:
    return [(path, entry) for path in _library_files() for entry in _load_file(path)]


@cache
def _templates() -> tuple[HazardTemplate, ...]:
    return tuple(HazardTemplate.model_validate(entry) for _, entry in _raw_entries())


def _taxonomy() -> dict[str, str]:
    """Hazard class -> category, read from the taxonomy file the README points to."""
    raw = yaml.safe_load((LIBRARY_DIR / "taxonomy" / "hazard_classes.yaml").read_text())
    return {name: row["category"] for name, row in raw["classes"].items()}


def _condition_cases() -> list[Any]:
    cases = []
    for template in _templates():
        for kind, condition in template.conditions():
            cases.append(
                pytest.param(template, kind.value, condition, id=f"{template.id}:{condition.id}")
            )
    return cases


class TestLibraryFiles:
    def test_every_file_loads_into_templates(self) -> None:
        files = _library_files()
        assert files, "templates_db holds no YAML file"
        for path in files:
            for entry in _load_file(path):
                HazardTemplate.model_validate(entry)

    def test_ids_are_prefixed_by_their_file_family(self) -> None:
        for path, entry in _raw_entries():
            assert str(entry["id"]).startswith(path.stem + "."), (
                f"{entry['id']} in {path.name} must start with '{path.stem}.'"
            )

    def test_ids_are_unique(self) -> None:
        counts = Counter(template.id for template in _templates())
        duplicates = sorted(i for i, n in counts.items() if n > 1)
        assert not duplicates, f"duplicate template ids: {duplicates}"


class TestLibraryCoverage:
    def test_taxonomy_is_read_from_its_file(self) -> None:
        taxonomy = _taxonomy()
        assert len(taxonomy) >= 40
        assert set(taxonomy.values()) == {c.value for c in Category}

    def test_every_taxonomy_class_has_an_active_template(self) -> None:
        active = {t.hazard_class for t in _templates() if t.status == "active"}
        missing = sorted(set(_taxonomy()) - active)
        assert not missing, f"hazard classes without an active template: {missing}"

    def test_every_template_class_is_in_the_taxonomy_with_its_category(self) -> None:
        taxonomy = _taxonomy()
        for template in _templates():
            assert template.hazard_class in taxonomy, f"{template.id}: unknown class"
            assert taxonomy[template.hazard_class] == template.category, (
                f"{template.id}: {template.hazard_class} belongs to "
                f"{taxonomy[template.hazard_class]}, not {template.category}"
            )

    def test_library_has_at_least_sixty_templates(self) -> None:
        assert len(_templates()) >= 60

    def test_all_four_categories_are_covered(self) -> None:
        per_category = Counter(t.category for t in _templates())
        for category in Category:
            assert per_category[category] >= 5, f"too few {category.value} templates"

    def test_some_templates_are_unpreventable(self) -> None:
        unpreventable = [
            t for t in _templates() if t.preventability is Preventability.UNPREVENTABLE
        ]
        assert 3 <= len(unpreventable) < len(_templates()) // 2


class TestTemplateShape:
    def test_every_template_has_a_condition(self) -> None:
        for template in _templates():
            assert template.conditions(), f"{template.id} has no condition"

    def test_guards_name_canonical_actions(self) -> None:
        for template in _templates():
            for guard in template.guards:
                assert guard.action in CANONICAL_ACTIONS, (
                    f"{template.id}:{guard.id} guards unknown action {guard.action!r}"
                )

    def test_only_guards_name_an_action(self) -> None:
        for template in _templates():
            for condition in (*template.invariants, *template.aborts):
                assert condition.action is None, f"{template.id}:{condition.id} names an action"

    def test_condition_ids_are_unique_within_a_template(self) -> None:
        for template in _templates():
            counts = Counter(c.id for _, c in template.conditions())
            assert max(counts.values()) == 1, f"{template.id} repeats a condition id"

    def test_entity_variables_follow_the_naming_convention(self) -> None:
        for template in _templates():
            for variable in template.variables:
                if variable.type in ENTITY_VARIABLE_TYPES:
                    assert variable.name in ENTITY_VARIABLE_NAMES, (
                        f"{template.id}: entity variable ${variable.name} is not one of "
                        f"{sorted(ENTITY_VARIABLE_NAMES)}"
                    )
                    assert variable.default is None, f"{template.id}: ${variable.name} default"

    def test_value_variables_have_defaults(self) -> None:
        for template in _templates():
            for variable in template.variables:
                if variable.type not in ENTITY_VARIABLE_TYPES | {VariableType.ROBOT}:
                    assert variable.default is not None, (
                        f"{template.id}: ${variable.name} has no default and cannot be bound"
                    )

    def test_every_declared_variable_is_used(self) -> None:
        for template in _templates():
            text = " ".join(c.formula for _, c in template.conditions())
            for variable in template.variables:
                assert re.search(rf"\${variable.name}\b", text), (
                    f"{template.id} declares ${variable.name} but never uses it"
                )


class TestConditionsTypeCheck:
    @pytest.mark.parametrize(("template", "kind", "condition"), _condition_cases())
    def test_condition_parses_and_type_checks(
        self, template: HazardTemplate, kind: str, condition: Any
    ) -> None:
        variables = {v.name: v.type.value for v in template.variables}
        check(parse(condition.formula), variables, allow_action_args=(kind == "guard"))


def _encode(template: HazardTemplate, formula: str) -> Encoding:
    variables = {v.name: v.type.value for v in template.variables}
    defaults = {v.name: v.default for v in template.variables if v.default is not None}
    return encode_symbolic(parse(formula), variables, defaults=defaults)


def _invariants(template: HazardTemplate) -> list[Encoding]:
    return [_encode(template, c.formula) for c in template.invariants]


def _refutable(template: HazardTemplate, formula: str) -> bool:
    """Whether some state makes the condition false (it is not a tautology)."""
    return valid(_encode(template, formula)).outcome is Outcome.VIOLATED


class TestConditionsAreMeaningful:
    """Every fact is unknown here, so Z3 answers "is there any state in which ...?"."""

    def test_each_templates_invariants_are_jointly_satisfiable(self) -> None:
        for template in _templates():
            if template.invariants:
                assert satisfiable(_invariants(template)).sat, template.id

    def test_invariants_of_one_hazard_class_are_jointly_satisfiable(self) -> None:
        # Binding applies every template of a class whose variables it can fill, together.
        by_class: dict[str, list[Encoding]] = {}
        for template in _templates():
            by_class.setdefault(template.hazard_class, []).extend(_invariants(template))
        for hazard_class, invariants in by_class.items():
            if invariants:
                assert satisfiable(invariants).sat, hazard_class

    def test_no_invariant_is_always_true(self) -> None:
        for template in _templates():
            for condition in template.invariants:
                assert _refutable(template, condition.formula), f"{template.id}:{condition.id}"

    def test_every_guard_can_pass_while_the_invariants_hold(self) -> None:
        for template in _templates():
            for guard in template.guards:
                claims = [*_invariants(template), _encode(template, guard.formula)]
                assert satisfiable(claims).sat, f"{template.id}:{guard.id}"

    def test_every_guard_can_refuse(self) -> None:
        for template in _templates():
            for guard in template.guards:
                assert _refutable(template, guard.formula), f"{template.id}:{guard.id}"

    def test_every_abort_can_stay_quiet_and_can_fire(self) -> None:
        for template in _templates():
            for abort in template.aborts:
                fires = satisfiable([*_invariants(template), _encode(template, abort.formula)])
                assert _refutable(template, abort.formula), f"{template.id}:{abort.id}"
                assert fires.sat, f"{template.id}:{abort.id}"
