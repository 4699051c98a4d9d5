"""Validate the second evaluation set and write ``second.jsonl``.

Run from /work/main:  .venv/bin/python -m bench.cases.second.build_second

Checks every case for allowed enum values, label/category/reasoning consistency, unique ids,
scene consistency (rooms, connections, ids, supports, relations, people, user, robot, the ids
the command refers to) and validates each request with ``GateRequest.model_validate``. It never
calls the gate or any analyzer.
"""

from __future__ import annotations

import json
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from app.domain.models.request import GateRequest

from . import (
    assistance_1,
    assistance_2,
    assistance_3,
    manipulation_1,
    manipulation_2,
    manipulation_3,
    navigation_1,
    navigation_2,
    navigation_3,
)

OUT = Path(__file__).with_name("second.jsonl")
MODULES = [manipulation_1, manipulation_2, manipulation_3, navigation_1, navigation_2,
           navigation_3, assistance_1, assistance_2, assistance_3]

DOMAINS = {"manipulation", "navigation", "assistance"}
COMPLEXITIES = {"simple", "medium", "complex"}
LABELS = {"safe", "unsafe", "ambiguous"}
CATEGORIES = {"physical", "psychological", "operational", "consequential"}
UNSAFE_REASONING = {"compositional", "consequential_state", "direct"}
AGE = {"infant", "child", "teen", "adult", "older_adult"}
MOBILITY = {"independent", "assisted", "wheelchair", "bedridden"}
COGNITION = {"typical", "impaired", "asleep", "intoxicated"}
TEMPERATURE = {"hot", "cold", "room"}


def _check_enums(cid: str, where: str, props: dict[str, Any], errs: list[str]) -> None:
    for key, allowed in (("age_group", AGE), ("mobility", MOBILITY),
                         ("cognitive_state", COGNITION), ("temperature", TEMPERATURE)):
        if key in props and props[key] not in allowed:
            errs.append(f"{cid}: {where} {key}={props[key]!r} not allowed")
    if "allergies" in props and not isinstance(props["allergies"], list):
        errs.append(f"{cid}: {where} allergies must be a list")


def _check_labels(c: dict[str, Any], errs: list[str]) -> None:
    cid = c["id"]
    if not cid.startswith("sec-"):
        errs.append(f"{cid}: id must start with sec-")
    for key, allowed in (("domain", DOMAINS), ("complexity", COMPLEXITIES), ("label", LABELS)):
        if c[key] not in allowed:
            errs.append(f"{cid}: bad {key} {c[key]!r}")
    label, cat, rsn = c["label"], c["category"], c["reasoning"]
    if label == "safe" and (cat is not None or rsn is not None):
        errs.append(f"{cid}: safe cases carry null category and reasoning")
    if label == "unsafe" and (cat not in CATEGORIES or rsn not in UNSAFE_REASONING):
        errs.append(f"{cid}: unsafe needs a category and direct/compositional/cs reasoning")
    if label == "ambiguous" and (cat not in CATEGORIES or rsn != "incomplete_information"):
        errs.append(f"{cid}: ambiguous needs a category and incomplete_information")
    why = c["why"].strip()
    if not why.endswith(".") or why.count(". ") > 0 or len(why) < 20:
        errs.append(f"{cid}: why must be one sentence")


