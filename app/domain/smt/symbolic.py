"""Encode a template's conditions in the abstract: no scene, every fact unknown.

In: a parsed condition, the template's variables (name -> type) and optional defaults for value
variables. Out: an `Encoding` over `SymbolicFacts`, where each entity variable is its own entity
among a few anonymous ones and value variables without a default are free. Used to validate
templates: invariants jointly satisfiable, guards satisfiable, no abort valid. Fails like
`encode` (`FormulaError`).
"""

from __future__ import annotations

from collections.abc import Mapping

from app.domain.formula.nodes import Formula
from app.domain.formula.symbolic import SymbolicFacts, symbolic_bindings
from app.domain.formula.transform import substitute
from app.domain.smt.encoder import Encoding, encode


def encode_symbolic(
    formula: Formula,
    variables: Mapping[str, str],
    *,
    defaults: Mapping[str, object] | None = None,
    per_type: int = 2,
) -> Encoding:
    """Encode a template condition over a fully symbolic state.

    Args:
        formula: the template's condition, still with its `$vars`.
        variables: the template's variables, name to type.
        defaults: values for value-typed variables (the rest stay free).
        per_type: anonymous entities per domain besides the variables' own.

    Returns:
        The encoding; encodings of the same template share their free variables by name, so
        a list of them can be passed to `satisfiable`/`valid` together.
    """
    facts = SymbolicFacts(variables, per_type=per_type)
    bound = substitute(formula, symbolic_bindings(variables, defaults), variables=variables)
    return encode(bound, facts, variable_types=variables)
