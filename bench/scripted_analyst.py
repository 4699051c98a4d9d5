"""A scripted, deterministic "analyst" that answers SafeGate's LLM prompts from their words alone.

It stands in for a model in `make bench`'s `llm (scripted)` and `ensemble (scripted)` methods:
a plumbing check of the LLM path end to end (prompt, litellm, real HTTP on loopback, parsing,
checks, merge, binding, gate), not a model and not a model score. It reads only the chat
request SafeGate sends (never a benchmark file, so never a label) and answers exactly this:
1. The library's classes are read from the system prompt's class list (category, class, the
   entity variables it binds).
2. Words: the command's words (from its data block), plus, from the deployment level on, the
   types of the scene objects whose type or id the command names. A class's score is how many
   of its name's words (split at "_", 3 letters or more) are among them.
3. One hazard: the best-scoring class (ties: the list's order), or `object_damage` when no class
   scores and the library has it, else none. It is `moderate`, `preventable`, `uncertain`,
   with the mechanism "the scripted analyst matched <words> in the request".
4. Entities, from the deployment level on, for the variables the class binds: obj and other =
   the first and second scene objects the command names (else the first objects listed),
   person = the first person of the scene (else the user's id), room = the robot's room (else
   the object's), aid = an object whose type is a walking aid or barrier. No task-level ids.
5. No unknowns and no dismissals. Every category without the hazard gets "none, because the
   scripted analyst matched no word of this category's classes", so all twelve cells are
   answered.
6. Batched prompts (schema with task/deployment/user) get the three levels at once; the entity
   round gets the listed hazards restated with the ids step 4 finds.
Fails: never; a prompt it cannot read gets an empty level answer, which SafeGate's own checks
then treat as not understood.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import Any

from bench.scripted_llm import Scripted

CATEGORIES = ("physical", "psychological", "operational", "consequential")
_DATA = re.compile(r'([A-Za-z ]+) \(JSON data\):\n<data id="([0-9a-f]+)">\n(.*?)\n'
                   r'</data id="\2">', re.S)
_CLASS_LINE = re.compile(r"^- ([a-z][a-z0-9_]+): .*?(?: \[([a-z, ]+)\])?$")
_LEVEL = re.compile(r"^Level: (task|deployment|user)\.", re.M)
_ENTITY_LINE = re.compile(r"^- [a-z]+/([a-z][a-z0-9_]+) \(given:", re.M)
_WORD = re.compile(r"[a-z]+")
_AIDS = ("walker", "cane", "crutch", "wheelchair", "gate", "rail", "barrier")
NONE_REASON = "none, because the scripted analyst matched no word of this category's classes"


@dataclass(frozen=True)
class _Class:
    name: str
    category: str
    binds: tuple[str, ...]


def _library(system: str) -> list[_Class]:
    classes: list[_Class] = []
    category = ""
    for line in system.splitlines():
        if line.rstrip(":") in CATEGORIES and line.endswith(":"):
            category = line[:-1]
        elif category and (found := _CLASS_LINE.match(line)):
            binds = tuple(b.strip() for b in (found.group(2) or "").split(",") if b.strip())
            classes.append(_Class(found.group(1), category, binds))
    return classes


def _words(text: str) -> set[str]:
    spaced = re.sub(r"([a-z])([A-Z])", r"\1 \2", text)  # CounterTop -> Counter Top
    return {w for w in _WORD.findall(spaced.lower()) if len(w) >= 3}


def _data(user: str) -> dict[str, Any]:
    return {label.strip().split()[0].lower(): json.loads(body)
            for label, _, body in _DATA.findall(user)}


def _named_objects(command: str, scene: dict[str, Any]) -> list[dict[str, Any]]:
    words = _words(command)
    objects = [o for o in scene.get("objects", []) if isinstance(o, dict)]
    named = [o for o in objects if _words(f"{o.get('type', '')} {o.get('id', '')}") & words]
    return named + [o for o in objects if o not in named]


def _entities(binds: tuple[str, ...], data: dict[str, Any]) -> dict[str, str]:
    command, scene = str(data.get("command", "")), data.get("scene") or {}
    objects = _named_objects(command, scene)
    people = [p["id"] for p in scene.get("people", []) if isinstance(p, dict) and "id" in p]
    user_id = (data.get("user") or {}).get("person_id")
    aids = [o["id"] for o in objects if any(a in str(o.get("type", "")).lower() for a in _AIDS)]
    rooms = [(data.get("robot") or {}).get("room"), *(o.get("room") for o in objects)]
    found = {
        "obj": objects[0]["id"] if objects else None,
        "other": objects[1]["id"] if len(objects) > 1 else None,
        "person": people[0] if people else user_id,
        "room": next((r for r in rooms if r), None),
        "aid": aids[0] if aids else None,
    }
    return {name: value for name in binds if isinstance(value := found.get(name), str)}


def _best_class(classes: list[_Class], words: set[str]) -> tuple[_Class | None, list[str]]:
    best: tuple[_Class | None, list[str]] = (None, [])
    for candidate in classes:
        matched = sorted(w for w in candidate.name.split("_") if len(w) >= 3 and w in words)
        if len(matched) > len(best[1]):
            best = (candidate, matched)
    if best[0] is None:
        fallback = next((c for c in classes if c.name == "object_damage"), None)
        return fallback, []
    return best


def _level(classes: list[_Class], data: dict[str, Any], *, with_ids: bool) -> dict[str, Any]:
    command = str(data.get("command", ""))
    words = _words(command)
    if with_ids and data.get("scene"):
        named = _named_objects(command, data["scene"])
        words |= {w for o in named[:2] for w in _words(str(o.get("type", "")))}
    chosen, matched = _best_class(classes, words)
    hazards = []
    if chosen is not None:
        hazards.append({
            "category": chosen.category, "hazard_class": chosen.name,
            "mechanism": "the scripted analyst matched "
                         f"{', '.join(matched) or 'no class word, so ordinary damage'} "
                         "in the request",
            "entities": _entities(chosen.binds, data) if with_ids else {},
            "severity": "moderate", "preventability": "preventable", "confidence": "uncertain",
        })
    covered = {h["category"] for h in hazards}
    return {"hazards": hazards, "unknowns": [], "dismissed": [],
            "none_because": {c: NONE_REASON for c in CATEGORIES if c not in covered}}


def _wants_batched(body: dict[str, Any]) -> bool:
    response_format = body.get("response_format") or {}
    schema = (response_format.get("json_schema") or {}).get("schema") \
        or response_format.get("schema") or {}
    return "task" in schema.get("properties", {})


def answer(body: dict[str, Any]) -> Scripted:
    """The scripted analyst's reply to one chat-completions request body.

    Args:
        body: the JSON body SafeGate's litellm client POSTed.

    Returns:
        A reply whose content is the JSON answer described in the module docstring.
    """
    messages = body.get("messages") or []
    system = str(messages[0].get("content", "")) if messages else ""
    user = str(messages[1].get("content", "")) if len(messages) > 1 else ""
    classes, data = _library(system), _data(user)
    if _wants_batched(body):
        reply: dict[str, Any] = {
            "task": _level(classes, data, with_ids=False),
            "deployment": _level(classes, data, with_ids=True),
            "user": _level(classes, data, with_ids=True),
        }
    elif (level := _LEVEL.search(user)) is not None:
        reply = _level(classes, data, with_ids=level.group(1) != "task")
    else:  # the entity round: restate the listed hazards with the ids that can be found
        asked = set(_ENTITY_LINE.findall(user))
        full = _level(classes, data, with_ids=True)
        reply = {"hazards": [h for h in full["hazards"] if h["hazard_class"] in asked],
                 "unknowns": []}
    return Scripted(content=json.dumps(reply))
