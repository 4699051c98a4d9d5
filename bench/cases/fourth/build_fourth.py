"""Build the fourth evaluation set: load the case modules, check them, write fourth.jsonl.

Run from the repository root: `.venv/bin/python -m bench.cases.fourth.build_fourth`.
The checks cover the benchmark format, every request against GateRequest, and the consistency of
each scene. Nothing here runs the gate or an analyzer.
"""

from __future__ import annotations

import json
import re
import sys
from collections import Counter
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from . import (
    assist_ambiguous,
    assist_safe,
    assist_unsafe,
    assist_unsafe_b,
    manip_ambiguous,
    manip_safe,
    manip_unsafe,
    manip_unsafe_b,
    nav_ambiguous,
    nav_safe,
    nav_unsafe,
    nav_unsafe_b,
)
from .kit import SETTINGS

OUT = Path(__file__).resolve().parent / "fourth.jsonl"

MODULES = (manip_safe, manip_unsafe, manip_unsafe_b, manip_ambiguous,
           nav_safe, nav_unsafe, nav_unsafe_b, nav_ambiguous,
           assist_safe, assist_unsafe, assist_unsafe_b, assist_ambiguous)

PREFIX = {"manipulation": "fth-m", "navigation": "fth-n", "assistance": "fth-a"}
DOMAINS = tuple(PREFIX)
COMPLEXITIES = ("simple", "medium", "complex")
LABELS = ("safe", "unsafe", "ambiguous")
CATEGORIES = ("physical", "psychological", "operational", "consequential")
UNSAFE_REASONING = ("direct", "compositional", "consequential_state")
STYLES = ("planner", "spoken", "indirect", "euphemism")
AGE_GROUPS = ("infant", "child", "teen", "adult", "older_adult")
MOBILITY = ("independent", "assisted", "wheelchair", "bedridden")
COGNITION = ("typical", "impaired", "asleep", "intoxicated")
TEMPERATURES = ("hot", "cold", "room")
REQUIRED = ("id", "domain", "complexity", "label", "category", "reasoning", "why", "request")
_ABBREVIATIONS = re.compile(r"\b(Mr|Mrs|Ms|Dr|St|No|vs|e\.g|i\.e|approx)\.")
_STEP = re.compile(r"(?:^|\s)(\d{1,2})[).]\s")


def load() -> list[dict[str, Any]]:
    """Every case in module order, including the private `_refs` key."""
    return [c for module in MODULES for c in module.CASES]


def one_sentence(text: str) -> bool:
    body = _ABBREVIATIONS.sub(lambda m: m.group(1), text.strip())
    return body.endswith(".") and not re.search(r"[.!?]\s+[A-Z0-9]", body[:-1])


def numbered_steps(command: str) -> int:
    """The highest step number written as `n)` or `n.` in a command."""
    return max((int(n) for n in _STEP.findall(command)), default=0)


def _label_problems(c: dict[str, Any]) -> list[str]:
    out: list[str] = []
    label, cat, rsn = c["label"], c["category"], c["reasoning"]
    for key, allowed in (("domain", DOMAINS), ("complexity", COMPLEXITIES), ("label", LABELS)):
        if c[key] not in allowed:
            out.append(f"{key} {c[key]!r}")
    if cat is not None and cat not in CATEGORIES:
        out.append(f"category {cat!r}")
    if label == "safe" and (cat is not None or rsn is not None):
        out.append("a safe case has null category and reasoning")
    if label == "safe" and c.get("hazard") is not None:
        out.append("a safe case has a null hazard tag")
    if label == "unsafe" and (cat is None or rsn not in UNSAFE_REASONING):
        out.append("an unsafe case needs a category and direct/compositional/consequential_state")
    if label == "ambiguous" and (cat is None or rsn != "incomplete_information"):
        out.append("an ambiguous case needs a category and incomplete_information")
    if label != "safe" and not c.get("hazard"):
        out.append("an unsafe or ambiguous case needs a hazard tag")
    if not isinstance(c["why"], str) or not one_sentence(c["why"]):
        out.append("why must be one sentence ending with a period")
    if c.get("style") not in STYLES:
        out.append(f"style {c.get('style')!r}")
    if c.get("setting") not in SETTINGS:
        out.append(f"setting {c.get('setting')!r}")
    prefix = PREFIX.get(c["domain"], "?")
    if not re.fullmatch(re.escape(prefix) + r"\d{2}", str(c["id"])):
        out.append(f"id must look like {prefix}NN")
    steps = numbered_steps(c["request"].get("command", ""))
    if c["complexity"] == "complex" and steps < 11:
        out.append(f"complex command lists {steps} numbered steps, needs 11 or more")
    if c["complexity"] != "complex" and steps >= 11:
        out.append("a command with 11 or more numbered steps must be complex")
    return out


def _person_problems(where: str, d: dict[str, Any]) -> list[str]:
    return [f"{where}: {key} {d[key]!r}"
            for key, allowed in (("age_group", AGE_GROUPS), ("mobility", MOBILITY),
                                 ("cognitive_state", COGNITION))
            if key in d and d[key] not in allowed]


def _connected(rooms: list[str], links: Iterable[list[str]]) -> set[str]:
    near: dict[str, set[str]] = {r: set() for r in rooms}
    for a, b in links:
        if a in near and b in near:
            near[a].add(b)
            near[b].add(a)
    if not rooms:
        return set()
    seen, todo = {rooms[0]}, [rooms[0]]
    while todo:
        for nxt in near[todo.pop()] - seen:
            seen.add(nxt)
            todo.append(nxt)
    return seen


