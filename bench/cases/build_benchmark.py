"""Write `benchmark.jsonl` from the hand-written case descriptions in `data/`.

In: the `CASES` lists of the nine `data/<domain>_<complexity>.py` modules. Out: one JSONL line
per case (id, domain, complexity, label, category, reasoning, why, request, plus the extra keys
`steps` and `missing`), and with `--counts` a Markdown summary for the README.
Fails: `CaseError` naming the case when a description is inconsistent: a step count outside its
complexity band, a dangling id or room, a repeated command, a safe case with a person of unknown
age or whereabouts, or an ambiguous case whose declared missing fact is in fact present.

Run: `.venv/bin/python -m bench.cases.build_benchmark [--counts]`.
"""

from __future__ import annotations

import importlib
import json
import re
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from app.domain.models import GateRequest
from bench.cases.kit import Case, Json

HERE = Path(__file__).parent
OUTPUT = HERE / "benchmark.jsonl"
PREFIX = {"manipulation": "manip", "navigation": "nav", "assistance": "assist"}
CELLS = [(d, c) for d in PREFIX for c in ("simple", "medium", "complex")]
CATEGORY_COLUMNS = ("physical", "psychological", "operational", "consequential", "null")
BANDS = {"simple": range(1, 5), "medium": range(5, 11), "complex": range(11, 200)}


class CaseError(ValueError):
    """A case description that would make a wrong or inconsistent benchmark line."""


def _cell_cases(domain: str, complexity: str) -> list[Case]:
    module = importlib.import_module(f"bench.cases.data.{domain}_{complexity}")
    cases: list[Case] = module.CASES
    for case in cases:
        if (case.domain, case.complexity) != (domain, complexity):
            raise CaseError(f"{case.command!r} sits in the {domain}/{complexity} file")
    return cases


def _check_references(case: Case, where: str) -> None:
    scene = case.scene
    rooms = set(scene["layout"]["rooms"])
    ids = {x["id"] for x in scene["objects"]} | {x["id"] for x in scene["people"]}
    for entity in scene["objects"] + scene["people"] + [case.robot]:
        if entity.get("room") is not None and entity["room"] not in rooms:
            raise CaseError(f"{where}: unknown room {entity['room']!r}")
    for x in scene["objects"]:
        for key in ("on", "in"):
            if key in x and x[key] not in ids:
                raise CaseError(f"{where}: {x['id']} {key} unknown {x[key]!r}")
    for r in scene["relations"]:
        if r["subject"] not in ids or r["object"] not in ids:
            raise CaseError(f"{where}: relation on unknown id {r}")
    person_id = case.user.get("person_id")
    if person_id is not None and person_id not in {x["id"] for x in scene["people"]}:
        raise CaseError(f"{where}: user {person_id!r} is not in the scene")
    if len(ids) != len(scene["objects"]) + len(scene["people"]):
        raise CaseError(f"{where}: repeated scene id")


def _missing_holds(case: Case, fact: Json) -> bool:
    objects = {x["id"]: x for x in case.scene["objects"]}
    people = {x["id"]: x for x in case.scene["people"]}
    kind = fact["kind"]
    if kind == "object_prop":
        return fact["attr"] not in objects[fact["id"]].get("properties", {})
    if kind == "person_attr":
        absent = fact["attr"] not in people[fact["id"]].get("properties", {})
        is_user = case.user.get("person_id") == fact["id"]
        return absent and not (is_user and case.user.get(fact["attr"]) is not None)
    if kind == "person_room":
        return people[fact["id"]].get("room") is None
    if kind == "user_attr":
        return case.user.get(fact["attr"]) is None
    if kind == "referent":
        kinds = {objects[i]["type"] for i in fact["ids"]}
        return len(fact["ids"]) >= 2 and len(kinds) == 1
    raise CaseError(f"unknown missing-fact kind {kind!r}")


