"""The action model as data for `GET /vocabulary`.

In: nothing. Out: `describe_actions()`, one JSON-ready dict per canonical action: name,
summary, aliases, arguments, preconditions (formula and plain words) and effects in words.
Fails: never.
"""

from __future__ import annotations

from typing import Any

from app.domain.world.action_names import aliases_of
from app.domain.world.action_specs import ACTION_SPECS


def describe_actions() -> list[dict[str, Any]]:
    """Every canonical action with its aliases, arguments, preconditions and effects.

    Returns:
        A list of dicts, in the order of the action table.
    """
    described: list[dict[str, Any]] = []
    for spec in ACTION_SPECS.values():
        arguments: list[dict[str, Any]] = []
        for role, kinds, required in (("object", spec.object_kinds, spec.object_required),
                                      ("target", spec.target_kinds, spec.target_required)):
            if kinds:
                arguments.append({"name": role, "type": " | ".join(kinds),
                                  "required": required})
        arguments.extend({"name": p.name, "type": p.type, "required": False,
                          "description": p.description} for p in spec.params)
        described.append({
            "name": spec.name,
            "summary": spec.summary,
            "aliases": list(aliases_of(spec.name)),
            "arguments": arguments,
            "preconditions": [{"formula": p.formula, "description": p.description}
                              for p in spec.preconditions],
            "effects": list(spec.effects),
        })
    return described
