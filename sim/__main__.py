"""`python -m sim`: run every scenario with every available method and write the results.

In: optional `--scenarios DIR`, `--out DIR`, `--only ID[,ID...]`. Out: `summary.json`,
`episodes.json`, `report.md` and `cr_tc.png` in the output directory (default
`sim/results/`), and the CR%/TC% table on stdout. Fails: exit code 2 on a malformed scenario.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from sim.methods import available_methods
from sim.planner import SimPlanner
from sim.report import write_outputs
from sim.runner import run_all, summarize
from sim.scenario import SCENARIOS_DIR, ScenarioError, load_scenarios

RESULTS_DIR = Path(__file__).with_name("results")


def main(argv: list[str] | None = None) -> int:
    """Run the simulation; returns the process exit code."""
    parser = argparse.ArgumentParser(prog="python -m sim", description=__doc__)
    parser.add_argument("--scenarios", type=Path, default=SCENARIOS_DIR)
    parser.add_argument("--out", type=Path, default=RESULTS_DIR)
    parser.add_argument("--only", default="", help="comma-separated scenario ids")
    args = parser.parse_args(argv)
    try:
        scenarios = load_scenarios(args.scenarios)
    except ScenarioError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    if args.only:
        wanted = set(args.only.split(","))
        scenarios = [s for s in scenarios if s.id in wanted]
    started = time.perf_counter()
    skipped: dict[str, str] = {}
    with available_methods(skipped) as methods:
        results = run_all(scenarios, methods, SimPlanner())
    summary = summarize(results)
    write_outputs(summary, results, skipped, args.out)
    print(f"{len(scenarios)} scenarios x {len(summary)} methods in "
          f"{time.perf_counter() - started:.1f} s -> {args.out}")
    for method, entry in summary.items():
        hazard, safe = entry["hazard_scenarios"], entry["safe_controls"]
        print(f"{method:16} hazard CR% {hazard['cr_percent']!s:>5} TC% {hazard['tc_percent']!s:>5}"
              f" | safe CR% {safe['cr_percent']!s:>5} TC% {safe['tc_percent']!s:>5}")
    for name, why in skipped.items():
        print(f"{name:16} not run: {why}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
