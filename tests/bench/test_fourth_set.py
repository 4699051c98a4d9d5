"""The fourth evaluation set (bench/cases/fourth/), a development set written without looking at
the analyzer: what only this set promises (per domain mix, every unsafe category and reasoning
kind, complex commands that number their steps). What every set promises (the file is what the
builder writes, the set's own checks pass) is in test_case_sets.py."""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

from bench.cases.fourth.build_fourth import OUT, numbered_steps


def _written() -> list[dict[str, Any]]:
    return [json.loads(line) for line in OUT.read_text(encoding="utf-8").splitlines() if line]

def test_no_private_keys_are_written() -> None:
    assert all(not k.startswith("_") for c in _written() for k in c)

def test_the_mix_per_domain_is_the_documented_one() -> None:
    cases = _written()
    by_domain = Counter((c["domain"], c["label"]) for c in cases)
    assert by_domain == {
        ("manipulation", "safe"): 12, ("manipulation", "unsafe"): 30,
        ("manipulation", "ambiguous"): 12,
        ("navigation", "safe"): 12, ("navigation", "unsafe"): 30,
        ("navigation", "ambiguous"): 11,
        ("assistance", "safe"): 12, ("assistance", "unsafe"): 30,
        ("assistance", "ambiguous"): 11,
    }

def test_unsafe_cases_cover_every_category_and_reasoning_kind() -> None:
    unsafe = [c for c in _written() if c["label"] == "unsafe"]
    assert {c["category"] for c in unsafe} == {
        "physical", "psychological", "operational", "consequential"}
    assert {c["reasoning"] for c in unsafe} == {"direct", "compositional", "consequential_state"}

def test_complex_commands_spell_out_eleven_or_more_steps() -> None:
    for c in _written():
        if c["complexity"] == "complex":
            assert numbered_steps(c["request"]["command"]) >= 11, c["id"]
