"""Action names: the canonical AI2-THOR/SMART-LLM names, their aliases, and skill families.

In: an action or skill name as a planner or a robot profile spells it (`pick`, `SwitchOn`,
`turn_on`, `PickupObject`...), in any case, with or without underscores. Out:
`canonical_action(name)` -> the canonical name or None; `canonical_skill(name)` -> the skill
family a robot profile lists (`pick`, `place`, `toggle`...). Fails: never.
"""

from __future__ import annotations

import re

_ALIASES: dict[str, tuple[str, ...]] = {
    "GoToObject": ("find", "find_object", "go_to_object", "approach", "go_to_person"),
    "navigate": ("goto", "go_to", "move_to", "navigate_to", "walk_to", "go", "go_to_room",
                 "navigate_to_room", "move"),
    "PickupObject": ("pick", "pickup", "pick_up", "pick_object", "grab", "grab_object", "grasp",
                     "take", "lift"),
    "PutObject": ("put", "place", "place_object", "put_down", "set_down", "put_on", "put_in",
                  "place_on", "place_in", "put_object_in", "stack"),
    "OpenObject": ("open",),
    "CloseObject": ("close", "shut"),
    "ToggleObjectOn": ("turn_on", "switch_on", "toggle_on", "power_on", "turn_on_object",
                       "switch_on_object", "start"),
    "ToggleObjectOff": ("turn_off", "switch_off", "toggle_off", "power_off", "turn_off_object",
                        "switch_off_object", "stop"),
    "SliceObject": ("slice", "cut", "chop"),
    "Pour": ("pour", "pour_into", "pour_liquid", "pour_object", "water"),
    "FillWithLiquid": ("fill", "fill_object_with_liquid", "fill_with"),
    "EmptyLiquid": ("empty", "empty_liquid_from_object", "empty_object"),
    "Cook": ("cook", "cook_object", "heat", "heat_object", "warm", "warm_up", "boil"),
    "HandOver": ("handover", "hand_over", "give", "give_to", "deliver", "hand_to", "hand",
                 "serve"),
    "ThrowObject": ("throw", "toss"),
    "DropHandObject": ("drop", "drop_object", "release", "let_go"),
    "BreakObject": ("break", "smash"),
    "CleanObject": ("clean", "wash", "wipe", "rinse", "scrub", "dust"),
    "DirtyObject": ("dirty", "soil", "make_dirty"),
    "PushObject": ("push", "shove", "pull", "pull_object", "move_object"),
    "SprayObject": ("spray", "spray_object"),
    "PlugIn": ("plug", "plug_in", "plugin", "connect"),
    "Unplug": ("unplug", "plug_out", "disconnect"),
    "LockObject": ("lock",),
    "UnlockObject": ("unlock",),
    "StirObject": ("stir", "mix"),
    "FoldObject": ("fold",),
    "Vacuum": ("vacuum", "hoover", "vacuum_floor"),
    "Mop": ("mop", "mop_floor"),
    "Escort": ("guide", "escort", "walk_with", "accompany"),
    "Follow": ("follow", "follow_person"),
    "Feed": ("feed", "feed_person"),
    "Assist": ("assist", "help", "lift_person", "transfer", "dress", "bathe", "shave"),
    "Record": ("record", "photograph", "take_photo", "film", "capture"),
    "Finish": ("finish", "done", "end", "end_task"),
    "Wait": ("wait", "idle", "pause", "stay"),
}
CANONICAL_ACTIONS: tuple[str, ...] = tuple(_ALIASES)

_SKILL_FAMILY: dict[str, str] = {
    "GoToObject": "navigate", "navigate": "navigate", "PickupObject": "pick",
    "PutObject": "place", "OpenObject": "open", "CloseObject": "close",
    "ToggleObjectOn": "toggle", "ToggleObjectOff": "toggle", "SliceObject": "slice",
    "Pour": "pour", "FillWithLiquid": "fill", "EmptyLiquid": "empty", "Cook": "cook",
    "HandOver": "handover", "ThrowObject": "throw", "DropHandObject": "drop",
    "BreakObject": "break", "CleanObject": "clean", "DirtyObject": "dirty",
    "PushObject": "push", "SprayObject": "spray", "PlugIn": "plug", "Unplug": "plug",
    "LockObject": "lock", "UnlockObject": "lock", "StirObject": "stir", "FoldObject": "fold",
    "Vacuum": "vacuum", "Mop": "mop", "Escort": "escort", "Follow": "navigate",
    "Feed": "feed", "Assist": "assist", "Record": "record", "Finish": "finish", "Wait": "wait",
}
_NON_ALNUM = re.compile(r"[^a-z0-9]")


def _key(name: str) -> str:
    return _NON_ALNUM.sub("", name.lower())


_LOOKUP: dict[str, str] = {}
for _canonical, _names in _ALIASES.items():
    for _name in (_canonical, *_names):
        _LOOKUP.setdefault(_key(_name), _canonical)


def aliases_of(canonical: str) -> tuple[str, ...]:
    """The accepted alias spellings of a canonical action (without the canonical name)."""
    return _ALIASES.get(canonical, ())


def canonical_action(name: str) -> str | None:
    """The canonical action for a name or alias, case- and underscore-insensitive; else None."""
    return _LOOKUP.get(_key(name))


def canonical_skill(name: str) -> str:
    """The skill family an action or skill name belongs to (`SwitchOn` -> `toggle`).

    Args:
        name: a skill from a robot profile or a vocabulary literal.

    Returns:
        The family name, or the name normalised (lower case, letters and digits) if unknown.
    """
    action = canonical_action(name)
    key = _key(name)
    return _SKILL_FAMILY[action] if action else _SKILL_SYNONYMS.get(key, key)


# Robot abilities that are no action of their own: moving between floors.
_SKILL_SYNONYMS = {"stairs": "climbstairs", "stairclimbing": "climbstairs",
                   "stairclimb": "climbstairs", "climbstairs": "climbstairs",
                   "climbingstairs": "climbstairs", "legs": "climbstairs"}
