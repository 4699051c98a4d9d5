"""Reference plans: how many authorized benchmark cases get one, each proved by Stage 5.

In: a case file (default `bench/cases/benchmark.jsonl`). Out: a table: cases, authorized, with a
reference plan (share of authorized), each plan verified again here with `verify_plan` (Z3) and
stepped to check it reaches the goal it was planned for, median and p90 planning time, and the
reasons of the cases without one. Exit 1 if any returned plan fails its re-verification (a
reference plan that is not proved must never be handed out).
Run: `PYTHONPATH=. .venv/bin/python bench/reference_plans.py [FILE]`.
"""

from __future__ import annotations

import statistics
import sys
import time
from collections import Counter
from pathlib import Path

from rich.console import Console
from rich.table import Table

from app.domain.analysis import SymbolicAnalyzer
from app.domain.planning import goal_for, reference_plan
from app.domain.verify import verify_plan
from app.domain.world import parse_action, state_from_request, step
from bench.plan_corpus import BENCHMARK, SOLVER_TIMEOUT_MS, authorized


def _why(reason: str) -> str:
    """A miss's reason without its case-specific details."""
    return reason.split(":")[1].strip() if reason.count(":") >= 1 else reason


def main(argv: list[str]) -> int:
    path = Path(argv[0]) if argv else BENCHMARK
    analyzer = SymbolicAnalyzer()
    cases = sum(1 for line in path.read_text(encoding="utf-8").splitlines() if line.strip())
    found = proved = reached = total = 0
    timings: list[float] = []
    misses: Counter[str] = Counter()
    for case in authorized(path, analyzer):
        total += 1
        started = time.perf_counter()
        reference = reference_plan(case.request, case.contract, timeout_ms=SOLVER_TIMEOUT_MS,
                                   reader=analyzer)
        timings.append((time.perf_counter() - started) * 1000)
        if reference.plan is None:
            misses[_why(reference.reason)] += 1
            continue
        found += 1
        state = state_from_request(case.request)
        again = verify_plan(list(reference.plan), case.contract, state,
                            timeout_ms=SOLVER_TIMEOUT_MS)
        proved += again.ok
        for index, raw in enumerate(reference.plan):
            state = step(state, parse_action(raw, step=index, state=state))
        reached += goal_for(case.request, state_from_request(case.request),
                            reader=analyzer).satisfied(state)
    timings.sort()
    table = Table(title=f"Reference plans on {path.name} (POST /gate?reference_plan=true)")
    for column in ("cases", "authorized", "with a reference plan", "re-verified (Z3)",
                   "reach their goal", "median ms", "p90 ms"):
        table.add_column(column)
    share = f"{found} ({100 * found / total:.1f} %)" if total else "0"
    table.add_row(str(cases), str(total), share, f"{proved}/{found}", f"{reached}/{found}",
                  f"{statistics.median(timings):.1f}" if timings else "-",
                  f"{timings[int(0.9 * (len(timings) - 1))]:.1f}" if timings else "-")
    console = Console()
    console.print(table)
    for why, count in misses.most_common():
        console.print(f"  no plan ({count}): {why}")
    return 0 if proved == found else 1


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
