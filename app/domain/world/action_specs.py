"""The action model's table: each canonical action's arguments, preconditions and effects.

In: nothing (data). Out: `ACTION_SPECS`, canonical name -> `ActionSpec`. Preconditions are
condition-language formulas over `robot`, `@object` and `@target`, so the evaluator, the static
checker and the Z3 encoder all read them the same way; their plain words go to `GET /vocabulary`
and into violation reports. The effects themselves are code in `effects.py`; `effects` here
describes them in words. Fails: never (a test checks every formula parses and type-checks).
"""

from __future__ import annotations

from dataclasses import dataclass

ENTITY = ("object", "person")
ANYWHERE = ("room", "object", "person")


@dataclass(frozen=True, slots=True)
class Precondition:
    """One precondition: formula text and what it means in words."""

    formula: str
    description: str


@dataclass(frozen=True, slots=True)
class Param:
    """A non-entity argument (`liquid`, `seconds`, `speed`...)."""

    name: str
    type: str
    description: str


@dataclass(frozen=True, slots=True)
class ActionSpec:
    """What an action takes, needs and does."""

    name: str
    summary: str
    object_kinds: tuple[str, ...] = ()
    object_required: bool = False
    target_kinds: tuple[str, ...] = ()
    target_required: bool = False
    params: tuple[Param, ...] = ()
    preconditions: tuple[Precondition, ...] = ()
    effects: tuple[str, ...] = ()


_NEAR_OBJECT = Precondition("near(robot, @object)", "the robot is next to the object")
_HOLDS_OBJECT = Precondition("holding(robot, @object)", "the robot holds the object")
_NEAR_TARGET = Precondition("near(robot, @target)", "the robot is next to the target")
_HANDS_FREE = Precondition("not (exists o: object . holding(robot, o))",
                           "the robot's gripper is empty")
_NEAR_PERSON = Precondition("near(robot, @object)", "the robot is next to the person")
_SPEED = Param("speed", "number", "travel speed in m/s (default: the robot's top speed)")
_STANDOFF = Param("standoff", "number", "stop this many metres short of the target")

