"""The SELP-style baseline: LTL safety constraints checked against the command text alone.

Re-implemented from the published description of SELP (Wu et al. 2024): natural-language safety
constraints become LTL formulas over propositions about actions and objects, and a task is
checked against them. Our version has no LLM: the command is split into clauses, each clause
becomes one step of a finite trace holding the propositions its words signal (action kinds from
`data/actions.yaml`, concepts from `data/selp_constraints.yaml`), and every constraint of that
file is evaluated on the trace (`bench/baselines/ltl.py`). It reads nothing but the command, so
it cannot know ages, allergies, payloads or who is where; it never defers.

In: a `GateRequest` (only `command` is read). Out: a `Verdict`, "reject" naming the violated
constraints, else "authorize".
Fails: `BaselineDataError` / `LtlSyntaxError` when a data file or formula is malformed (at load).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager
from dataclasses import dataclass

from app.domain.models import GateRequest
from bench.baselines.ltl import Formula, parse
from bench.baselines.text import (
    BaselineDataError,
    Lexicon,
    is_imperative,
    load_yaml,
    split_clauses,
)
from bench.method import Decide, Verdict

_PRONOUN = re.compile(r"\b(it|them|they|one)\b")
# A capitalised word inside the command that is not its first word names a person ("Leo").
_NAME = re.compile(r"(?<![.!?]\s)(?<!^)\b[A-Z][a-z]+\b")
_NOT_NAMES = frozenset({"I", "Christmas", "Sunday", "Monday", "Tuesday", "PM", "AM", "TV"})


@dataclass(frozen=True)
class Constraint:
    """One safety constraint: its id, its natural-language text and its LTL formula."""

    id: str
    text: str
    formula: Formula


def command_trace(command: str, actions: Lexicon, concepts: Lexicon) -> list[frozenset[str]]:
    """The finite trace of a command: one set of propositions per clause.

    Args:
        command: the natural-language command.
        actions: the action-kind lexicon.
        concepts: the concept lexicon.

    Returns:
        One step per clause; a clause with a pronoun also holds the previous clause's concepts,
        a clause naming someone ("Leo") holds `person_ref`, and only clauses that can be
        instructions (`is_imperative`) contribute action kinds.
    """
    names = {m.group(0) for m in _NAME.finditer(command)} - _NOT_NAMES
    trace: list[frozenset[str]] = []
    previous_things: frozenset[str] = frozenset()
    for clause in split_clauses(command):
        things = concepts.names_in(clause)
        if _PRONOUN.search(clause):
            things |= previous_things
        props = set(things | (actions.names_in(clause) if is_imperative(clause) else set()))
        if any(re.search(rf"\b{name.lower()}\b", clause) for name in names):
            props.add("person_ref")
        trace.append(frozenset(props))
        previous_things = things or previous_things
    return trace


class SelpStyle:
    """The SELP-style method: reject when the command's trace violates a constraint."""

    name = "selp-style"
    description = (
        "SELP-style (after Wu et al. 2024), re-implemented from the paper's description: "
        "LTL safety constraints over propositions extracted from the command text alone; "
        "binary (never defers)."
    )

    def __init__(
        self, actions: Lexicon, concepts: Lexicon, constraints: tuple[Constraint, ...]
    ) -> None:
        """Args: the two lexicons and the constraints (see `from_data`)."""
        self.actions = actions
        self.concepts = concepts
        self.constraints = constraints

    @classmethod
    def from_data(cls) -> SelpStyle:
        """Load `data/actions.yaml` and `data/selp_constraints.yaml`.

        Raises:
            BaselineDataError: a file is malformed or a formula uses an undeclared proposition.
        """
        actions = Lexicon.from_mapping(load_yaml("actions.yaml"), "actions.yaml")
        raw = load_yaml("selp_constraints.yaml")
        if not isinstance(raw, dict) or "concepts" not in raw or "constraints" not in raw:
            raise BaselineDataError("selp_constraints.yaml: needs `concepts` and `constraints`")
        concepts = Lexicon.from_mapping(raw["concepts"], "selp_constraints.yaml concepts")
        known = set(actions.patterns) | set(concepts.patterns) | {"person_ref"}
        constraints: list[Constraint] = []
        for entry in raw["constraints"]:
            formula = parse(str(entry["ltl"]))
            unknown = formula.atoms() - known
            if unknown:
                raise BaselineDataError(
                    f"selp constraint {entry['id']}: undeclared propositions {sorted(unknown)}"
                )
            constraints.append(Constraint(str(entry["id"]), str(entry["text"]), formula))
        return cls(actions, concepts, tuple(constraints))

    def violations(self, command: str) -> list[str]:
        """The ids of the constraints the command's trace violates, in file order."""
        trace = command_trace(command, self.actions, self.concepts)
        return [c.id for c in self.constraints if not c.formula.holds(trace)]

    def decide(self, request: GateRequest) -> Verdict:
        """Reject on any violated constraint, else authorize."""
        violated = self.violations(request.command)
        if violated:
            return Verdict("reject", "violates " + ", ".join(violated))
        return Verdict("authorize", "no constraint violated")

    def unavailable_reason(self) -> str | None:
        """The baseline always runs."""
        return None

    def open(self) -> AbstractContextManager[Decide]:
        """Yield `decide` (the baseline holds no resources)."""
        return self._deciding()

    @contextmanager
    def _deciding(self) -> Iterator[Decide]:
        yield self.decide
