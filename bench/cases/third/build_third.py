"""Build the third evaluation set: load the case modules, validate them, write third.jsonl.

Run from the repository root: `.venv/bin/python -m bench.cases.third.build_third`.
Validation checks the format, each request against GateRequest, and scene consistency; it never
runs the gate or any analyzer.
"""

from __future__ import annotations

import json
import re
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from . import (
    assist_ambiguous,
    assist_safe,
    assist_unsafe,
    manip_ambiguous,
    manip_safe,
    manip_unsafe,
    manip_unsafe_b,
    nav_ambiguous,
    nav_safe,
    nav_unsafe,
)
from .kit import SETTINGS

OUT = Path(__file__).resolve().parent / "third.jsonl"

_MODULES = (manip_safe, manip_unsafe, manip_unsafe_b, manip_ambiguous,
            nav_safe, nav_unsafe, nav_ambiguous,
            assist_safe, assist_unsafe, assist_ambiguous)

DOMAINS = ("manipulation", "navigation", "assistance")
COMPLEXITIES = ("simple", "medium", "complex")
LABELS = ("safe", "unsafe", "ambiguous")
CATEGORIES = ("physical", "psychological", "operational", "consequential")
REASONINGS = ("compositional", "incomplete_information", "consequential_state", "direct")
STYLES = ("planner", "spoken", "indirect")
AGE_GROUPS = ("infant", "child", "teen", "adult", "older_adult")
MOBILITY = ("independent", "assisted", "wheelchair", "bedridden")
COGNITIVE = ("typical", "impaired", "asleep", "intoxicated")
TEMPERATURES = ("hot", "cold", "room")
REQUIRED = ("id", "domain", "complexity", "label", "category", "reasoning", "why", "request")
_ABBREV = re.compile(r"\b(Mr|Mrs|Ms|Dr|St|a\.m|p\.m|vs|e\.g|i\.e)\.")


def load() -> list[dict[str, Any]]:
    """All cases, as dicts (including the private `_refs` key)."""
    return [c for m in _MODULES for c in m.CASES]


def _one_sentence(text: str) -> bool:
    body = _ABBREV.sub(lambda m: m.group(1), text.strip())
    return body.endswith(".") and not re.search(r"[.!?]\s+[A-Z0-9]", body[:-1])


def _check_labels(c: dict[str, Any]) -> list[str]:
    out: list[str] = []
    label, cat, rsn = c["label"], c["category"], c["reasoning"]
    if c["domain"] not in DOMAINS:
        out.append(f"domain {c['domain']!r}")
    if c["complexity"] not in COMPLEXITIES:
        out.append(f"complexity {c['complexity']!r}")
    if label not in LABELS:
        out.append(f"label {label!r}")
    if cat is not None and cat not in CATEGORIES:
        out.append(f"category {cat!r}")
    if rsn is not None and rsn not in REASONINGS:
        out.append(f"reasoning {rsn!r}")
    if label == "safe" and (cat is not None or rsn is not None):
        out.append("safe case must have null category and reasoning")
    if label == "unsafe" and (cat is None or rsn not in
                              ("direct", "compositional", "consequential_state")):
        out.append("unsafe case needs a category and a direct/compositional/left-state reasoning")
    if label == "ambiguous" and (cat is None or rsn != "incomplete_information"):
        out.append("ambiguous case needs a category and incomplete_information")
    if not isinstance(c["why"], str) or not _one_sentence(c["why"]):
        out.append("why must be one sentence ending with a period")
    if c.get("style") not in STYLES:
        out.append(f"style {c.get('style')!r}")
    if c.get("setting") not in SETTINGS:
        out.append(f"setting {c.get('setting')!r}")
    return out


def _check_person_fields(where: str, d: dict[str, Any]) -> list[str]:
    out: list[str] = []
    for key, allowed in (("age_group", AGE_GROUPS), ("mobility", MOBILITY),
                         ("cognitive_state", COGNITIVE)):
        if key in d and d[key] not in allowed:
            out.append(f"{where}: {key} {d[key]!r}")
    return out


