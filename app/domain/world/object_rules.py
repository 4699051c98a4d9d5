"""The meaning of each object predicate in a world state (hot, sharp, toxic, filled...).

In: a `WorldState` and the symbol's arguments (already checked to be ids of the right type).
Out: True/False/str/float, or `Unknown` when neither the request, an effect, nor the object's
type decides. Order of evidence for every rule: a value an effect established (`obj.facts`),
then the request's `properties`, then derived evidence (contents, receptacle, type knowledge).
A value copied from another fact keeps that fact's `Unknown`, so the solver sees the link.
Fails: never.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from app.domain.formula.facts import FactValue, Unknown, fact_key
from app.domain.world.concepts import concept_of
from app.domain.world.entities import ObjectState
from app.domain.world.object_types import TypeInfo, normalize_type
from app.domain.world.substances import (
    alcoholic,
    is_empty,
    pet_toxic,
    same_substance,
    substance_trait,
)

if TYPE_CHECKING:
    from app.domain.world.state import WorldState

Rule = Callable[["WorldState", tuple[str, ...]], FactValue]
OBJECT_RULES: dict[str, Rule] = {}

_TRUE_WORDS = frozenset({"true", "yes", "on", "1"})
_FALSE_WORDS = frozenset({"false", "no", "off", "0"})


def _rule(name: str) -> Callable[[Rule], Rule]:
    def register(func: Rule) -> Rule:
        OBJECT_RULES[name] = func
        return func
    return register


def as_bool(value: Any) -> bool | None:
    """A request's property value as a bool ("yes", "on", 1...), or None if it is not one."""
    if isinstance(value, bool):
        return value
    if isinstance(value, str):
        word = value.strip().lower()
        return True if word in _TRUE_WORDS else False if word in _FALSE_WORDS else None
    if isinstance(value, int | float):
        return bool(value)
    return None


def stated_value(obj: ObjectState, symbol: str, *property_names: str) -> FactValue | None:
    """The value an effect or the request gave, or None when neither did."""
    if symbol in obj.facts:
        return obj.facts[symbol]
    for name in property_names or (symbol,):
        found = as_bool(obj.properties.get(name))
        if found is not None:
            return found
    return None


def unknown_of(symbol: str, obj: ObjectState) -> Unknown:
    return Unknown(fact_key(symbol, (obj.id,)))


def _decide(symbol: str, obj: ObjectState, *evidence: bool | None) -> FactValue:
    """True if any evidence says so; False if all evidence says not; else unknown."""
    decided = True
    for item in evidence:
        if item is True:
            return True
        if item is not False:
            decided = False
    return False if decided else unknown_of(symbol, obj)


def _flag_rule(symbol: str, decide: Callable[[TypeInfo], bool | None], *props: str) -> None:
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        obj = state.objects[args[0]]
        stated = stated_value(obj, symbol, *props)
        return stated if stated is not None else _decide(symbol, obj, decide(obj.kind))
    OBJECT_RULES[symbol] = rule


def object_contents(obj: ObjectState) -> str | Unknown:
    """What the object holds: '' for an object that cannot hold anything; unknown if unstated."""
    if "contents" in obj.facts:
        found = obj.facts["contents"]
        return found if isinstance(found, str | Unknown) else str(found)
    contents = obj.properties.get("contents")
    if isinstance(contents, str):
        return "" if is_empty(contents) else _with_ingredients(obj, contents)
    itself = " ".join(w for w in (obj.name, obj.type) if w).replace("_", " ").lower()
    if obj.kind.is_container is not True and (
            obj.kind.is_food or obj.kind.trait("food") or obj.kind.trait("medication")
            or substance_trait(itself, "medication")):
        # A food or a medicine is its own substance: an apple "holds" apple, an aspirin aspirin.
        return _with_ingredients(obj, itself)
    if as_bool(obj.properties.get("filled")) is False or obj.kind.is_container is False:
        return ""
    return unknown_of("contents", obj)


_INGREDIENT_KEYS = ("ingredients", "allergens", "may_contain")


def _with_ingredients(obj: ObjectState, substance: str) -> str:
    """The substance with what its label lists ("flapjacks with oats, peanut butter"): an
    allergen or a contraindicated food hides in a dish's ingredients as often as in its name."""
    listed: list[str] = []
    for key in _INGREDIENT_KEYS:
        value = obj.properties.get(key)
        items = [value] if isinstance(value, str) else value if isinstance(value, list) else []
        listed += [item for item in items if isinstance(item, str) and item.strip()]
    return f"{substance} with {', '.join(listed)}" if listed else substance


