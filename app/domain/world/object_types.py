"""What an object's type tells about it: AI2-THOR capabilities plus hazard knowledge.

In: an object type as a request gives it (an AI2-THOR type such as `StoveBurner`, or a plain
noun such as "kitchen knife"). Out: a `TypeInfo` whose `flag`/`trait` lookups answer True,
False, or None when the type does not determine the answer. The AI2-THOR part comes from the
one AI2-THOR type table (`ai2thor_table.py`: `data/ai2thor_types.json`), with the receptacles
AI2-THOR's documentation lists for each type; the hazard traits (sharp, electrical, toxic,
valuable...) are our own table below. A plain noun that is no AI2-THOR type ("wallet", "hair
dryer") is read through the object concepts (`concepts.py`): the AI2-THOR type the concept is,
plus the concept's properties as traits. Fails: never; an unrecognised type answers None to every
question, so every fact about it stays unknown.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from app.domain.world.ai2thor_table import ai2thor_types
from app.domain.world.concepts import Concept, concept_of, modifier_concepts

# Hazard traits by type. An AI2-THOR type not listed under a trait does not have it (False);
# None marks a type where it depends on the instance (a spray bottle may hold water or bleach).
_TRAITS: dict[str, dict[str, bool | None]] = {
    "sharp": {
        "Knife": True, "ButterKnife": True, "Fork": True, "Scissors": True, "Razor": True,
        "Cleaver": True, "Saw": True, "Axe": True, "Needle": True, "Skewer": True,
        "Pen": None, "Pencil": None,
    },
    "electrical": {
        "Toaster": True, "Microwave": True, "CoffeeMachine": True, "Laptop": True,
        "Television": True, "Desktop": True, "DeskLamp": True, "FloorLamp": True,
        "CellPhone": True, "AlarmClock": True, "VacuumCleaner": True, "Fridge": True,
        "LightSwitch": True, "StoveBurner": None, "StoveKnob": None, "Kettle": None,
        "Iron": True, "Heater": True, "Oven": True, "Stove": None, "HairDryer": True,
        "Blender": True, "Fan": True, "PowerStrip": True, "Outlet": True,
        "ExtensionCord": True, "Cable": True, "Charger": True, "ElectricKettle": True,
        "WashingMachine": True, "Dishwasher": True, "Lamp": True,
    },
    "heat_source": {
        "Candle": True, "Oven": True, "Stove": True, "Heater": True, "Iron": True,
        "Fireplace": True, "Grill": True, "ElectricKettle": True, "HairDryer": True,
    },
    "toxic": {
        "SprayBottle": None, "SoapBottle": None, "Bleach": True, "Detergent": True,
        "CleaningSpray": True, "Pesticide": True, "Poison": True, "DrainCleaner": True,
        "LaundryPod": True, "Battery": True,
    },
    "flammable": {
        "Candle": True, "Newspaper": True, "AluminumFoil": False, "Lighter": True,
        "Matches": True, "Gasoline": True,
    },
    "allergen": {"Bread": True, "Egg": True},
    "medication": {
        "Medicine": True, "Medication": True, "Pill": True, "Pills": True,
        "PillBottle": True, "Inhaler": True, "InsulinPen": True, "EpiPen": True,
        "PillOrganizer": True, "PillOrganiser": True, "PillBox": True, "Dosette": True,
        "MedicineBottle": True, "Tablets": True, "Syringe": True,
    },
    "walking_aid": {
        "Walker": True, "Cane": True, "Crutch": True, "Crutches": True, "Wheelchair": True,
        "Rollator": True, "WalkingStick": True, "WalkingFrame": True,
    },
    # What a person relies on to see, hear, move or call for help.
    "personal_aid": {
        "Glasses": True, "HearingAid": True, "Dentures": True, "CallButton": True,
        "CallBell": True, "AlarmPendant": True, "Walker": True, "Cane": True, "Crutch": True,
        "Crutches": True, "Wheelchair": True, "Rollator": True, "WalkingStick": True,
        "WalkingFrame": True,
    },
    # Devices keeping someone breathing or fed, and the switches that cut the home's power.
    "life_support": {
        "OxygenConcentrator": True, "Ventilator": True, "CPAP": True, "CpapMachine": True,
        "FeedingPump": True, "InfusionPump": True, "DialysisMachine": True,
    },
    "mains_switch": {
        "FuseBox": True, "CircuitBreaker": True, "Breaker": True, "ConsumerUnit": True,
        "MainSwitch": True, "BreakerPanel": True, "ElectricalPanel": True,
    },
    "ignition": {"Lighter": True, "Matches": True, "Matchbox": True},
    "oxygen_supply": {"OxygenConcentrator": True, "OxygenCylinder": True, "OxygenTank": True},
    "open_flame": {"Candle": True, "Fireplace": True, "OilLamp": True},
    "safety_barrier": {
        "BabyGate": True, "SafetyGate": True, "StairGate": True, "StoveGuard": True,
        "FireGuard": True, "BedRail": True, "Railing": True, "ChildLock": True,
        "SafetyLock": True,
    },
    "small": {"Pill": True, "Pills": True, "Battery": True, "Coin": True, "Marble": True},
    # Things whose loss or destruction is a real loss to someone: money, documents, devices,
    # keepsakes and the personal aids people depend on.
    "valuable": {
        "CreditCard": True, "Wallet": True, "Watch": True, "CellPhone": True, "Laptop": True,
        "KeyChain": True, "Painting": True, "Book": None, "Statue": None, "Vase": None,
        "Desktop": True, "Television": True, "Glasses": True, "HearingAid": True,
        "Dentures": True, "Jewelry": True, "Ring": True, "Passport": True,
    },
    # Made to hold food or drink while it is heated (in a microwave, on a burner, in a kettle).
    "heat_safe": {
        "Bowl": True, "Cup": True, "Mug": True, "Plate": True, "Pot": True, "Pan": True,
        "Kettle": True, "ElectricKettle": True, "BakingTray": True, "Teapot": True,
        "FoilTray": True, "Tray": None, "IroningBoard": True, "StoveBurner": True,
        "Oven": True, "Trivet": True, "StoveTop": True, "Hob": True,
    },
}

# What an object concept's properties say about the traits and flags of its instances.
_CONCEPT_TRAITS = {
    "sharp": "sharp", "electrical": "electrical", "toxic": "toxic", "flammable": "flammable",
    "medication": "medication", "walking_aid": "walking_aid", "safety_barrier": "safety_barrier",
    "personal_aid": "personal_aid", "life_support": "life_support",
    "mains_switch": "mains_switch", "small": "small", "personal": "valuable",
    "sentimental": "valuable", "food": "food", "metal": "metal", "heavy": "heavy",
    "ignition": "ignition", "camera": "camera", "water_source": "water_source", "toy": "toy",
    "noisy": "noisy", "oxygen_supply": "oxygen_supply",
    "open_flame": "open_flame",
}
_RARE_TRAITS = ("walking_aid", "personal_aid", "life_support", "mains_switch", "ignition",
                "safety_barrier", "medication", "valuable", "water_source", "oxygen_supply",
                "open_flame")
_LISTED_TRAITS = frozenset({"sharp", "electrical", "toxic", "flammable", "medication",
                            "walking_aid", "personal_aid", "life_support", "mains_switch",
                            "ignition", "safety_barrier", "small",
                            "valuable", "food", "metal", "heavy", "water_source",
                            "oxygen_supply", "open_flame"})
_CONCEPT_FLAGS = {"heat_source": "heat_source", "fragile": "breakable", "container": "receptacle"}

# Types outside AI2-THOR that requests commonly name, with the capabilities they surely have.
_EXTRA_FLAGS: dict[str, dict[str, bool]] = {
    "Glass": {"pickupable": True, "breakable": True, "can_fill": True, "receptacle": True},
    "WineGlass": {"pickupable": True, "breakable": True, "can_fill": True, "receptacle": True},
    "Jar": {"pickupable": True, "breakable": True, "can_fill": True, "openable": True},
    "Teapot": {"pickupable": True, "breakable": True, "can_fill": True},
    "Bucket": {"pickupable": True, "can_fill": True, "receptacle": True},
    "MopBucket": {"pickupable": True, "can_fill": True, "receptacle": True},
    "Scissors": {"pickupable": True},
    "Bleach": {"pickupable": True, "can_fill": True, "openable": True},
    "Detergent": {"pickupable": True, "can_fill": True, "openable": True},
    "PillBottle": {"pickupable": True, "openable": True},
    "Oven": {"openable": True, "toggleable": True, "receptacle": True},
    "Stove": {"toggleable": True, "receptacle": True},
    "Iron": {"pickupable": True, "toggleable": True},
    "Heater": {"toggleable": True},
    "ElectricKettle": {"pickupable": True, "toggleable": True, "can_fill": True},
    "Walker": {"moveable": True},
    "Cane": {"pickupable": True},
    "Wheelchair": {"moveable": True},
    "BabyGate": {"openable": True, "moveable": True},
    "Door": {"openable": True},
    "Window": {"openable": True},
}

# AI2-THOR flags that vary by instance where the household meaning does not: one scene's
# fridge lacks `isColdSource`, yet a fridge chills what is put in it.
_FLAG_OVERRIDES: dict[str, dict[str, bool]] = {"Fridge": {"cold_source": True}}

# Surfaces and containers an object is put *in* rather than *on*.
CONTAINER_TYPES = frozenset({
    "Fridge", "Drawer", "Cabinet", "Microwave", "Sink", "SinkBasin", "Bathtub", "BathtubBasin",
    "GarbageCan", "Bowl", "Cup", "Mug", "Pot", "Box", "LaundryHamper", "Toilet", "Safe", "Kettle",
    "Oven", "Glass", "Jar", "Dishwasher", "WashingMachine",
})

# Types that hold a substance deciding their hazards although AI2-THOR cannot fill them.
_SUBSTANCE_HOLDERS = frozenset({"SprayBottle", "SoapBottle", "PillBottle", "Bleach", "Detergent"})

_FLAMMABLE_MATERIALS = frozenset({"Paper", "Fabric", "Wax"})
_NON_ALNUM = re.compile(r"[^a-z0-9]")


def normalize_type(name: str) -> str:
    """The lookup key of a type name: lower case, letters and digits only."""
    return _NON_ALNUM.sub("", name.lower())


@dataclass(frozen=True, slots=True)
class TypeInfo:
    """What is known about one object type; every lookup answers True, False or None."""

    name: str
    known: bool
    flags: dict[str, bool | None] = field(default_factory=dict)
    traits: dict[str, bool | None] = field(default_factory=dict)
    mass_kg: tuple[float, float] | None = None
    materials_all: frozenset[str] = frozenset()
    materials_some: frozenset[str] = frozenset()
    size_m: tuple[float, float, float] | None = None
    receptacles: frozenset[str] = frozenset()
    """AI2-THOR types this type may be put in or on (empty when the table does not say)."""
    described: bool = False
    """Not an AI2-THOR type, but an object concept says what it is."""

    def flag(self, name: str) -> bool | None:
        """An AI2-THOR capability (`pickupable`, `breakable`, `can_fill`, `heat_source`...)."""
        if name in self.flags:
            return self.flags[name]
        return False if self.known else None

    def trait(self, name: str) -> bool | None:
        """A hazard trait (`sharp`, `electrical`, `toxic`...) the type determines, else None."""
        if name in self.traits:
            return self.traits[name]
        return False if self.known else None

    def material(self, name: str) -> bool | None:
        """Whether instances of the type are made (partly) of `name`, e.g. `Metal`."""
        if name in self.materials_all:
            return True
        if name in self.materials_some or not self.known or not self.materials_all:
            return None
        return False

    @property
    def is_container(self) -> bool | None:
        """Whether it can hold a substance (a liquid, food, pills) that decides its hazards."""
        fill, receptacle, pickup = self.flag("can_fill"), self.flag("receptacle"), self.flag(
            "pickupable")
        if fill or (receptacle and pickup) or self.name in _SUBSTANCE_HOLDERS:
            return True
        if fill is False and receptacle is False:
            return False
        if fill is None or receptacle is None or pickup is None:
            return None
        return False

    @property
    def is_food(self) -> bool | None:
        """Food by material; a known type without recorded materials is a fixture, not food."""
        if "food" in self.traits and self.traits["food"] is not None:
            return self.traits["food"]
        if "Food" in self.materials_all:
            return True
        return None if "Food" in self.materials_some or not self.known else False

    @property
    def soft(self) -> bool | None:
        """Soft and light enough to toss without harm (fabric, sponge, paper)."""
        soft_materials = {"Fabric", "Sponge", "Paper"}
        if self.materials_all and self.materials_all <= soft_materials:
            return True
        if not self.known or self.materials_some & soft_materials:
            return None
        return False

    def fits_in(self, receptacle: str) -> bool | None:
        """Whether AI2-THOR lets an object of this type be put in or on a receptacle type."""
        if not self.receptacles:
            return None
        return normalize_type(receptacle) in {normalize_type(r) for r in self.receptacles}

    @property
    def flammable_by_material(self) -> bool | None:
        if self.materials_all & _FLAMMABLE_MATERIALS:
            return True
        if self.materials_some & _FLAMMABLE_MATERIALS or not self.known:
            return None
        return False


@cache
def _table() -> dict[str, TypeInfo]:
    raw = ai2thor_types()
    names = set(raw) | set(_EXTRA_FLAGS) | {t for table in _TRAITS.values() for t in table}
    infos: dict[str, TypeInfo] = {}
    for name in sorted(names):
        row: Mapping[str, Any] | None = raw.get(name)
        base = name.removesuffix("Sliced").removesuffix("Cracked")
        if base != name and row is not None and not row["flags"] and base in raw:
            # AI2-THOR's "BreadSliced" has no metadata of its own: it is bread, in pieces
            row = {**raw[base], "receptacles": row.get("receptacles") or raw[base].get(
                "receptacles", ())}
        traits = {trait: table[name] for trait, table in _TRAITS.items() if name in table}
        if row is not None and row["flags"]:
            mass = row["mass_kg"]
            size = row["size_m"]
            flags = dict(row["flags"])
            if traits.get("heat_source"):
                flags["heat_source"] = True
            flags.update(_FLAG_OVERRIDES.get(name, {}))
            info = TypeInfo(
                name, True, flags, traits,
                (float(mass[0]), float(mass[1])) if mass else None,
                frozenset(row["materials_all"]), frozenset(row["materials_some"]),
                (float(size[0]), float(size[1]), float(size[2])) if size else None,
                frozenset(row.get("receptacles", ())),
            )
        else:
            flags = {k: v for k, v in _EXTRA_FLAGS.get(name, {}).items()}
            if "heat_source" in traits:
                flags["heat_source"] = traits["heat_source"]
            rare = {trait: False for trait in _RARE_TRAITS if trait not in traits}
            for flag in ("toggleable", "heat_source"):
                flags.setdefault(flag, bool(traits.get(flag)))
            info = TypeInfo(name, False, dict(flags), {**rare, **traits})
        infos[normalize_type(name)] = info
    return infos


def _positive_only(info: TypeInfo, name: str) -> TypeInfo:
    """A type named by a longer noun ("kitchen knife"): keep what it surely has, not what not."""
    return TypeInfo(
        name, False,
        {k: v for k, v in info.flags.items() if v},
        {k: v for k, v in info.traits.items() if v},
        info.mass_kg, info.materials_all, info.materials_some, info.size_m, info.receptacles,
    )


def _concept_base(name: str, concept: Concept, table: dict[str, TypeInfo]) -> TypeInfo | None:
    """The AI2-THOR type a noun of the concept most likely is: the one its words name ("phone"
    is a CellPhone, not the concept's first type, a Laptop), the only one, or none."""
    bases = [table[normalize_type(t)] for t in concept.types if normalize_type(t) in table]
    head = normalize_type(name.split()[-1]) if name.split() else ""
    named = [b for b in bases if head and (head in normalize_type(b.name)
                                           or normalize_type(b.name) in normalize_type(name))]
    if named:
        return named[0]
    return bases[0] if len(bases) == 1 else None


def _from_concept(name: str, concept: Concept, table: dict[str, TypeInfo]) -> TypeInfo:
    """A plain noun's knowledge: its concept's AI2-THOR type (what it surely has) plus the
    concept's properties; a concept without a clear type knows only its properties."""
    base = _concept_base(name, concept, table)
    # The noun is an instance of that AI2-THOR type: what the type never does, it does not.
    flags: dict[str, bool | None] = dict(base.flags) if base else {}
    traits: dict[str, bool | None] = (
        {k: v for k, v in base.traits.items() if v} if base else {})
    own = table.get(normalize_type(name))
    if own is not None:
        flags.update({k: v for k, v in own.flags.items() if v is not None})
        traits.update({k: v for k, v in own.traits.items() if v is not None})
    for prop in concept.props:
        if prop in _CONCEPT_TRAITS:
            traits[_CONCEPT_TRAITS[prop]] = True
        if prop in _CONCEPT_FLAGS:
            flags[_CONCEPT_FLAGS[prop]] = True
    if "fixed" in concept.props:
        flags.setdefault("pickupable", False)
        flags.setdefault("moveable", False)
    elif "furniture" not in concept.props:
        flags.setdefault("pickupable", True)
    # A concept lists its hazard properties: what it does not list, its instances are not,
    # except what a container's contents decide.
    holds = "container" in concept.props
    for trait in _LISTED_TRAITS - ({"toxic", "medication", "food", "flammable"} if holds
                                   else set()):
        traits.setdefault(trait, False)
    if not holds:
        flags.setdefault("can_fill", False)
        flags.setdefault("receptacle", False)
    powered = bool(concept.props & {"appliance", "light", "electrical", "heat_source"})
    flags.setdefault("toggleable", powered)
    flags.setdefault("heat_source", "heat_source" in concept.props)
    mass = base.mass_kg if base else None
    word_mass = concept.word_mass_of(name)  # a radio is no television, whatever TVs weigh
    if word_mass is not None:
        mass = (word_mass, word_mass)
    elif mass is None and concept.mass_kg is not None:
        mass = (float(concept.mass_kg), float(concept.mass_kg))  # the concept's typical mass
    # "the top step" is the Stairs: a concept of one type names instances by that type
    named = base.name if base else (concept.types[0] if len(concept.types) == 1 else name)
    return TypeInfo(
        named, False, flags, traits, mass,
        base.materials_all if base else frozenset(), base.materials_some if base else frozenset(),
        base.size_m if base else None, base.receptacles if base else frozenset(),
        described=True,
    )


@cache
def type_info(name: str) -> TypeInfo:
    """The knowledge for a type name: exact AI2-THOR/extra match, else the object concept the
    noun names, else the longest known type the name ends with (positive facts only), else an
    unknown type.

    Args:
        name: the object's `type` as given.

    Returns:
        Its `TypeInfo`; never raises.
    """
    key = normalize_type(name)
    table = _table()
    if key in table and table[key].known:
        return table[key]
    concept = concept_of(name)
    if concept is not None:
        return _from_concept(name, concept, table)
    if key in table:
        return table[key]
    for length in range(len(key) - 1, 2, -1):
        suffix = key[-length:]
        if suffix in table:
            return _positive_only(table[suffix], name)
    return _ordinary(name)


def _ordinary(name: str) -> TypeInfo:
    """A thing no table places under a hazardous kind is an ordinary object: not sharp, toxic,
    hot, electrical, heavy or valuable, holding nothing; only what a modifier names ("solvent
    drum", "petrol can") adds a hazard. Its size and whether it breaks stay unknown."""
    traits: dict[str, bool | None] = {t: False for t in (*_LISTED_TRAITS, *_RARE_TRAITS)}
    for concept in modifier_concepts(name):
        for prop in concept.props & {"toxic", "medication", "flammable"}:
            traits[prop] = True
    traits["small"] = None
    flags: dict[str, bool | None] = {"can_fill": False, "receptacle": False,
                                     "toggleable": False, "heat_source": False,
                                     "openable": False, "cookable": False}
    return TypeInfo(name, False, flags, traits, described=True)
