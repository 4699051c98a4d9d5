"""Every vocabulary symbol's rule in one table, keyed by symbol name.

In: nothing. Out: `RULES`, merged from the object, size, placement and agent rule modules plus
`is_a`. A test checks that every symbol of `app.domain.formula.vocabulary` has a rule.
Fails: never.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from app.domain.formula.facts import FactValue
from app.domain.world.agent_rules import AGENT_RULES
from app.domain.world.concepts import concept_of
from app.domain.world.entities import ROBOT_ID
from app.domain.world.object_rules import OBJECT_RULES, Rule
from app.domain.world.object_types import normalize_type
from app.domain.world.placement_rules import PLACEMENT_RULES
from app.domain.world.size_rules import SIZE_RULES

if TYPE_CHECKING:
    from app.domain.world.state import WorldState


def _is_a(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Matches the type, name or role, ignoring case and spacing; a plain-noun type matches its
    # head noun ("kitchen knife" is a Knife).
    entity_id, wanted = args[0], normalize_type(args[1])
    if not wanted:
        return False
    names: list[str | None]
    kind = state.entity_type(entity_id)
    if entity_id == ROBOT_ID:
        names = ["robot", state.robot.name]
    elif kind == "person":
        person = state.people[entity_id]
        names = ["person", person.role, person.name]
    elif kind == "object":
        obj = state.objects[entity_id]
        names = ["object", obj.type, obj.name, obj.kind.name, "obstacle" if obj.obstacle else None]
        if len(wanted) >= 3 and normalize_type(obj.type).endswith(wanted):
            return True
        concept = concept_of(obj.type) or (concept_of(obj.name) if obj.name else None)
        if concept is not None:  # "a water glass" is a drinking_vessel, as its concept says
            names += [concept.name, *concept.props]
    else:
        # A room is a kind of room by its name: "master_bedroom" is a bedroom.
        return wanted == "room" or wanted in normalize_type(entity_id)
    return wanted in {normalize_type(n) for n in names if n}


__all__ = ["RULES", "Rule"]

RULES: dict[str, Rule] = {**OBJECT_RULES, **SIZE_RULES, **PLACEMENT_RULES, **AGENT_RULES,
                          "is_a": _is_a}
