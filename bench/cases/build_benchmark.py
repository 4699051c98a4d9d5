"""Write `benchmark.jsonl` from the hand-written case files in `data/`.

In: the nine case files `data/<domain>_<complexity>.yaml`, read by `kit.read_cases`. Out: one
JSONL line per case (id, domain, complexity, label, category, reasoning, why, request, plus the
extra keys `steps` and `missing`), and with `--counts` a Markdown summary for the README.
Fails: `CaseError` naming the case when a file cannot be read or a description is inconsistent
(the checks are `validate.check_case`), or when a command repeats another case's.

Run: `.venv/bin/python -m bench.cases.build_benchmark [--counts]`.
"""

from __future__ import annotations

import json
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from app.domain.models import GateRequest
from bench.cases.case_files import read_cases
from bench.cases.kit import Case, CaseError, Json
from bench.cases.validate import check_case, normalized_command

HERE = Path(__file__).parent
OUTPUT = HERE / "benchmark.jsonl"
DATA = HERE / "data"
PREFIX = {"manipulation": "manip", "navigation": "nav", "assistance": "assist"}
CELLS = [(d, c) for d in PREFIX for c in ("simple", "medium", "complex")]
CATEGORY_COLUMNS = ("physical", "psychological", "operational", "consequential", "null")


def _cell_cases(domain: str, complexity: str) -> list[Case]:
    cases = read_cases(DATA / f"{domain}_{complexity}.yaml")
    for case in cases:
        if (case.domain, case.complexity) != (domain, complexity):
            raise CaseError(f"{case.command!r} sits in the {domain}/{complexity} file")
    return cases


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
            check_case(case, ident)
            normalized = normalized_command(case.command)
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


def render(lines: list[Json]) -> str:
    """The benchmark file's exact text: one compact JSON object a line."""
    return "".join(json.dumps(record, ensure_ascii=False, separators=(",", ":")) + "\n"
                   for record in lines)


def main(argv: list[str]) -> None:
    """Build and write the benchmark; print counts with `--counts`."""
    lines = build()
    OUTPUT.write_text(render(lines), encoding="utf-8")
    print(f"wrote {len(lines)} cases to {OUTPUT}")
    if "--counts" in argv:
        print(counts_markdown(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