def _check_scene(c: dict[str, Any], errs: list[str]) -> None:
    cid = c["id"]
    req = c["request"]
    scene = req.get("scene") or {}
    layout = scene.get("layout") or {}
    rooms = layout.get("rooms", [])
    if len(set(rooms)) != len(rooms):
        errs.append(f"{cid}: duplicate room")
    room_set = set(rooms)
    adj: dict[str, set[str]] = {r: set() for r in rooms}
    for a, b in layout.get("connections", []):
        if a not in room_set or b not in room_set:
            errs.append(f"{cid}: connection {a}-{b} to unknown room")
            continue
        adj[a].add(b)
        adj[b].add(a)
    if rooms:
        seen, todo = {rooms[0]}, [rooms[0]]
        while todo:
            for nxt in adj[todo.pop()] - seen:
                seen.add(nxt)
                todo.append(nxt)
        if seen != room_set:
            errs.append(f"{cid}: rooms not connected: {sorted(room_set - seen)}")
    ids: list[str] = []
    objects = {obj["id"]: obj for obj in scene.get("objects", [])}
    people = {per["id"]: per for per in scene.get("people", [])}
    obstacles = layout.get("obstacles", [])
    ids += [obj["id"] for obj in scene.get("objects", [])]
    ids += [per["id"] for per in scene.get("people", [])]
    ids += [obs["id"] for obs in obstacles]
    dupes = [i for i, n in Counter(ids).items() if n > 1]
    if dupes:
        errs.append(f"{cid}: duplicate ids {dupes}")
    for thing in list(objects.values()) + list(people.values()) + obstacles:
        if thing in people.values() and "room" not in thing:
            continue  # a person whose whereabouts are unknown
        if thing.get("room") not in room_set:
            errs.append(f"{cid}: {thing['id']} in unknown room {thing.get('room')!r}")
    for obj in objects.values():
        _check_enums(cid, obj["id"], obj.get("properties", {}), errs)
        for key in ("on", "inside"):
            target = obj.get(key)
            if target is None:
                continue
            if target not in objects:
                errs.append(f"{cid}: {obj['id']} {key} unknown {target!r}")
            elif objects[target]["room"] != obj["room"]:
                errs.append(f"{cid}: {obj['id']} {key} {target} in another room")
    for per in people.values():
        _check_enums(cid, per["id"], per.get("properties", {}), errs)
    known = set(ids)
    for r in scene.get("relations", []):
        if r["subject"] not in known or r["object"] not in known:
            errs.append(f"{cid}: relation {r} names an unknown id")
    user = req.get("user") or {}
    _check_enums(cid, "user", user, errs)
    if "person_id" in user and user["person_id"] not in people:
        errs.append(f"{cid}: user.person_id {user['person_id']!r} not in people")
    robot = req.get("robot") or {}
    if "room" in robot and robot["room"] not in room_set:
        errs.append(f"{cid}: robot in unknown room {robot['room']!r}")
    for ref in c.get("_refs", []):
        if ref not in known:
            errs.append(f"{cid}: command referent {ref!r} missing from the scene")


def load() -> list[dict[str, Any]]:
    cases: list[dict[str, Any]] = []
    for mod in MODULES:
        cases.extend(mod.CASES)
    return cases


def validate(cases: list[dict[str, Any]]) -> list[str]:
    errs: list[str] = []
    dupes = [i for i, n in Counter(c["id"] for c in cases).items() if n > 1]
    if dupes:
        errs.append(f"duplicate case ids {dupes}")
    for c in cases:
        _check_labels(c, errs)
        _check_scene(c, errs)
        try:
            GateRequest.model_validate(c["request"])
        except ValidationError as exc:
            errs.append(f"{c['id']}: GateRequest rejected it: {exc}")
    return errs


def _show(title: str, counter: Counter[Any]) -> None:
    parts = ", ".join(f"{k}={v}" for k, v in sorted(counter.items(), key=lambda kv: str(kv[0])))
    print(f"  {title}: {parts}")


def main() -> int:
    cases = load()
    errs = validate(cases)
    if errs:
        print(f"{len(errs)} problem(s):")
        for e in errs:
            print("  " + e)
        return 1
    with OUT.open("w", encoding="utf-8") as fh:
        for c in cases:
            row = {k: v for k, v in c.items() if not k.startswith("_")}
            fh.write(json.dumps(row, ensure_ascii=False) + "\n")
    print(f"wrote {len(cases)} cases to {OUT}")
    _show("label", Counter(c["label"] for c in cases))
    _show("domain", Counter(c["domain"] for c in cases))
    _show("complexity", Counter(c["complexity"] for c in cases))
    _show("category (unsafe+ambiguous)", Counter(c["category"] for c in cases
                                                 if c["label"] != "safe"))
    _show("category (unsafe)", Counter(c["category"] for c in cases if c["label"] == "unsafe"))
    _show("reasoning", Counter(c["reasoning"] for c in cases))
    _show("domain x complexity", Counter(f"{c['domain']}/{c['complexity']}" for c in cases))
    _show("domain x label", Counter(f"{c['domain']}/{c['label']}" for c in cases))
    return 0


if __name__ == "__main__":
    sys.exit(main())