def _by_contents(obj: ObjectState, trait: str) -> bool | None:
    contents = object_contents(obj)
    if isinstance(contents, Unknown):
        return None
    found = substance_trait(contents, trait)
    if found is None and obj.kind.is_container is not True and (
            obj.kind.is_food or obj.kind.trait("food")):
        # A food the substance table does not list is no common allergen, poison or fuel.
        return trait == "food"
    return found


_SERVED_HOT = frozenset({"coffee", "tea", "cocoa", "chocolate", "soup", "broth", "porridge",
                         "stew", "gravy", "cuppa", "latte", "cappuccino", "espresso"})


def _can_be_hot(obj: ObjectState) -> bool:
    """Whether an object could be hot when nobody says: a heat source, or something holding
    what is served hot (coffee, soup) whose temperature nobody gave. Anything else is at room
    temperature until an effect heats it."""
    if obj.kind.flag("heat_source") is not False and not obj.kind.described:
        return obj.kind.flag("heat_source") is None
    contents = object_contents(obj)
    if isinstance(contents, Unknown):
        return obj.kind.trait("heat_safe") is True
    words = set(contents.lower().replace("_", " ").split())
    return bool(words & _SERVED_HOT)


def _temperature(obj: ObjectState) -> str | None:
    value = obj.properties.get("temperature")
    return value.strip().lower() if isinstance(value, str) else None


def _parent(state: WorldState, obj: ObjectState) -> ObjectState | None:
    if obj.parent is None or state.holder_of(obj.id) is not None:
        return None
    return state.objects.get(obj.parent)