def _scene_problems(req: dict[str, Any], refs: list[str]) -> list[str]:
    out: list[str] = []
    scene = req.get("scene") or {}
    layout = scene.get("layout") or {}
    rooms = list(layout.get("rooms") or [])
    room_set = set(rooms)
    links = layout.get("connections") or []
    out += [f"connection {a}-{b} names an unknown room" for a, b in links
            if a not in room_set or b not in room_set]
    if _connected(rooms, links) != room_set:
        out.append("the layout's rooms are not all connected")
    objects = scene.get("objects") or []
    people = scene.get("people") or []
    obstacles = layout.get("obstacles") or []
    ids = [e["id"] for e in (*objects, *people, *obstacles)]
    out += [f"duplicate scene id {i!r}" for i, n in Counter(ids).items() if n > 1]
    where = {o["id"]: o.get("room") for o in objects}
    for e in (*objects, *obstacles):
        if e.get("room") not in room_set:
            out.append(f"{e['id']} is in unknown room {e.get('room')!r}")
    for o in objects:
        for key in ("on", "in"):
            target = o.get(key)
            if target is None:
                continue
            if target not in where:
                out.append(f"{o['id']}.{key} names unknown object {target!r}")
            elif where[target] != o.get("room"):
                out.append(f"{o['id']}.{key} -> {target} is in another room")
        temp = (o.get("properties") or {}).get("temperature")
        if temp is not None and temp not in TEMPERATURES:
            out.append(f"{o['id']}: temperature {temp!r}")
    for p in people:
        if p.get("room") is not None and p["room"] not in room_set:
            out.append(f"{p['id']} is in unknown room {p['room']!r}")
        out += _person_problems(p["id"], p.get("properties") or {})
    id_set = set(ids)
    for r in scene.get("relations") or []:
        out += [f"relation {r['subject']} {r['relation']} {r['object']}: unknown {end!r}"
                for end in (r["subject"], r["object"]) if end not in id_set]
    bot = req.get("robot") or {}
    if bot.get("room") not in room_set:
        out.append(f"robot in unknown room {bot.get('room')!r}")
    payload = bot.get("payload_kg")
    if payload is not None and not 0.5 <= payload <= 25:
        out.append(f"robot payload {payload} kg is outside 0.5..25")
    user = req.get("user")
    if user is not None:
        pid = user.get("person_id")
        if pid is not None and pid not in {p["id"] for p in people}:
            out.append(f"user.person_id {pid!r} is not among the people")
        out += _person_problems("user", user)
    missing = [r for r in refs if r not in id_set]
    if missing:
        out.append(f"ids named by the command are missing from the scene: {missing}")
    return out


def validate(cases: list[dict[str, Any]]) -> list[str]:
    """Problems as 'id: message' strings; an empty list means the set is consistent."""
    from app.domain.models import GateRequest  # only to check the request shape

    problems = [f"{i}: duplicate id" for i, n in Counter(c.get("id") for c in cases).items()
                if n > 1]
    for c in cases:
        cid = c.get("id", "?")
        absent = [k for k in REQUIRED if k not in c]
        if absent:
            problems.append(f"{cid}: missing keys {absent}")
            continue
        found = _label_problems(c)
        try:
            GateRequest.model_validate(c["request"])
        except Exception as exc:  # a pydantic ValidationError, reported rather than raised
            found.append(f"GateRequest: {exc}")
        found += _scene_problems(c["request"], c.get("_refs", []))
        problems += [f"{cid}: {m}" for m in found]
    cells = Counter((c.get("domain"), c.get("complexity")) for c in cases)
    problems += [f"mix: no {d} x {x} case" for d in DOMAINS for x in COMPLEXITIES
                 if not cells[(d, x)]]
    for d in DOMAINS:
        nums = sorted(int(c["id"][5:]) for c in cases if c.get("domain") == d
                      and str(c.get("id", "")).startswith(PREFIX[d]) and c["id"][5:].isdigit())
        if nums != list(range(1, len(nums) + 1)):
            problems.append(f"mix: {d} ids are not numbered 1..{len(nums)} without gaps")
    return problems


def public(c: dict[str, Any]) -> dict[str, Any]:
    return {k: v for k, v in c.items() if not k.startswith("_")}


def mix(cases: list[dict[str, Any]]) -> str:
    lines = [f"cases: {len(cases)}"]
    for key in ("label", "domain", "complexity", "category", "reasoning", "style", "setting"):
        cnt = Counter(str(c.get(key)) for c in cases)
        lines.append(f"{key}: " + ", ".join(f"{k}={v}" for k, v in sorted(cnt.items())))
    for title, key, values in (("domain x label", "label", LABELS),
                               ("domain x complexity", "complexity", COMPLEXITIES)):
        lines.append(f"{title}:")
        for d in DOMAINS:
            row = Counter(c[key] for c in cases if c["domain"] == d)
            lines.append(f"  {d:<13}" + "  ".join(f"{v}={row[v]}" for v in values))
    for label in ("unsafe", "ambiguous"):
        pairs = Counter(f"{c['category']}/{c['reasoning']}" for c in cases
                        if c["label"] == label)
        lines.append(f"{label} category/reasoning: "
                     + ", ".join(f"{k}={v}" for k, v in sorted(pairs.items())))
    return "\n".join(lines)


def main() -> int:
    cases = load()
    problems = validate(cases)
    if problems:
        print(f"{len(problems)} problem(s), nothing written:", file=sys.stderr)
        for p in problems:
            print(f"  {p}", file=sys.stderr)
        return 1
    with OUT.open("w", encoding="utf-8") as fh:
        for c in cases:
            fh.write(json.dumps(public(c), ensure_ascii=False) + "\n")
    print(f"wrote {OUT}")
    print(mix(cases))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
