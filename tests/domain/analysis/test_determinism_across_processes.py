"""Same request, same decision, in every process: no set's iteration order may reach it.

Python seeds its string hashes per process, so a rule that walks a set (a route search over
neighbour sets, the rooms a robot drives through) can answer differently after a restart while
answering the same way every time within one process. Each child process here analyses the
development case sets through Stages 1-4 under its own `PYTHONHASHSEED` and prints one digest
per case (the report, binding, decision and contract; not the timings).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
CASE_FILES = ("bench/cases/benchmark.jsonl", "bench/cases/second/second.jsonl",
              "bench/cases/fourth/fourth.jsonl")
SEEDS = ("1", "2", "3")

_DIGESTS = """
import hashlib, json, sys
from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.store.seed import load_library
analyzer = SymbolicAnalyzer()
templates = TemplateIndex(load_library(Settings().templates_dir))
for name in sys.argv[1:]:
    for line in open(name, encoding="utf-8"):
        if line.strip():
            case = json.loads(line)
            result = run_gate(GateRequest.model_validate(case["request"]),
                              templates=templates, analyzer=analyzer)
            kept = result.model_dump_json(exclude={"timings_ms"})
            print(case["id"], hashlib.sha256(kept.encode()).hexdigest())
"""


def _digests(seed: str) -> dict[str, str]:
    done = subprocess.run(
        [sys.executable, "-c", _DIGESTS, *CASE_FILES], cwd=ROOT, capture_output=True,
        text=True, check=True, timeout=300, env={**os.environ, "PYTHONHASHSEED": seed})
    return dict(line.split() for line in done.stdout.splitlines())


@pytest.mark.slow
def test_reports_do_not_depend_on_the_hash_seed() -> None:
    first, *others = (_digests(seed) for seed in SEEDS)
    assert len(first) > 500
    for other in others:
        differing = sorted(case for case in first if other.get(case) != first[case])
        assert not differing, f"reports differ between processes for {differing}"