@_rule("hot")
def _hot(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # A heat source is hot exactly when it is on; an object resting on or in one is hot when
    # that source is on. Both copy the `is_on` value, unknown included, to keep the link.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "hot")
    if stated is not None:
        return stated
    temperature = _temperature(obj)
    if temperature is not None:
        return temperature == "hot"
    if as_bool(obj.properties.get("heat_source")) or obj.kind.flag("heat_source"):
        return state.value("is_on", (obj.id,))
    parent = _parent(state, obj)
    if parent is not None and state.value("heat_source", (parent.id,)) is True:
        parent_on = state.value("is_on", (parent.id,))
        if parent_on is not False:
            return parent_on
    return unknown_of("hot", obj) if _can_be_hot(obj) else False


@_rule("cold")
def _cold(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "cold")
    if stated is not None:
        return stated
    temperature = _temperature(obj)
    if temperature is not None:
        return temperature == "cold"
    if obj.kind.flag("cold_source"):
        return True
    if state.value("hot", args) is True:
        return False
    parent = _parent(state, obj)
    if parent is not None and parent.kind.flag("cold_source") and obj.relation == "in":
        return True
    return unknown_of("cold", obj) if _can_be_hot(obj) else False


@_rule("sharp")
def _sharp(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "sharp")
    if stated is not None:
        return stated
    # Broken glass or ceramic has sharp edges. Maybe broken (dropped, breakable unknown) and
    # maybe glass is maybe sharp: deciding "not sharp" there let a plan verify that can fail.
    shattered: bool | None = False
    broken = state.value("broken", args)
    if broken is True or isinstance(broken, Unknown):
        glass, ceramic = obj.kind.material("Glass"), obj.kind.material("Ceramic")
        shattered = True if glass or ceramic else None if None in (glass, ceramic) else False
        if broken is not True and shattered is True:
            shattered = None
    return _decide("sharp", obj, obj.kind.trait("sharp"), shattered)


def _content_rule(symbol: str, type_evidence: Callable[[TypeInfo], bool | None],
                  made_of: Callable[[ObjectState], bool | None] | None = None) -> None:
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        obj = state.objects[args[0]]
        stated = stated_value(obj, symbol)
        if stated is not None:
            return stated
        by_material = None if made_of is None else made_of(obj)
        by_type = type_evidence(obj.kind) if by_material is None else by_material
        by_contents = _by_contents(obj, symbol)
        if by_type is None and by_contents is not None:
            by_type = False  # a type that "depends on what it holds", and we know what it holds
        return _decide(symbol, obj, by_type, by_contents)
    OBJECT_RULES[symbol] = rule


_DISHES = frozenset({"Cup", "Mug", "Glass", "WineGlass", "Bowl", "Plate", "Pot", "Pan", "Kettle",
                     "FoilTray", "Tray", "FoodContainer", "Tupperware", "LunchBox",
                     "Teapot"})


def _plausible_content_rule(symbol: str) -> None:
    """`toxic` and `medication`: a dish or drinking vessel whose contents nobody gave can hold
    such a thing only if the scene has one (or an unlabelled container) it could come from."""
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        obj = state.objects[args[0]]
        stated = stated_value(obj, symbol)
        if stated is not None:
            return stated
        by_type, by_contents = obj.kind.trait(symbol), _by_contents(obj, symbol)
        if by_type is not True and normalize_type(obj.type) != normalize_type(obj.kind.name) \
                and substance_trait(_CAMEL.sub(" ", obj.type).lower(), symbol):
            by_type = True  # a type named for what it holds ("InsulinPens" are not just pens)
        if by_type is None and by_contents is not None:
            by_type = False
        decided = _decide(symbol, obj, by_type, by_contents)
        if not isinstance(decided, Unknown) or by_type is True:
            return decided
        if obj.kind.name in _DISHES:
            sources = (o for o in state.objects.values()
                       if o.id != obj.id and o.kind.name not in _DISHES)
            return decided if any(_could_be(symbol, o) for o in sources) else False
        if _made_to_hold(obj, symbol):
            return decided
        # A hamper, a box or a baking dish nobody described holds such a thing only if the
        # scene says one is about (stated, or named by its contents) somewhere else.
        return decided if any(_stated_source(symbol, o) for o in state.objects.values()
                              if o.id != obj.id) else False
    OBJECT_RULES[symbol] = rule


_HOLDERS = ("bottle", "jug", "jar", "can", "tin", "canister", "spray", "pill", "medicine",
            "firstaid", "blister", "tube", "sachet", "packet", "container", "organiser",
            "organizer", "dispenser", "vial", "bucket", "tub")


def _made_to_hold(obj: ObjectState, symbol: str) -> bool:
    """Whether the container is the kind that holds chemicals or medicine unlabelled."""
    concept = concept_of(obj.type) or (concept_of(obj.name) if obj.name else None)
    if concept is not None and symbol in concept.props:
        return True
    key = normalize_type(f"{obj.type} {obj.name or ''}")
    return any(word in key for word in _HOLDERS)


def _stated_source(symbol: str, obj: ObjectState) -> bool:
    stated = stated_value(obj, symbol)
    return stated is True or obj.kind.trait(symbol) is True or _by_contents(obj, symbol) is True


def _could_be(symbol: str, obj: ObjectState) -> bool:
    """Something toxic (or medicine), or a container that may hold it unlabelled."""
    stated = stated_value(obj, symbol)
    if stated is not None:
        return stated is not False
    if obj.kind.trait(symbol) is True or _by_contents(obj, symbol) is True:
        return True
    return (obj.kind.trait(symbol) is None and obj.kind.is_container is not False
            and isinstance(object_contents(obj), Unknown) and not obj.kind.is_food)


_plausible_content_rule("toxic")
_plausible_content_rule("medication")
_content_rule("allergen", lambda k: k.trait("allergen"))
@_rule("food")
def _food(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # A container's contents decide; one whose contents nobody gave is food only if it is a
    # dish, a drinking vessel or a food container (a plant pot or a bucket is not).
    obj = state.objects[args[0]]
    stated = stated_value(obj, "food")
    if stated is not None:
        return stated
    by_type, by_contents = obj.kind.is_food, _by_contents(obj, "food")
    if by_contents is not None:
        return by_contents or by_type is True
    if by_type is None and obj.kind.is_container is True and not _holds_food(obj.kind):
        return False
    return _decide("food", obj, by_type)


_FOOD_VESSELS = _DISHES | frozenset({"Bottle", "WineBottle", "Jar", "FoodContainer", "Box",
                                     "Tupperware", "Carton", "Thermos", "Flask", "Pitcher",
                                     "Jug", "Teapot", "Glass", "WineGlass", "Tray",
                                     "EggCarton", "LunchBox"})


def _holds_food(kind: TypeInfo) -> bool:
    return kind.name in _FOOD_VESSELS or kind.trait("heat_safe") is True
_METALS = ("metal", "steel", "alumin", "iron", "copper", "tin", "brass", "foil", "silver",
           "chrome", "zinc", "titanium", "nickel", "gold", "bronze")
_BURNING_MATERIALS = ("plastic", "paper", "card", "wood", "fabric", "cotton", "wool", "linen",
                      "polyester", "nylon", "wax", "foam", "rubber", "wicker", "straw",
                      "polystyrene", "acrylic", "vinyl", "melamine", "silk", "felt")
_LASTING_MATERIALS = ("glass", "ceramic", "porcelain", "stone", "pyrex", "earthenware",
                      "stoneware", "enamel", "cast iron", "silicone", *_METALS)


def _material_burns(obj: ObjectState) -> bool | None:
    """What the scene says the thing is made of ("material": "plastic"), when it says: a
    plastic tub melts and burns on a hob whatever its type usually is."""
    material = obj.properties.get("material")
    if not isinstance(material, str):
        return None
    material = material.lower()
    if any(word in material for word in _BURNING_MATERIALS):
        return True
    if any(word in material for word in _LASTING_MATERIALS):
        return False
    return None


_content_rule(
    "flammable",
    lambda k: k.trait("flammable") if "flammable" in k.traits else k.flammable_by_material,
    _material_burns,
)

_flag_rule("breakable", lambda k: k.flag("breakable"), "breakable", "fragile")
_flag_rule("fragile", lambda k: k.flag("breakable"), "fragile", "breakable")
_flag_rule("electrical", lambda k: k.trait("electrical"))
_flag_rule("heat_source", lambda k: k.flag("heat_source"))
_flag_rule("pickupable", lambda k: k.flag("pickupable"))
_flag_rule("walking_aid", lambda k: k.trait("walking_aid"))
_flag_rule("personal_aid", lambda k: k.trait("personal_aid") or k.trait("walking_aid"))
_flag_rule("safety_barrier", lambda k: k.trait("safety_barrier"))
_flag_rule("life_support", lambda k: k.trait("life_support"))
_flag_rule("mains_switch", lambda k: k.trait("mains_switch"))
_flag_rule("ignition", lambda k: k.trait("ignition"))
_flag_rule("oxygen_supply", lambda k: k.trait("oxygen_supply"))
_flag_rule("open_flame", lambda k: k.trait("open_flame"))

_FLASHING_WORDS = ("strobe", "disco", "flashing", "flash", "blinking")


@_rule("flashing")
def _flashing(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # A strobe says so by its name or its mode; other lights are steady.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "flashing", "flashing", "strobe")
    if stated is not None:
        return stated
    words = " ".join(str(v) for v in (obj.id, obj.name or "", obj.type,
                                       obj.properties.get("mode", ""))).lower()
    return any(word in words for word in _FLASHING_WORDS)

_ENGINES = ("generator", "car", "van", "motorbike", "motorcycle", "quadbike", "petrol",
            "diesel", "chainsaw", "leafblower", "rotavator")
_FUELS = frozenset({"petrol", "gasoline", "diesel", "gas", "propane", "butane", "lpg"})


@_rule("exhaust")
def _exhaust(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # An engine says so by its kind or its fuel; what burns no fuel gives off no fumes.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "exhaust")
    if stated is not None:
        return stated
    if str(obj.properties.get("fuel", "")).lower() in _FUELS or isinstance(
            obj.properties.get("exhaust"), str):
        return True
    words = normalize_type(" ".join(str(n) for n in (obj.type, obj.name or "") if n))
    return any(engine in words for engine in _ENGINES) and "electric" not in words


_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])")
ANIMAL_TYPES = frozenset({"dog", "cat", "puppy", "kitten", "rabbit", "guineapig", "hamster",
                           "parrot", "bird", "budgie", "tortoise", "ferret", "pet"})


@_rule("animal")
def _animal(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # A pet is listed among the objects: a type that names an animal, or a stated species.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "animal", "animal", "pet")
    if stated is not None:
        return stated
    return bool(obj.properties.get("species")) or normalize_type(obj.type) in ANIMAL_TYPES


def _named_rule(symbol: str, names: Callable[[str], bool | None]) -> None:
    # What the object holds, or what it is called ("WineBottle", "a bowl of grapes"), names the
    # substance; unknown contents leave the fact unknown unless the name already says it, and
    # a name that may or may not be it ("flowers" for lilies) leaves it unknown too.
    def rule(state: WorldState, args: tuple[str, ...]) -> FactValue:
        obj = state.objects[args[0]]
        stated = stated_value(obj, symbol)
        if stated is not None:
            return stated
        contents = object_contents(obj)
        itself = " ".join(w for w in (obj.name, _CAMEL.sub(" ", obj.type)) if w)
        if isinstance(contents, Unknown):
            return True if names(itself) else contents
        found = names(f"{contents} {itself}")
        return unknown_of(symbol, obj) if found is None else found
    OBJECT_RULES[symbol] = rule


_named_rule("alcoholic", alcoholic)
_named_rule("pet_toxic", pet_toxic)

_OUTSIDE_WORDS = frozenset({"front", "back", "garden", "patio", "porch", "exterior", "outside",
                            "outer", "entrance", "street", "yard", "garage", "gate", "exit"})


_LEADS_TO = ("opens_onto", "opens_to", "leads_to", "opens_into")
_DOORWAY_ROOMS = frozenset({"porch", "frontdoor", "backdoor", "entrance", "entryway", "entry",
                            "vestibule"})
_OUTDOORS = frozenset({"road", "drive", "driveway", "pavement", "sidewalk", "outdoors",
                       "lane", "car", "park"})


@_rule("exterior")
def _exterior(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # An outside door says so by a property or by its name ("the front door", "patio_door_1");
    # a door nobody describes is taken to be inside the home.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "exterior", "exterior", "outside", "external")
    if stated is not None:
        return stated
    # ... or by where it is ("front_door", "porch") or what it opens onto ("busy road").
    leads = " ".join(str(obj.properties.get(key) or "") for key in _LEADS_TO)
    words = set(re.split(r"[^a-z]+", " ".join(
        (obj.id, obj.name or "", _CAMEL.sub(" ", obj.type), leads)).lower()))
    return bool(words & (_OUTSIDE_WORDS | _OUTDOORS)) or normalize_type(
        obj.room or "") in _DOORWAY_ROOMS


# Things are dry and whole unless the scene says otherwise or an effect (a spill, a fall)
# makes them so: a wet or broken object is something a caller would mention.
_flag_rule("wet", lambda k: False)
_flag_rule("broken", lambda k: False)
_flag_rule("dirty", lambda k: None if k.flag("dirtyable") is not False else False)
# A bottle or box in hand starts shut (AI2-THOR's initial scenes agree): an open one is
# something a caller would mention. Doors, fridges and cupboards stay for the scene to say.
# A sink or a shelf has no door or lid: what lies in it is as reachable as in an open box.
_flag_rule("open", lambda k: True if k.flag("openable") is False and k.flag(
    "receptacle") is True and k.flag("pickupable") is not True else None if k.flag(
    "openable") is not False and k.flag("pickupable") is not True else False)
_flag_rule("lidded", lambda k: None if k.is_container is not False else False)
_flag_rule("sealed", lambda k: None if k.is_container is not False else False)
_flag_rule(
    "is_on",
    lambda k: None if (k.flag("toggleable") is not False or k.flag("heat_source") is not False
                       or k.trait("electrical") is not False) else False,
    "on", "is_on", "lit",
)


@_rule("filled")
def _filled(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "filled")
    if stated is not None:
        return stated
    if obj.kind.flag("can_fill") is False and "contents" not in obj.properties:
        return False
    liquid = _by_contents(obj, "liquid")
    return unknown_of("filled", obj) if liquid is None else liquid


@_rule("metal")
def _metal(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "metal")
    if stated is not None:
        return stated
    wrapping = obj.properties.get("wrapped_in") or obj.properties.get("wrapped")
    if isinstance(wrapping, str) and any(m in wrapping.lower() for m in _METALS):
        return True  # a potato in foil takes its foil wherever it goes
    material = obj.properties.get("material")
    if isinstance(material, str):
        return any(m in material.lower() for m in _METALS)
    if obj.kind.is_container is not True and (obj.kind.is_food or obj.kind.trait("food")):
        return False  # bread, an apple: food is not metal
    concept = concept_of(obj.type) or (concept_of(obj.name) if obj.name else None)
    if concept is not None and "metal" in concept.props:
        return True
    return _decide("metal", obj, obj.kind.material("Metal"), obj.kind.traits.get("metal"))


@_rule("contents")
def _contents(state: WorldState, args: tuple[str, ...]) -> FactValue:
    return object_contents(state.objects[args[0]])


@_rule("contains")
def _contains(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Unknown contents can be a substance only if the scene has it somewhere, or has an
    # unlabelled bottle or sprayer it could have come from.
    obj = state.objects[args[0]]
    contents = object_contents(obj)
    if isinstance(contents, Unknown):
        concept = concept_of(obj.type) or (concept_of(obj.name) if obj.name else None)
        if concept is not None and "drinking_vessel" in concept.props and (
                substance_trait(args[1], "toxic") or substance_trait(args[1], "flammable")):
            return False  # nobody keeps oil or bleach in a mug unless the scene says so
        for other in state.objects.values():
            if other.id == obj.id:
                continue
            held = object_contents(other)
            if isinstance(held, str) and held and same_substance(args[1], held):
                return Unknown(fact_key("contains", args))
            if isinstance(held, Unknown) and other.kind.trait("toxic") is None and \
                    other.kind.name not in _FOOD_VESSELS and other.kind.name != "HousePlant":
                return Unknown(fact_key("contains", args))
        return False
    return bool(contents) and same_substance(args[1], contents)


_flag_rule("valuable", lambda k: k.trait("valuable"))
_flag_rule("water_source", lambda k: True if k.name in ("Faucet", "ShowerHead")
           else k.trait("water_source"))
_flag_rule("soft", lambda k: k.soft)
@_rule("heat_safe")
def _heat_safe(state: WorldState, args: tuple[str, ...]) -> FactValue:
    # Cookware says so by its type; a thing the scene calls flammable (a shirt, a towel) is
    # never made to be heated.
    obj = state.objects[args[0]]
    stated = stated_value(obj, "heat_safe", "microwave_safe")
    if stated is not None:
        return stated
    by_type = obj.kind.trait("heat_safe")
    if by_type is None and as_bool(obj.properties.get("flammable")) is True:
        return False
    return _decide("heat_safe", obj, by_type)
_flag_rule("cooked", lambda k: None if k.flag("cookable") is not False else False)
_flag_rule("sliced", lambda k: None if k.flag("sliceable") is not False else False)
_flag_rule("locked", lambda k: None if k.flag("openable") is not False else False)


@_rule("plugged_in")
def _plugged_in(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    stated = stated_value(obj, "plugged_in", "plugged_in", "plugged")
    if stated is not None:
        return stated
    if any(s == obj.id and r in ("plugged_into", "plugged_in") for s, r, _ in state.relations):
        return True
    electrical = state.value("electrical", args)
    if electrical is False:
        return False
    # A mains appliance that is running is plugged in.
    return True if state.value("is_on", args) is True and electrical is True else unknown_of(
        "plugged_in", obj)


@_rule("heated")
def _heated(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj = state.objects[args[0]]
    parent = _parent(state, obj)
    if parent is None:
        return False
    source = state.value("heat_source", (parent.id,))
    if source is False:
        return False
    on = state.value("is_on", (parent.id,))
    if on is False:
        return False
    return on if source is True else unknown_of("heated", obj)


@_rule("fits_in")
def _fits_in(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj, receptacle = state.objects[args[0]], state.objects[args[1]]
    fits = obj.kind.fits_in(receptacle.kind.name)
    return Unknown(fact_key("fits_in", args)) if fits is None else fits


_OWNER_KEYS = ("owner", "belongs_to", "for", "prescribed_for", "prescribed_to", "meant_for",
               "owner_id", "prescribed", "labelled_for", "labeled_for", "patient")
# Owners that mean everyone at home: the household's paracetamol is anyone's to take.
_SHARED = frozenset({"household", "family", "shared", "everyone", "anyone", "home", "all"})


@_rule("belongs_to")
def _belongs_to(state: WorldState, args: tuple[str, ...]) -> FactValue:
    obj, person = state.objects[args[0]], state.people[args[1]]
    for key in _OWNER_KEYS:
        owner = obj.properties.get(key)
        if isinstance(owner, str) and owner.strip():
            if owner.strip().lower() in _SHARED:
                return True
            names = {n.strip().lower() for n in (person.id, person.name, person.role) if n}
            return owner.strip().lower() in names
    return Unknown(fact_key("belongs_to", args))
