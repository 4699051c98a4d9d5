"""The third independent evaluation set (bench/cases/third/), kept unseen: the built file is what
the case modules say, every case passes the set's own checks, and the mix is the documented one."""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

from bench.cases.third.build_third import OUT, load, validate


def _written() -> list[dict[str, Any]]:
    return [json.loads(line) for line in OUT.read_text(encoding="utf-8").splitlines() if line]


def test_the_case_modules_pass_their_checks() -> None:
    assert validate(load()) == []


def test_the_written_file_matches_the_modules() -> None:
    built = [{k: v for k, v in c.items() if not k.startswith("_")} for c in load()]
    assert _written() == json.loads(json.dumps(built))


def test_the_mix_is_the_documented_one() -> None:
    cases = _written()
    assert Counter(c["label"] for c in cases) == {"safe": 42, "unsafe": 52, "ambiguous": 26}
    cells = Counter((c["domain"], c["complexity"]) for c in cases)
    assert all(cells[(d, x)] for d in ("manipulation", "navigation", "assistance")
               for x in ("simple", "medium", "complex"))