def _check(case: Case, where: str) -> None:
    if case.steps not in BANDS[case.complexity]:
        raise CaseError(f"{where}: {case.steps} steps is not {case.complexity}")
    _check_references(case, where)
    if case.label != "safe" and (case.category is None or case.reasoning is None):
        raise CaseError(f"{where}: a {case.label} case needs a category and a reasoning kind")
    if case.label == "safe":
        for person in case.scene["people"]:
            if "age_group" not in person.get("properties", {}) or "room" not in person:
                raise CaseError(f"{where}: safe case with unknown age or room of {person['id']}")
    if case.label == "ambiguous" and not case.missing:
        raise CaseError(f"{where}: an ambiguous case must declare its missing fact")
    for fact in case.missing:
        if not _missing_holds(case, fact):
            raise CaseError(f"{where}: declared missing fact {fact} is present")


def _line(case: Case, ident: str) -> Json:
    request: Json = {"command": case.command, "scene": case.scene, "user": case.user,
                     "robot": case.robot}
    GateRequest.model_validate(request)
    return {"id": ident, "domain": case.domain, "complexity": case.complexity,
            "label": case.label, "category": case.category, "reasoning": case.reasoning,
            "why": case.why, "request": request, "steps": case.steps,
            "missing": case.missing}


def build() -> list[Json]:
    """Check every case description and return the benchmark lines in grid order.

    Returns:
        The JSONL records.

    Raises:
        CaseError: on the first inconsistent description.
    """
    lines: list[Json] = []
    seen_commands: set[str] = set()
    for domain, complexity in CELLS:
        for number, case in enumerate(_cell_cases(domain, complexity), start=1):
            ident = f"{PREFIX[domain]}-{complexity[0]}{number:02d}"
            _check(case, ident)
            normalized = re.sub(r"[^a-z0-9]+", " ", case.command.lower()).strip()
            if normalized in seen_commands:
                raise CaseError(f"{ident}: command repeats another case's")
            seen_commands.add(normalized)
            lines.append(_line(case, ident))
    return lines


def counts_markdown(lines: list[Json]) -> str:
    """Markdown tables of case counts for the README."""
    out: list[str] = []
    labels = ("safe", "unsafe", "ambiguous")
    out.append("| domain | complexity | safe | unsafe | ambiguous | total |")
    out.append("|---|---|---|---|---|---|")
    cells = Counter((x["domain"], x["complexity"], x["label"]) for x in lines)
    for domain, complexity in CELLS:
        row = [cells[(domain, complexity, label)] for label in labels]
        out.append(f"| {domain} | {complexity} | " + " | ".join(map(str, row)) + f" | {sum(row)} |")
    totals = Counter(x["label"] for x in lines)
    out.append("| **all** | | " + " | ".join(str(totals[lb]) for lb in labels)
               + f" | {len(lines)} |")
    for key in ("category", "reasoning"):
        out.append("")
        out.append(f"| {key} | safe | unsafe | ambiguous | total |")
        out.append("|---|---|---|---|---|")
        by: Counter[tuple[Any, str]] = Counter((x[key], x["label"]) for x in lines)
        for value in sorted({x[key] for x in lines}, key=lambda v: str(v)):
            row = [by[(value, label)] for label in labels]
            name = "null" if value is None else value
            out.append(f"| {name} | " + " | ".join(map(str, row)) + f" | {sum(row)} |")
    out += ["", "| label | category | reasoning | cases |", "|---|---|---|---|"]
    combos = Counter((x["label"], x["category"], x["reasoning"]) for x in lines)
    for (label, category, reasoning), n in sorted(combos.items(), key=lambda kv: str(kv[0])):
        out.append(f"| {label} | {category or 'null'} | {reasoning or 'null'} | {n} |")
    out += ["", "| domain | " + " | ".join(CATEGORY_COLUMNS) + " |",
            "|---|" + "---|" * len(CATEGORY_COLUMNS)]
    by_domain = Counter((x["domain"], x["category"] or "null") for x in lines)
    for domain in PREFIX:
        out.append(f"| {domain} | "
                   + " | ".join(str(by_domain[(domain, c)]) for c in CATEGORY_COLUMNS) + " |")
    return "\n".join(out)


def main(argv: list[str]) -> None:
    """Build and write the benchmark; print counts with `--counts`."""
    lines = build()
    with OUTPUT.open("w", encoding="utf-8") as out:
        for record in lines:
            out.write(json.dumps(record, ensure_ascii=False, separators=(",", ":")) + "\n")
    print(f"wrote {len(lines)} cases to {OUTPUT}")
    if "--counts" in argv:
        print(counts_markdown(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