def _check_scene(req: dict[str, Any], refs: list[str]) -> list[str]:
    out: list[str] = []
    scene = req.get("scene") or {}
    layout = scene.get("layout") or {}
    rooms = layout.get("rooms") or []
    room_set = set(rooms)
    if len(room_set) != len(rooms):
        out.append("duplicate room names")
    adj: dict[str, set[str]] = {r: set() for r in rooms}
    for a, b in layout.get("connections") or []:
        if a not in room_set or b not in room_set:
            out.append(f"connection {a}-{b} names an unknown room")
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
            out.append(f"rooms not connected: {sorted(room_set - seen)}")
    objects = scene.get("objects") or []
    people = scene.get("people") or []
    obstacles = layout.get("obstacles") or []
    ids = [e["id"] for e in (*objects, *people, *obstacles)]
    dupes = [i for i, n in Counter(ids).items() if n > 1]
    if dupes:
        out.append(f"duplicate scene ids {dupes}")
    id_set = set(ids)
    obj_room = {o["id"]: o.get("room") for o in objects}
    for e in (*objects, *obstacles):
        if e.get("room") not in room_set:
            out.append(f"{e['id']} in unknown room {e.get('room')!r}")
    for o in objects:
        for key in ("on", "in"):
            tgt = o.get(key)
            if tgt is None:
                continue
            if tgt not in obj_room:
                out.append(f"{o['id']}.{key} -> unknown object {tgt!r}")
            elif obj_room[tgt] != o.get("room"):
                out.append(f"{o['id']}.{key} -> {tgt} is in another room")
        temp = (o.get("properties") or {}).get("temperature")
        if temp is not None and temp not in TEMPERATURES:
            out.append(f"{o['id']}: temperature {temp!r}")
    for p in people:
        if p.get("room") is not None and p["room"] not in room_set:
            out.append(f"{p['id']} in unknown room {p['room']!r}")
        out.extend(_check_person_fields(p["id"], p.get("properties") or {}))
    for r in scene.get("relations") or []:
        for end in (r["subject"], r["object"]):
            if end not in id_set:
                out.append(f"relation {r['subject']} {r['relation']} {r['object']}: "
                           f"unknown {end!r}")
    robot = req.get("robot") or {}
    if robot.get("room") not in room_set:
        out.append(f"robot in unknown room {robot.get('room')!r}")
    payload = robot.get("payload_kg")
    if payload is not None and not 0.5 <= payload <= 25:
        out.append(f"robot payload {payload} outside 0.5..25 kg")
    user = req.get("user")
    if user is not None:
        pid = user.get("person_id")
        if pid is not None and pid not in {p["id"] for p in people}:
            out.append(f"user.person_id {pid!r} not among people")
        out.extend(_check_person_fields("user", user))
    missing = [r for r in refs if r not in id_set]
    if missing:
        out.append(f"command referents missing from scene: {missing}")
    return out


def validate(cases: list[dict[str, Any]]) -> list[str]:
    """Problems found, as 'id: message' strings; empty when the set is consistent."""
    from app.domain.models.request import GateRequest  # only to validate the request shape

    problems: list[str] = []
    counts = Counter(c.get("id") for c in cases)
    problems += [f"{i}: duplicate id" for i, n in counts.items() if n > 1]
    for c in cases:
        cid = c.get("id", "?")
        miss = [k for k in REQUIRED if k not in c]
        if miss:
            problems.append(f"{cid}: missing keys {miss}")
            continue
        if not str(cid).startswith("thd-"):
            problems.append(f"{cid}: id must start with thd-")
        msgs = _check_labels(c)
        try:
            GateRequest.model_validate(c["request"])
        except Exception as exc:  # pydantic.ValidationError, reported not raised
            msgs.append(f"GateRequest: {exc}")
        msgs += _check_scene(c["request"], c.get("_refs", []))
        problems += [f"{cid}: {m}" for m in msgs]
    cells = Counter((c.get("domain"), c.get("complexity")) for c in cases)
    problems += [f"mix: no {d} x {x} case" for d in DOMAINS for x in COMPLEXITIES
                 if not cells[(d, x)]]
    return problems


def _public(case: dict[str, Any]) -> dict[str, Any]:
    return {k: v for k, v in case.items() if not k.startswith("_")}


def _mix(cases: list[dict[str, Any]]) -> str:
    lines = [f"cases: {len(cases)}"]
    for key in ("label", "domain", "complexity", "category", "reasoning", "style", "setting"):
        cnt = Counter(str(c.get(key)) for c in cases)
        lines.append(f"{key}: " + ", ".join(f"{k}={v}" for k, v in sorted(cnt.items())))
    lines.append("domain x complexity:")
    for d in DOMAINS:
        row = Counter(c["complexity"] for c in cases if c["domain"] == d)
        lines.append(f"  {d:<13}" + "  ".join(f"{x}={row[x]}" for x in COMPLEXITIES))
    lines.append("domain x label:")
    for d in DOMAINS:
        row = Counter(c["label"] for c in cases if c["domain"] == d)
        lines.append(f"  {d:<13}" + "  ".join(f"{x}={row[x]}" for x in LABELS))
    unsafe = [c for c in cases if c["label"] == "unsafe"]
    pairs = Counter(f"{c['category']}/{c['reasoning']}" for c in unsafe)
    lines.append("unsafe category/reasoning: "
                 + ", ".join(f"{k}={v}" for k, v in sorted(pairs.items())))
    return "\n".join(lines)


def main() -> int:
    cases = load()
    problems = validate(cases)
    if problems:
        print(f"{len(problems)} problem(s):", file=sys.stderr)
        for p in problems:
            print(f"  {p}", file=sys.stderr)
        return 1
    with OUT.open("w", encoding="utf-8") as fh:
        for c in cases:
            fh.write(json.dumps(_public(c), ensure_ascii=False) + "\n")
    print(f"wrote {OUT}")
    print(_mix(cases))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
