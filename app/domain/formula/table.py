"""A dict-backed, in-memory state: the simplest `Facts`, for tests, benchmarks and validation.

In: the entities (id -> `robot`/`object`/`person`/`room`) and the known facts, keyed
`(symbol, args)` with a bool, float or str value, or an explicit `Unknown` (to give an unknown a
chosen key). Out: a `Facts`; any fact not listed is `Unknown(fact_key(symbol, args))`. The
constant `robot` is always an entity. Nothing here raises for a lookup; the constructor raises
`ValueError` on an entity type it does not know.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from app.domain.formula.facts import FactValue, Unknown, fact_key
from app.domain.formula.nodes import ROBOT_ID
from app.domain.formula.vocabulary import ENTITY_TYPES

FactTable = Mapping[tuple[str, tuple[str, ...]], FactValue]


class TableFacts:
    """Facts read from a dictionary; immutable once built (use `updated` for a changed copy)."""

    __slots__ = ("_by_symbol", "_domains", "_entities", "_unknowns", "_values")

    def __init__(self, entities: Mapping[str, str], facts: FactTable | None = None) -> None:
        """Build a state.

        Args:
            entities: every entity id with its type; `robot` is added when missing.
            facts: known (or explicitly keyed unknown) facts, `{("hot", ("mug_1",)): True}`.

        Raises:
            ValueError: an entity type that is not robot, object, person or room.
        """
        self._entities: dict[str, str] = {ROBOT_ID: "robot", **entities}
        for entity_id, type_name in self._entities.items():
            if type_name not in ENTITY_TYPES:
                raise ValueError(f"entity {entity_id!r} has unknown type {type_name!r}")
        self._values: dict[tuple[str, tuple[str, ...]], FactValue] = {
            (symbol, tuple(args)): value for (symbol, args), value in (facts or {}).items()
        }
        # Looked up per symbol, then per argument tuple: cheaper than hashing (symbol, args).
        self._by_symbol: dict[str, dict[tuple[str, ...], FactValue]] = {}
        for (symbol, args), known in self._values.items():
            self._by_symbol.setdefault(symbol, {})[args] = known
        self._unknowns: dict[tuple[str, tuple[str, ...]], Unknown] = {}
        domains: dict[str, list[str]] = {type_name: [] for type_name in ENTITY_TYPES}
        for entity_id, type_name in self._entities.items():
            domains[type_name].append(entity_id)
        self._domains = {type_name: tuple(ids) for type_name, ids in domains.items()}

    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        """The stored value, or `Unknown` keyed by `fact_key(symbol, args)`."""
        table = self._by_symbol.get(symbol)
        if table is not None:
            found = table.get(args)
            if found is not None:
                return found
        # Memoised so a repeatedly read unknown costs no string formatting.
        unknown = self._unknowns.get((symbol, args))
        if unknown is None:
            unknown = self._unknowns[(symbol, args)] = Unknown(fact_key(symbol, args))
        return unknown

    def domain(self, type_name: str) -> Sequence[str]:
        """Entity ids of a type, in insertion order (empty for a type with none)."""
        return self._domains.get(type_name, ())

    def entity_type(self, entity_id: str) -> str | None:
        """The entity's type, or None for an id not in this state."""
        return self._entities.get(entity_id)

    @property
    def entities(self) -> Mapping[str, str]:
        """Every entity id with its type."""
        return dict(self._entities)

    @property
    def facts(self) -> FactTable:
        """Every stored fact."""
        return dict(self._values)

    def updated(self, changes: FactTable) -> TableFacts:
        """A copy with some facts changed (an `Unknown` value makes that fact unknown)."""
        return TableFacts(self._entities, {**self._values, **changes})
