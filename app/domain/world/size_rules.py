"""How big a thing is: choking size, mass, heavy, and bulky enough to block a way out.

In: a `WorldState` and the object's id. Out: True/False/float or `Unknown`. Evidence in the
order of every object rule: a value an effect established, the request's `properties`, then
what the type says (AI2-THOR's median bounding box and mass, or the object concept's).
Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING

from app.domain.formula.facts import FactValue
from app.domain.world.concepts import concept_of
from app.domain.world.object_rules import Rule, object_contents, stated_value, unknown_of
from app.domain.world.substances import bite_sized

if TYPE_CHECKING:
    from app.domain.world.state import WorldState

SIZE_RULES: dict[str, Rule] = {}
_WORD = re.compile(r"[a-z]+")
_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])")
HEAVY_KG = 5.0
# Bigger than this on its longest side, a thing left in a doorway narrows the way out.
BULKY_M = 0.5
_BIG_WORDS = frozenset({"large", "big", "huge", "bulky", "oversized", "giant", "tall"})
# Kinds that stand in a way by their size: furniture, appliances, and the things below (a bag
# or a pair of shoes by the door does not block it; a crate or a pushchair does).
_BULKY_PROPS = frozenset({"furniture", "heavy", "appliance"})
_BULKY_WORDS = frozenset({"crate", "crates", "box", "boxes", "carton", "cartons", "parcel",
                          "parcels", "package", "packages", "suitcase", "suitcases", "luggage",
                          "cage", "cages", "trolley", "trolleys", "cart", "carts", "pallet",
                          "pram", "pushchair", "stroller", "buggy", "bike", "bicycle",
                          "wheelchair", "mattress", "wheelie", "bin", "bins"})


def _rule(name: str) -> Callable[[Rule], Rule]:
    def register(func: Rule) -> Rule:
        SIZE_RULES[name] = func
        return func
    return register


@_rule("small")
def _small(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Choking-hazard size: fits a cylinder about 3.2 cm wide and 5.7 cm deep. AI2-THOR's
    # median bounding box of the type stands in for the instance's size.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "small")
    if stated is not None:
        return stated
    if obj.kind.trait("small"):
        return True
    contents = object_contents(obj)
    if isinstance(contents, str) and contents and bite_sized(contents):
        return True  # a bowl of whole grapes hands a child pieces of choking size
    size = obj.kind.size_m
    if size is not None and obj.kind.known:
        if size[0] <= 0.057 and size[1] <= 0.032:
            return True
        if size[1] > 0.045:
            return False
    return unknown_of("small", obj)


@_rule("mass_kg")
def _mass(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    if "mass_kg" in obj.facts:
        return obj.facts["mass_kg"]
    mass = obj.properties.get("mass_kg")
    if isinstance(mass, int | float) and not isinstance(mass, bool):
        return float(mass)
    known = obj.kind.mass_kg
    if known is not None and known[0] == known[1]:
        return known[0]
    return unknown_of("mass_kg", obj)


@_rule("heavy")
def _heavy(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "heavy")
    if stated is not None:
        return stated
    mass = state.value("mass_kg", args)
    if isinstance(mass, float):
        return mass >= HEAVY_KG
    known = obj.kind.mass_kg
    if known is not None and (known[0] >= HEAVY_KG or known[1] < HEAVY_KG):
        return known[0] >= HEAVY_KG
    return unknown_of("heavy", obj)


@_rule("bulky")
def _bulky(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "bulky")
    if stated is not None:
        return stated
    size = obj.properties.get("size")
    if isinstance(size, str) and size.strip().lower() in _BIG_WORDS:
        return True
    heavy = state.value("heavy", args)
    concept = concept_of(obj.type) or (concept_of(obj.name) if obj.name else None)
    words = set(_WORD.findall(f"{_CAMEL.sub(' ', obj.type)} {obj.name or ''}".lower()))
    if heavy is True or words & _BULKY_WORDS or (
            concept is not None and concept.props & _BULKY_PROPS):
        return True
    if obj.kind.size_m is not None and obj.kind.known:
        return max(obj.kind.size_m) >= BULKY_M
    if state.value("small", args) is True or heavy is False:
        return False  # light enough to carry in one hand and set aside
    return unknown_of("bulky", obj)
