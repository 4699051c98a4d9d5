"""Build `fresh.jsonl` from the hand-written case modules beside this file, validating each case.

In: the `CASES` lists of the data modules. Out: `fresh.jsonl` (one case a line, sorted by id)
and a count summary on stdout. Fails with exit status 1, writing nothing, if any case is
inconsistent (see `kit.check_case`), any request does not validate as a `GateRequest`, or an id
repeats. Run: `.venv/bin/python -m bench.cases.fresh.build_fresh` (add `--check` to verify the
file on disk is up to date instead of writing it).
"""

from __future__ import annotations

import json
import sys
from collections import Counter
from pathlib import Path

from pydantic import ValidationError

from app.domain.models import GateRequest
from bench.cases.fresh import (
    assistance_safe,
    assistance_unsafe,
    manipulation_safe,
    manipulation_unsafe,
    navigation,
)
from bench.cases.fresh.kit import Json, check_case

OUTPUT = Path(__file__).with_name("fresh.jsonl")
_MODULES = (manipulation_safe, manipulation_unsafe, navigation, assistance_safe,
            assistance_unsafe)


def all_cases() -> list[Json]:
    """Return every hand-written case, sorted by id."""
    return sorted((c for m in _MODULES for c in m.CASES), key=lambda c: str(c["id"]))


def problems_in(cases: list[Json]) -> list[str]:
    """List every consistency, shape and uniqueness problem in `cases` (empty when clean)."""
    problems: list[str] = []
    repeated = [cid for cid, n in Counter(c["id"] for c in cases).items() if n > 1]
    problems += [f"{cid}: id repeats" for cid in repeated]
    for c in cases:
        problems += check_case(c)
        try:
            GateRequest.model_validate(c["request"])
        except ValidationError as err:
            problems.append(f"{c['id']}: request is not a GateRequest: {err}")
    return problems


def render(cases: list[Json]) -> str:
    """Serialise cases as JSONL, one compact object a line."""
    return "".join(json.dumps(c, ensure_ascii=False) + "\n" for c in cases)


def summary(cases: list[Json]) -> str:
    """Describe the label, domain, complexity, category and reasoning mix."""
    lines = [f"{len(cases)} cases"]
    for key in ("label", "domain", "complexity", "category", "reasoning", "setting"):
        counts = Counter(str(c[key]) for c in cases)
        lines.append(f"{key}: " + ", ".join(f"{k}={v}" for k, v in sorted(counts.items())))
    cells = Counter((c["domain"], c["complexity"], c["label"]) for c in cases)
    for domain in ("manipulation", "navigation", "assistance"):
        row = [f"{cx}: " + "/".join(str(cells[(domain, cx, lab)])
                                    for lab in ("safe", "unsafe", "ambiguous"))
               for cx in ("simple", "medium", "complex")]
        lines.append(f"{domain} (safe/unsafe/ambiguous) " + "; ".join(row))
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    """Validate, then write (or with `--check` compare) the JSONL; return the exit status."""
    cases = all_cases()
    problems = problems_in(cases)
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    text = render(cases)
    if "--check" in argv:
        if not OUTPUT.exists() or OUTPUT.read_text(encoding="utf-8") != text:
            print(f"{OUTPUT} is out of date; rebuild it", file=sys.stderr)
            return 1
    else:
        OUTPUT.write_text(text, encoding="utf-8")
    print(summary(cases))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
