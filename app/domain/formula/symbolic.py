"""A fully symbolic state for checking templates in the abstract, with no scene at hand.

In: a template's variables (name without `$` -> type) and how many anonymous entities of each type
to add. Out: `SymbolicFacts`, a `Facts` in which every fact is `Unknown` (keyed by `fact_key`), and
`symbolic_bindings`, which binds each entity variable to its own distinct entity of that state
(`robot` variables to the robot). With the Z3 encoder this asks "is there any state in which ...",
e.g. whether a template's invariants can hold together. Raises `ValueError` on an unknown type.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from app.domain.formula.facts import FactValue, Unknown, fact_key
from app.domain.formula.nodes import ROBOT_ID, EntityRef
from app.domain.formula.vocabulary import ALL_TYPES

_DOMAIN_TYPES = ("object", "person", "room")


def _entity_domain(type_name: str) -> str | None:
    """The domain an entity variable's own entity joins (`entity` ranges like an object)."""
    if type_name == "entity":
        return "object"
    return type_name if type_name in _DOMAIN_TYPES else None


def variable_entity_id(name: str) -> str:
    """The id of the entity standing for template variable `$name` in a symbolic state."""
    return f"${name}"


class SymbolicFacts:
    """Facts that are all unknown, over a few anonymous entities plus the template's own."""

    __slots__ = ("_domains", "_types")

    def __init__(self, variables: Mapping[str, str] | None = None, *, per_type: int = 2) -> None:
        """Build the state.

        Args:
            variables: the template's variables; each entity variable gets its own entity.
            per_type: anonymous entities added to each of the object, person and room domains.

        Raises:
            ValueError: a variable type that is not a type of the language.
        """
        self._types: dict[str, str] = {ROBOT_ID: "robot"}
        domains: dict[str, list[str]] = {type_name: [] for type_name in _DOMAIN_TYPES}
        for name, type_name in (variables or {}).items():
            if type_name not in ALL_TYPES:
                raise ValueError(f"variable ${name} has unknown type {type_name!r}")
            domain = _entity_domain(type_name)
            if domain is not None:
                self._types[variable_entity_id(name)] = domain
                domains[domain].append(variable_entity_id(name))
        for type_name in _DOMAIN_TYPES:
            for index in range(1, per_type + 1):
                entity_id = f"{type_name}~{index}"
                self._types[entity_id] = type_name
                domains[type_name].append(entity_id)
        self._domains = {name: tuple(ids) for name, ids in domains.items()}
        self._domains["robot"] = (ROBOT_ID,)

    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        """Always unknown, keyed by the fact's canonical name."""
        return Unknown(fact_key(symbol, args))

    def domain(self, type_name: str) -> Sequence[str]:
        """The variables' entities of that type, then the anonymous ones."""
        return self._domains.get(type_name, ())

    def entity_type(self, entity_id: str) -> str | None:
        """The type of an entity of this state, or None."""
        return self._types.get(entity_id)


def symbolic_bindings(
    variables: Mapping[str, str], defaults: Mapping[str, object] | None = None
) -> dict[str, object]:
    """Bindings that put a template's conditions into a `SymbolicFacts` state.

    Args:
        variables: the template's variables, name to type.
        defaults: values for value-typed variables; those without one stay `$var`s, which the Z3
            encoder treats as free variables of their type.

    Returns:
        Entity variables bound to their own `EntityRef`, `robot` variables to the robot, and
        value variables to their defaults when given.
    """
    bindings: dict[str, object] = {}
    for name, type_name in variables.items():
        if type_name == "robot":
            bindings[name] = EntityRef(ROBOT_ID)
        elif _entity_domain(type_name) is not None:
            bindings[name] = EntityRef(variable_entity_id(name))
        elif defaults is not None and name in defaults:
            bindings[name] = defaults[name]
    return bindings