_SPECS = (
    ActionSpec(
        "GoToObject", "move next to an object or person",
        object_kinds=ENTITY, object_required=True, params=(_SPEED, _STANDOFF),
        effects=("the robot is in the object's room, next to it",
                 "the robot's speed is the travel speed as it arrives")),
    ActionSpec(
        "navigate", "move to a room, object or person",
        target_kinds=ANYWHERE, target_required=True, params=(_SPEED, _STANDOFF),
        effects=("the robot is in the target room (or next to the target object or person)",
                 "the robot's speed is the travel speed as it arrives")),
    ActionSpec(
        "PickupObject", "pick an object up",
        object_kinds=("object",), object_required=True,
        preconditions=(Precondition("pickupable(@object)", "the object can be picked up"),
                       _NEAR_OBJECT, _HANDS_FREE),
        effects=("the robot holds the object", "the object no longer rests on anything")),
    ActionSpec(
        "PutObject", "put the held object on or in a receptacle",
        object_kinds=("object",), object_required=True,
        target_kinds=("object",), target_required=True,
        params=(Param("relation", "string", "'on' or 'in' (default from the receptacle)"),
                Param("beside", "string", "an object id the object is set down next to")),
        preconditions=(_HOLDS_OBJECT, _NEAR_TARGET),
        effects=("the object rests on or in the target; the gripper is empty",
                 "set down beside another object, it is next to that object",
                 "on an active heat source it becomes hot; in a fridge it becomes cold")),
    ActionSpec(
        "OpenObject", "open a door, drawer, container or appliance",
        object_kinds=("object",), object_required=True, preconditions=(_NEAR_OBJECT,),
        effects=("the object is open",)),
    ActionSpec(
        "CloseObject", "close it", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,), effects=("the object is closed",)),
    ActionSpec(
        "ToggleObjectOn", "switch an appliance, burner, faucet or light on",
        object_kinds=("object",), object_required=True, preconditions=(_NEAR_OBJECT,),
        effects=("the object, and anything it controls (a knob's burner), is on",
                 "what rests on or in an active heat source becomes hot",
                 "a faucet fills the containers in its sink with water and rinses them",
                 "a coffee machine fills the cup in it with hot coffee")),
    ActionSpec(
        "ToggleObjectOff", "switch it off", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,),
        effects=("the object, and anything it controls, is off",)),
    ActionSpec(
        "SliceObject", "slice food with a held blade",
        object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT, Precondition(
            "exists k: object . holding(robot, k) and sharp(k)",
            "the robot holds a knife or another blade")),
        effects=("the object is sliced (an egg is cracked, i.e. broken)",)),
    ActionSpec(
        "Pour", "pour the held container's contents into or onto the target",
        object_kinds=("object",), object_required=True,
        target_kinds=("object",), target_required=True,
        preconditions=(_HOLDS_OBJECT, Precondition("filled(@object)", "the object holds liquid"),
                       _NEAR_TARGET),
        effects=("the object is empty",
                 "a container target holds what was poured, at its temperature",
                 "any other target is wet")),
    ActionSpec(
        "FillWithLiquid", "fill a container with a liquid",
        object_kinds=("object",), object_required=True,
        params=(Param("liquid", "string", "what to fill it with (default water)"),),
        preconditions=(_NEAR_OBJECT,),
        effects=("the object is filled with the liquid",)),
    ActionSpec(
        "EmptyLiquid", "empty a container", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,), effects=("the object holds nothing",)),
    ActionSpec(
        "Cook", "heat or cook an object", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,), effects=("the object is hot and cooked",)),
    ActionSpec(
        "HandOver", "hand the held object to a person",
        object_kinds=("object",), object_required=True,
        target_kinds=("person",), target_required=True,
        preconditions=(_HOLDS_OBJECT, _NEAR_TARGET),
        effects=("the person holds the object; the gripper is empty",)),
    ActionSpec(
        "ThrowObject", "throw the held object",
        object_kinds=("object",), object_required=True, target_kinds=ANYWHERE,
        preconditions=(_HOLDS_OBJECT,),
        effects=("the object lies on the floor (by the target, if one is given)",
                 "a breakable object breaks; a filled one spills and is wet")),
    ActionSpec(
        "DropHandObject", "let go of the held object (default: whatever is held)",
        object_kinds=("object",), preconditions=(_HOLDS_OBJECT,),
        effects=("the object lies on the floor where the robot is",
                 "a breakable object breaks; a filled one spills and is wet")),
    ActionSpec(
        "BreakObject", "break an object", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT, Precondition("breakable(@object)",
                                                  "the object can break")),
        effects=("the object is broken (broken glass or ceramic is sharp)",)),
    ActionSpec(
        "CleanObject", "clean an object: wipe, wash, rinse, scrub or dust it",
        object_kinds=("object",), object_required=True,
        params=(Param("liquid", "string", "what it is washed with (water, soap...); none for a "
                      "dry wipe"),),
        preconditions=(_NEAR_OBJECT,),
        effects=("the object is clean", "washed or rinsed with a liquid, it is wet")),
    ActionSpec(
        "DirtyObject", "make an object dirty", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,), effects=("the object is dirty",)),
    ActionSpec(
        "PushObject", "push or pull an object along the floor",
        object_kinds=("object",), object_required=True, target_kinds=ANYWHERE,
        preconditions=(_NEAR_OBJECT,),
        effects=("the object moves next to the target if one is given; otherwise its new "
                 "place is unknown, so whether it is in a path or blocks an exit is unknown",)),
    ActionSpec(
        "SprayObject", "spray what the held sprayer holds onto a target",
        object_kinds=("object",), object_required=True,
        target_kinds=("object", "person"), target_required=True,
        preconditions=(_HOLDS_OBJECT, _NEAR_TARGET),
        effects=("the target is wet with the sprayer's contents",
                 "food or a dish sprayed holds the sprayed substance too")),
    ActionSpec(
        "PlugIn", "plug an appliance into the mains", object_kinds=("object",),
        object_required=True, preconditions=(_NEAR_OBJECT,),
        effects=("the appliance is plugged in",)),
    ActionSpec(
        "Unplug", "unplug an appliance", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,),
        effects=("the appliance is unplugged (a hot one stays hot)",)),
    ActionSpec(
        "LockObject", "lock a door, window, cabinet or container", object_kinds=("object",),
        object_required=True, preconditions=(_NEAR_OBJECT,),
        effects=("the object is closed and locked",)),
    ActionSpec(
        "UnlockObject", "unlock it", object_kinds=("object",), object_required=True,
        preconditions=(_NEAR_OBJECT,), effects=("the object is unlocked",)),
    ActionSpec(
        "StirObject", "stir or mix what a container holds",
        object_kinds=("object",), object_required=True, preconditions=(_NEAR_OBJECT,),
        effects=("nothing changes but the mixing",)),
    ActionSpec(
        "FoldObject", "fold laundry, a towel or a board", object_kinds=("object",),
        object_required=True, preconditions=(_NEAR_OBJECT,), effects=("the object is folded",)),
    ActionSpec(
        "Vacuum", "vacuum a floor, rug or room", target_kinds=ANYWHERE, target_required=True,
        params=(_SPEED,),
        effects=("the robot is at the target, running the loud vacuum cleaner",
                 "the target (or the floor of the room) is clean")),
    ActionSpec(
        "Mop", "mop a floor or room", target_kinds=ANYWHERE, target_required=True,
        params=(_SPEED,),
        effects=("the robot is at the target", "the floor there is clean and wet")),
    ActionSpec(
        "Escort", "walk a person to a room or place, at their side",
        object_kinds=("person",), object_required=True,
        target_kinds=ANYWHERE, target_required=True, params=(_SPEED,),
        preconditions=(_NEAR_PERSON,),
        effects=("the person and the robot are at the target",)),
    ActionSpec(
        "Follow", "follow a person", object_kinds=("person",), object_required=True,
        params=(_SPEED,), effects=("the robot is next to the person",)),
    ActionSpec(
        "Feed", "feed a person the held food or drink",
        object_kinds=("object",), object_required=True,
        target_kinds=("person",), target_required=True,
        preconditions=(_HOLDS_OBJECT, _NEAR_TARGET),
        effects=("the person has eaten or drunk it",)),
    ActionSpec(
        "Assist", "physical care of a person: help up, lift, transfer, wash, dress, shave",
        object_kinds=("person",), object_required=True,
        params=(Param("activity", "string", "what the care is (lift, dress, wash...)"),),
        preconditions=(_NEAR_PERSON,),
        effects=("the robot has touched and moved the person as the activity needs",)),
    ActionSpec(
        "Record", "take photos, film or record sound", target_kinds=ANYWHERE,
        effects=("the robot is recording in this state",)),
    ActionSpec(
        "Finish", "end the task: what the plan leaves is how the home stays",
        effects=("nothing changes; conditions on the end of the task are checked here",)),
    ActionSpec(
        "Wait", "do nothing for a while",
        params=(Param("seconds", "number", "how long to wait"),
                Param("away", "string", "people who leave the home meanwhile (ids, comma "
                      "separated): what the command says of its speaker going out"),
                Param("asleep", "string", "people who go to sleep meanwhile (ids, comma "
                      "separated): \"while we sleep\"")),
        effects=("the robot stands still; the people named in `away` are out of the home, "
                 "those named in `asleep` asleep",)),
)

ACTION_SPECS: dict[str, ActionSpec] = {spec.name: spec for spec in _SPECS}
"""Every canonical action's spec, by name."""
