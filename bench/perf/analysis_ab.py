"""Stages 1-4 in process, this checkout against another one, in the same run.

Run: `.venv/bin/python bench/perf/analysis_ab.py --baseline DIR [--baseline-python PY]
[--rounds N]`, where DIR is another checkout of SafeGate (e.g. `git worktree add
/tmp/safegate-before <commit>`) and PY the interpreter of a venv with that checkout's
dependencies (default: this one). Run by hand (not by `make perf`): it needs a baseline.

Each checkout runs in its own Python process (its own `app` package on `sys.path`) and decides
every request of `bench/cases/benchmark.jsonl` with the embedded symbolic analyzer and its own
seed library, the way `POST /gate` calls `run_gate`, after one warm-up pass. The two processes run
their rounds in turn (one round of this checkout, one of the baseline, ...), so a busy machine
slows both alike. Prints ms per request (p50, p90, p99, max) for each and their ratio.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

from rich.console import Console
from rich.table import Table

HERE = Path(__file__).resolve().parents[2]
CASES = HERE / "bench" / "cases" / "benchmark.jsonl"

# Run inside each checkout: decide every case once per line read on stdin, print the times.
_WORKER = r"""
import json, sys, time
from pathlib import Path
from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.store.seed import load_library
requests = [GateRequest.model_validate(json.loads(line)["request"])
            for line in Path(sys.argv[1]).read_text().splitlines() if line]
index = TemplateIndex(load_library(Path("templates_db")))
analyzer = SymbolicAnalyzer()
for request in requests:
    run_gate(request, templates=index, analyzer=analyzer)
print("ready", flush=True)
for _ in sys.stdin:
    times = []
    for request in requests:
        started = time.perf_counter()
        run_gate(request, templates=index, analyzer=analyzer)
        times.append((time.perf_counter() - started) * 1000)
    print(json.dumps(times), flush=True)
"""


def _start(checkout: Path, python: str = sys.executable) -> subprocess.Popen[str]:
    process = subprocess.Popen(
        [python, "-c", _WORKER, str(CASES)], cwd=checkout, text=True,
        stdin=subprocess.PIPE, stdout=subprocess.PIPE,
        env={"PYTHONPATH": str(checkout), "PATH": "/usr/bin:/bin"})
    assert process.stdout is not None and process.stdout.readline().strip() == "ready"
    return process


def _round(process: subprocess.Popen[str]) -> list[float]:
    assert process.stdin is not None and process.stdout is not None
    process.stdin.write("go\n")
    process.stdin.flush()
    times: list[float] = json.loads(process.stdout.readline())
    return times


def _row(name: str, times: list[float]) -> list[str]:
    ordered = sorted(times)
    pick = [ordered[min(len(ordered) - 1, int(f * len(ordered)))] for f in (0.5, 0.9, 0.99)]
    return [name, *(f"{v:.2f}" for v in pick), f"{ordered[-1]:.2f}",
            f"{statistics.fmean(times):.2f}"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", type=Path, required=True)
    parser.add_argument("--baseline-python", default=sys.executable)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    mine = _start(HERE)
    theirs = _start(args.baseline.resolve(), args.baseline_python)
    after: list[float] = []
    before: list[float] = []
    try:
        for _ in range(args.rounds):
            after += _round(mine)
            before += _round(theirs)
    finally:
        for process in (mine, theirs):
            process.kill()
    table = Table(title=f"run_gate in process, {len(before)} requests each (benchmark.jsonl)")
    for column in ("checkout", "p50 ms", "p90 ms", "p99 ms", "max ms", "mean ms"):
        table.add_column(column)
    table.add_row(*_row(f"baseline ({args.baseline})", before))
    table.add_row(*_row("this checkout", after))
    Console().print(table)
    ratio = statistics.fmean(after) / statistics.fmean(before)
    Console().print(f"mean ratio this / baseline: {ratio:.2f}")


if __name__ == "__main__":
    main()
