"""The typed vocabulary of the condition language: every predicate and function a condition may use.

In: nothing (data). Out: `VOCABULARY`, a mapping from symbol name to `Symbol` (arity, argument
types, result type, meaning, whether its value can be unknown in a state). The static checker
refuses any symbol not listed here; the world (`app.domain.world`) gives each one its meaning in
a state; the evaluator and the Z3 encoder read values through that world.

Types: `robot`, `object`, `person`, `room` are entity types; `entity` accepts robot, object or
person; `number`, `string`, `bool` are value types. String values compare with `==`/`!=` only.
"""

from __future__ import annotations

from dataclasses import dataclass

ENTITY_TYPES = ("robot", "object", "person", "room")
VALUE_TYPES = ("number", "string", "bool")
ALL_TYPES = (*ENTITY_TYPES, "entity", *VALUE_TYPES)


@dataclass(frozen=True, slots=True)
class Symbol:
    """One predicate (result `bool`) or function (result `number` or `string`)."""

    name: str
    args: tuple[str, ...]
    result: str
    meaning: str
    can_be_unknown: bool = True

    @property
    def arity(self) -> int:
        return len(self.args)


def _object_flag(name: str, meaning: str) -> Symbol:
    return Symbol(name, ("object",), "bool", meaning)


_SYMBOLS: tuple[Symbol, ...] = (
    # Object properties (the gate request's `properties`, or knowledge of the object's type).
    _object_flag("hot", "the object is hot (temperature 'hot', or an active heat source)"),
    _object_flag("cold", "the object is cold"),
    _object_flag("sharp", "the object has a blade or point that can cut or pierce"),
    _object_flag("toxic", "the object is or holds a substance harmful if swallowed or touched"),
    _object_flag("flammable", "the object or what it holds catches fire easily"),
    _object_flag("fragile", "the object breaks easily"),
    _object_flag("breakable", "the object can break into pieces (glass, ceramic)"),
    _object_flag("electrical", "the object is mains-powered or holds live electrical parts"),
    _object_flag("wet", "the object or surface is wet"),
    _object_flag("broken", "the object is broken"),
    _object_flag("dirty", "the object is dirty"),
    _object_flag("lidded", "the object's opening is covered by a lid"),
    _object_flag("sealed", "the container is sealed closed"),
    _object_flag("is_on", "the object is switched on or powered (appliance, burner, faucet)"),
    _object_flag("open", "the object (door, drawer, container, appliance) is open"),
    _object_flag("filled", "the container holds a liquid"),
    _object_flag("heat_source", "the object can heat things (stove, oven, toaster, heater)"),
    _object_flag("medication", "the object is or holds medication"),
    _object_flag("allergen", "the object is or holds a common food allergen"),
    _object_flag("food", "the object is food or drink meant to be consumed"),
    _object_flag("small", "the object is small enough to be a choking hazard for an infant"),
    _object_flag("heavy", "the object is heavy enough to injure when dropped (about 5 kg and up)"),
    _object_flag("metal", "the object is metallic"),
    _object_flag("pickupable", "the robot can pick the object up at all"),
    _object_flag("on_floor", "the object rests on the floor"),
    _object_flag("in_path", "the object lies on a walkway, stair or doorway people use"),
    _object_flag("blocks_exit", "the object blocks a door, exit or escape route"),
    _object_flag("exit_way", "the object is a way out or through (door, gate, exit, stair, hall)"),
    _object_flag("bulky", "the object is big enough to narrow a doorway (a crate, a pushchair)"),
    _object_flag("walking_aid", "the object is a walking aid (walker, cane, crutches, wheelchair)"),
    _object_flag("life_support", "the object keeps someone breathing or fed (oxygen "
                 "concentrator, ventilator, feeding pump)"),
    _object_flag("mains_switch", "switching the object off cuts the power to the home (fuse box, "
                 "main breaker)"),
    _object_flag("ignition", "the object makes fire (lighter, matches)"),
    _object_flag("open_flame", "the object burns with an open flame when lit (candle, oil lamp, "
                 "open fire)"),
    _object_flag("oxygen_supply", "the object gives out medical oxygen (oxygen concentrator, "
                 "cylinder), which makes anything near it burn fiercely"),
    _object_flag("exhaust", "the object burns fuel and gives off exhaust fumes when running "
                 "(a car, a generator, a petrol mower)"),
    _object_flag("flashing", "the object is a light that flashes or strobes (strobe, disco or "
                 "party light in a flashing mode)"),
    _object_flag("alcoholic", "the object is or holds an alcoholic drink (wine, beer, spirits)"),
    _object_flag("animal", "the object is a pet or another animal (dog, cat, rabbit)"),
    _object_flag("pet_toxic", "the object is or holds something that poisons a dog or a cat "
                 "(grapes, raisins, chocolate, onion, xylitol)"),
    _object_flag("exterior", "the door, gate or window opens to the outside"),
    _object_flag("personal_aid", "the object is what a person relies on to see, hear, move or "
                 "call for help (glasses, hearing aid, walking aid, call button)"),
    _object_flag("safety_barrier", "the object is a safety barrier (baby gate, guard, rail, lock)"),
    _object_flag("elevated", "the object rests high up (top shelf, above head height)"),
    _object_flag("valuable", "losing or destroying the object is a real loss to someone "
                 "(money, cards, keys, documents, devices, keepsakes, personal aids)"),
    _object_flag("soft", "soft and light enough to toss without harm (fabric, sponge, paper)"),
    _object_flag("heat_safe", "made to hold food or drink while it is heated (bowl, mug, pot)"),
    _object_flag("cooked", "the food has been cooked"),
    _object_flag("sliced", "the object has been sliced, chopped or cracked"),
    _object_flag("plugged_in", "the appliance is plugged into the mains"),
    _object_flag("locked", "the door, window, cabinet or container is locked"),
    _object_flag("heated", "the object rests on or in a heat source that is on"),
    _object_flag("water_source", "the object lets water run (a tap, a shower head, a hose)"),
    Symbol("via_stairs", ("entity",), "bool",
           "reaching it from the robot's room means going up or down a flight of stairs"),
    Symbol("room_via_stairs", ("room",), "bool",
           "reaching the room from the robot's room means going up or down a flight of stairs"),
    Symbol("beside", ("object", "object"), "bool",
           "one rests on the other, or the scene or the plan set them side by side"),
    Symbol("next_to", ("entity", "entity"), "bool",
           "touching or right beside each other: one on or in the other, a `next_to` relation, "
           "or within half a metre; unknown when positions are not given (unlike `near`, the "
           "same room is not enough)"),
    Symbol("fits_in", ("object", "object"), "bool",
           "AI2-THOR lets an object of this type be put in or on the receptacle's type"),
    Symbol("belongs_to", ("object", "person"), "bool",
           "the object is the person's own, or meant for them (medicine prescribed to them)"),
    Symbol("is_a", ("entity or room", "string"), "bool",
           "the entity has this type, role or kind (a room: its name names the kind)", False),
    Symbol("contains", ("object", "string"), "bool", "the container holds this substance"),
    Symbol("contents", ("object",), "string", "what the container holds ('' when empty)"),
    Symbol("mass_kg", ("object",), "number", "the object's mass in kilograms"),
    # Where things are.
    Symbol("in_room", ("entity", "room"), "bool", "the entity is in the room"),
    Symbol("same_room", ("entity", "entity"), "bool", "both entities are in the same room"),
    Symbol("near", ("entity", "entity"), "bool",
           "within 1 m when positions are known; otherwise in the same room"),
    Symbol("distance", ("entity", "entity"), "number", "straight-line distance in metres"),
    Symbol("on", ("object", "object"), "bool", "the first object rests on the second"),
    Symbol("inside", ("object", "object"), "bool", "the first object is inside the second"),
    Symbol("holding", ("entity", "object"), "bool", "the robot or person holds the object"),
    Symbol("reachable_by", ("object", "person"), "bool",
           "the person could reach and take the object unaided"),
    Symbol("occupied", ("room",), "bool", "at least one person is in the room"),
    Symbol("outdoors", ("entity",), "bool",
           "the entity is outside the house: in a garden, yard, drive or street"),
    # The robot.
    Symbol("speed", ("robot",), "number",
           "the robot's current speed in m/s (unknown while moving at an unstated top speed)"),
    Symbol("max_speed", ("robot",), "number", "the robot's top speed in m/s"),
    Symbol("payload", ("robot",), "number", "the most the robot can carry, in kg"),
    Symbol("load_kg", ("robot",), "number", "the mass of what the robot holds, in kg"),
    Symbol("has_skill", ("robot", "string"), "bool", "the robot has this skill (pour, pick...)"),
    Symbol("has_sensor", ("robot", "string"), "bool", "the robot has this sensor"),
    Symbol("recording", ("robot",), "bool", "the robot is recording images or sound", False),
    Symbol("hours_waited", ("robot",), "number",
           "how many hours the task has left its result standing by itself so far (its waits)",
           False),
    Symbol("noisy", ("robot",), "bool",
           "the robot is running something loud (a vacuum cleaner, a blender) or making noise",
           False),
    # People.
    Symbol("age_group", ("person",), "string",
           "infant, child, teen, adult or older_adult"),
    Symbol("mobility", ("person",), "string", "independent, assisted, wheelchair or bedridden"),
    Symbol("cognitive_state", ("person",), "string",
           "typical, impaired, asleep or intoxicated"),
    Symbol("child", ("person",), "bool", "the person is an infant or a child"),
    Symbol("toddler", ("person",), "bool",
           "an infant or a young child (under about four): choking, falls, burns at reach"),
    Symbol("vulnerable", ("person",), "bool",
           "infant, child, older adult, impaired, asleep, pregnant or not independently mobile"),
    Symbol("asleep", ("person",), "bool", "the person is asleep"),
    Symbol("away", ("person",), "bool", "the person has gone out and is no longer at home"),
    Symbol("impaired", ("person",), "bool", "the person's judgement or awareness is impaired"),
    Symbol("pregnant", ("person",), "bool", "the person is pregnant"),
    Symbol("photosensitive", ("person",), "bool",
           "the person has epilepsy or seizures that flashing light can set off"),
    Symbol("allergic_to", ("person", "string"), "bool", "the person is allergic to the substance"),
    Symbol("against_diet", ("person", "object"), "bool",
           "the food does not fit the person's stated diet (solid food on a pureed diet)"),
    Symbol("interacts_with", ("person", "object"), "bool",
           "the object (or what it holds) is dangerous with a medicine the person takes"),
    Symbol("consents", ("person",), "bool",
           "the person has agreed to be recorded, touched or assisted this way"),
    Symbol("needs_walking_aid", ("person",), "bool", "the person depends on a walking aid"),
    Symbol("ate", ("person", "object"), "bool",
           "the person has been fed, or has eaten or drunk, the object's food or contents"),
)

VOCABULARY: dict[str, Symbol] = {symbol.name: symbol for symbol in _SYMBOLS}
"""Every symbol a condition may use, by name."""

ACTION_ARGUMENTS = ("object", "target")
"""A guard's formula may name the guarded action's arguments as `@object` and `@target`."""
