"""A template skeleton for a hazard the library cannot bind, for a curator to complete.

In: the unbound hazard proposal and the library. Out: a template document in the library's
schema: an id following the `<family>.<name>` convention (the family of the class's earlier
templates, else the category) that no stored template uses, the class, category, severity and
preventability the analyzer proposed, the mechanism as description, and the entity variables the
analyzer filled, typed by the naming convention. The condition lists are left empty on purpose:
the safety conditions are the curator's to write (validation refuses a template without one).
Fails: never.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from app.domain.models import HazardProposal, HazardTemplate

_CONVENTIONAL_TYPES = {
    "obj": ("object", "the main object acted on"),
    "other": ("object", "the second object (heat source, receptacle, appliance...)"),
    "person": ("person", "the person at risk"),
    "room": ("room", "the room concerned"),
    "aid": ("object", "the walking aid or safety barrier"),
}


def _family(proposal: HazardProposal, library: Sequence[HazardTemplate]) -> str:
    for template in library:
        if template.hazard_class == proposal.hazard_class and "." in template.id:
            return template.id.split(".", 1)[0]
    return proposal.category.value


def _free_id(base: str, library: Sequence[HazardTemplate]) -> str:
    taken = {template.id for template in library}
    candidate, suffix = base, 2
    while candidate in taken:
        candidate, suffix = f"{base}_{suffix}", suffix + 1
    return candidate


def _variable(name: str, entity_id: str) -> dict[str, Any]:
    type_name, meaning = _CONVENTIONAL_TYPES.get(name, ("entity", "an entity of the scene"))
    return {"name": name, "type": type_name, "description": f"{meaning} (here {entity_id})"}


def suggest_template(
    proposal: HazardProposal, library: Sequence[HazardTemplate] = ()
) -> dict[str, Any]:
    """A skeleton template for an unbound hazard.

    Args:
        proposal: the hazard no active template covered.
        library: the stored templates, to pick the family prefix and a free id.

    Returns:
        A template document (JSON-ready) with empty condition lists.
    """
    base = f"{_family(proposal, library)}.{proposal.hazard_class}"
    return {
        "id": _free_id(base, library),
        "name": proposal.hazard_class.replace("_", " ").capitalize(),
        "category": proposal.category.value,
        "hazard_class": proposal.hazard_class,
        "description": proposal.mechanism,
        "iso_clause": "",
        "severity": proposal.severity.value,
        "preventability": proposal.preventability.value,
        "variables": [_variable(n, proposal.entities[n]) for n in sorted(proposal.entities)],
        "invariants": [],
        "guards": [],
        "aborts": [],
    }
