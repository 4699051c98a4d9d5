"""The fourth evaluation set (bench/cases/fourth/), a development set written without looking at
the analyzer: the built file is what the case modules say, every case passes the set's own
checks, and the mix is the documented one."""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

from bench.cases.fourth.build_fourth import OUT, load, numbered_steps, validate

DOMAINS = ("manipulation", "navigation", "assistance")


def _written() -> list[dict[str, Any]]:
    return [json.loads(line) for line in OUT.read_text(encoding="utf-8").splitlines() if line]


def test_the_case_modules_pass_their_checks() -> None:
    assert validate(load()) == []


def test_the_written_file_matches_the_modules() -> None:
    built = [{k: v for k, v in c.items() if not k.startswith("_")} for c in load()]
    assert _written() == json.loads(json.dumps(built))


def test_no_private_keys_are_written() -> None:
    assert all(not k.startswith("_") for c in _written() for k in c)


def test_the_mix_is_the_documented_one() -> None:
    cases = _written()
    assert len(cases) == 160
    assert Counter(c["label"] for c in cases) == {"safe": 36, "unsafe": 90, "ambiguous": 34}
    by_domain = Counter((c["domain"], c["label"]) for c in cases)
    assert by_domain == {
        ("manipulation", "safe"): 12, ("manipulation", "unsafe"): 30,
        ("manipulation", "ambiguous"): 12,
        ("navigation", "safe"): 12, ("navigation", "unsafe"): 30,
        ("navigation", "ambiguous"): 11,
        ("assistance", "safe"): 12, ("assistance", "unsafe"): 30,
        ("assistance", "ambiguous"): 11,
    }
    cells = Counter((c["domain"], c["complexity"]) for c in cases)
    assert all(cells[(d, x)] for d in DOMAINS for x in ("simple", "medium", "complex"))


def test_unsafe_cases_cover_every_category_and_reasoning_kind() -> None:
    unsafe = [c for c in _written() if c["label"] == "unsafe"]
    assert {c["category"] for c in unsafe} == {
        "physical", "psychological", "operational", "consequential"}
    assert {c["reasoning"] for c in unsafe} == {"direct", "compositional", "consequential_state"}


def test_complex_commands_spell_out_eleven_or_more_steps() -> None:
    for c in _written():
        if c["complexity"] == "complex":
            assert numbered_steps(c["request"]["command"]) >= 11, c["id"]
