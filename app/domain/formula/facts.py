"""The interface between the condition language and a world state: facts that may be unknown.

In: a symbol name from the vocabulary and its argument ids. Out: a value (bool, float or str) or
`Unknown`. The evaluator reads facts three-valued; the Z3 encoder turns every `Unknown` into a
free variable named by its `key`, so two unknown facts with the same key are the same unknown
(an effect that copies an unknown, e.g. "the pan is as hot as the burner is on", keeps the link).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol


@dataclass(frozen=True, slots=True)
class Unknown:
    """A fact the state does not determine. `key` names it for the solver and counterexamples."""

    key: str


Value = bool | float | str
FactValue = Value | Unknown

ActionArgs = Mapping[str, str | None]
"""The guarded action's arguments for `@object`/`@target` (ids), or None outside guards."""


def fact_key(symbol: str, args: Sequence[str]) -> str:
    """The canonical name of a fact, e.g. `hot(mug_1)`; also the default key of its unknown."""
    return f"{symbol}({','.join(args)})"


class Facts(Protocol):
    """What the evaluator and the encoder need from a state."""

    def value(self, symbol: str, args: tuple[str, ...]) -> FactValue:
        """The value of a vocabulary symbol applied to entity ids or literal strings."""
        ...

    def domain(self, type_name: str) -> Sequence[str]:
        """The ids of every entity of a type (`person`, `object`, `room`) for quantifiers."""
        ...

    def entity_type(self, entity_id: str) -> str | None:
        """`robot`, `object`, `person` or `room` for a known id; None for an id not in the state."""
        ...
