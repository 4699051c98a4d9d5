"""Regression guard for speed work on the analyzer: every benchmark case's report and decision.

Run: `.venv/bin/python bench/perf/analysis_stability.py record [SNAPSHOT]` once before a change,
then `.venv/bin/python bench/perf/analysis_stability.py check [SNAPSHOT]` after it.
In: bench/cases/benchmark.jsonl and the YAML template library. Out: a JSON snapshot (default
/tmp/safegate-analysis-snapshot.json) holding, per case, the full `HazardReport` (proposals and
unknowns, in order) and the gate's decision, rule, defer kind and question; `check` prints every
case whose report or decision differs and exits 1 if any does.
It is a script, not a committed test, on purpose: features that legitimately change decisions
(new rules, semantic matching) would break a committed snapshot; this one guards one optimisation
at a time. Fails: exits 2 when `check` finds no snapshot to compare with.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

from app.config import Settings
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.store import load_library

CASES = Path(__file__).resolve().parents[1] / "cases" / "benchmark.jsonl"
DEFAULT_SNAPSHOT = Path("/tmp/safegate-analysis-snapshot.json")


def outcomes() -> dict[str, Any]:
    """Each benchmark case's report and gate decision, keyed by case id."""
    analyzer = SymbolicAnalyzer()
    templates = TemplateIndex(load_library(Settings().templates_dir))
    results: dict[str, Any] = {}
    for line in CASES.read_text().splitlines():
        if not line.strip():
            continue
        case = json.loads(line)
        request = GateRequest.model_validate(case["request"])
        result = run_gate(request, templates=templates, analyzer=analyzer)
        decision = result.decision
        results[case["id"]] = {
            "report": result.report.model_dump(mode="json"),
            "decision": decision.decision.value,
            "rule": decision.rule.value,
            "defer_kind": decision.defer_kind.value if decision.defer_kind else None,
            "question": decision.question,
            "contract": result.contract.model_dump(mode="json") if result.contract else None,
        }
    return results


def main(argv: list[str]) -> int:
    if not argv or argv[0] not in ("record", "check"):
        print(__doc__)
        return 2
    snapshot = Path(argv[1]) if len(argv) > 1 else DEFAULT_SNAPSHOT
    current = outcomes()
    if argv[0] == "record":
        snapshot.write_text(json.dumps(current, indent=1, sort_keys=True))
        print(f"recorded {len(current)} cases to {snapshot}")
        return 0
    if not snapshot.exists():
        print(f"no snapshot at {snapshot}; run `record` first")
        return 2
    recorded = json.loads(snapshot.read_text())
    changed = sorted(case for case in recorded.keys() | current.keys()
                     if recorded.get(case) != current.get(case))
    for case in changed:
        before, after = recorded.get(case) or {}, current.get(case) or {}
        parts = [key for key in before.keys() | after.keys() if before.get(key) != after.get(key)]
        print(f"CHANGED {case}: {', '.join(sorted(parts))}")
    print(f"{len(current)} cases, {len(changed)} changed")
    return 1 if changed else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
