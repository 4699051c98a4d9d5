"""Every case set under bench/cases/, one parametrized test a property: each committed file is
byte for byte what its builder writes, each set passes its own checks, every line is a case of
the benchmark format, and each label mix is the one its README documents."""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

import pytest

from bench.cases.build_benchmark import OUTPUT as BENCHMARK
from bench.cases.build_benchmark import build, render
from bench.cases.fourth import build_fourth
from bench.cases.fresh import build_fresh
from bench.cases.second import build_second
from bench.cases.third import build_third
from bench.score import load_cases

CASES = BENCHMARK.parent
DEVMIX = CASES / "devmix" / "devmix.jsonl"


def _public_lines(cases: Iterable[dict[str, Any]]) -> str:
    """How the second, third and fourth builders write: private `_` keys dropped."""
    return "".join(json.dumps({k: v for k, v in c.items() if not k.startswith("_")},
                              ensure_ascii=False) + "\n" for c in cases)


BUILT: dict[str, tuple[Path, Callable[[], str]]] = {
    "benchmark": (BENCHMARK, lambda: render(build())),
    "fresh": (build_fresh.OUTPUT, lambda: build_fresh.render(build_fresh.all_cases())),
    "second": (build_second.OUT, lambda: _public_lines(build_second.load())),
    "third": (build_third.OUT, lambda: _public_lines(build_third.load())),
    "fourth": (build_fourth.OUT, lambda: _public_lines(build_fourth.load())),
}
CHECKED: dict[str, Callable[[], list[str]]] = {
    "fresh": lambda: build_fresh.problems_in(build_fresh.all_cases()),
    "second": lambda: build_second.validate(build_second.load()),
    "third": lambda: build_third.validate(build_third.load()),
    "fourth": lambda: build_fourth.validate(build_fourth.load()),
}
MIX: dict[str, tuple[Path, dict[str, int]]] = {
    "benchmark": (BENCHMARK, {"safe": 83, "unsafe": 100, "ambiguous": 49}),
    "second": (build_second.OUT, {"safe": 55, "unsafe": 63, "ambiguous": 32}),
    "third": (build_third.OUT, {"safe": 42, "unsafe": 52, "ambiguous": 26}),
    "fourth": (build_fourth.OUT, {"safe": 36, "unsafe": 90, "ambiguous": 34}),
}
FILES = {name: path for name, (path, _) in BUILT.items()} | {"devmix": DEVMIX}


@pytest.mark.parametrize("name", BUILT)
def test_the_committed_file_is_what_its_builder_writes(name: str) -> None:
    path, written_by_builder = BUILT[name]
    assert path.read_text(encoding="utf-8") == written_by_builder()


@pytest.mark.parametrize("name", CHECKED)
def test_every_case_passes_its_sets_checks(name: str) -> None:
    assert CHECKED[name]() == []


@pytest.mark.parametrize("name", FILES)
def test_every_line_is_a_case_with_its_own_id(name: str) -> None:
    lines = FILES[name].read_text(encoding="utf-8").splitlines()
    cases = load_cases(FILES[name])  # raises on a bad line or a repeated id
    assert len(cases) == len(lines) >= 90
    assert {c.label for c in cases} == {"safe", "unsafe", "ambiguous"}


@pytest.mark.parametrize("name", MIX)
def test_the_label_mix_is_the_documented_one(name: str) -> None:
    path, mix = MIX[name]
    cases = load_cases(path)
    assert Counter(c.label for c in cases) == mix
    cells = Counter((c.domain, c.complexity) for c in cases)
    assert len(cells) == 9 and min(cells.values()) > 0
