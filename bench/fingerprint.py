"""A fingerprint of SafeGate's decisions on every case set, to show a change left them alone.

In: case files (default: every `bench/cases/**/*.jsonl`), run through the `safegate` method of
the benchmark runner (POST /gate of an embedded app, symbolic analyzer). Out: one line per set,
`<set> <cases> <sha256>`, where the hash is over the set's `{case id: decision}` as canonical
JSON; `--out FILE` also writes them as JSON, and `--against FILE` compares with an earlier run
and exits 1 when any set's hash differs. Only hashes and counts are printed, never a decision,
so running it on the sealed sets reveals nothing about them.
Fails: `BenchmarkError` on a bad case file; an HTTP error from the gate propagates.

Run: `python -m bench.fingerprint --out /tmp/before.json`, change the code, then
`python -m bench.fingerprint --against /tmp/before.json`.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from collections.abc import Sequence
from pathlib import Path

from bench.methods import SafeGateMethod
from bench.score import load_cases

CASES_ROOT = Path(__file__).resolve().parent / "cases"


def case_files(root: Path | None = None) -> list[Path]:
    """Every case set under `root` (default `bench/cases/`), in a stable order."""
    return sorted((root or CASES_ROOT).rglob("*.jsonl"))


def decision_digest(decisions: dict[str, str]) -> str:
    """The sha256 of a set's `{case id: decision}`, keys sorted, as compact JSON."""
    canonical = json.dumps(decisions, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


def fingerprint(
    paths: Sequence[Path], root: Path | None = None
) -> dict[str, dict[str, object]]:
    """Run SafeGate on each file and hash its decisions.

    Args:
        paths: case files under `root`.
        root: the directory set names are given relative to (default `bench/cases/`).

    Returns:
        For each set (its path relative to `root`), the number of cases and the digest.
    """
    prints: dict[str, dict[str, object]] = {}
    # One embedded app for every set: each request is decided on its own, as in production.
    with SafeGateMethod().open() as decide:
        for path in paths:
            decisions = {case.id: decide(case.request).decision for case in load_cases(path)}
            name = str(path.resolve().relative_to((root or CASES_ROOT).resolve()))
            prints[name] = {"cases": len(decisions), "sha256": decision_digest(decisions)}
            print(f"{name:<36} {len(decisions):>4} {prints[name]['sha256']}", flush=True)
    return prints


def differing_sets(
    now: dict[str, dict[str, object]], before: dict[str, dict[str, object]]
) -> list[str]:
    """The sets whose fingerprint changed, appeared or disappeared."""
    return sorted(name for name in now.keys() | before.keys() if now.get(name) != before.get(name))


def main(argv: Sequence[str] | None = None) -> int:
    """Command-line entry: fingerprint, optionally save and compare; 1 when anything differs."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path, help="case files (default: all sets)")
    parser.add_argument("--out", type=Path, help="write the fingerprints here as JSON")
    parser.add_argument("--against", type=Path, help="an earlier --out file to compare with")
    args = parser.parse_args(argv)
    prints = fingerprint(args.files or case_files())
    if args.out:
        args.out.write_text(json.dumps(prints, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    if args.against:
        changed = differing_sets(prints, json.loads(args.against.read_text(encoding="utf-8")))
        print(f"{len(prints) - len(changed)}/{len(prints)} sets identical"
              + (f"; differing: {', '.join(changed)}" if changed else ""))
        return 1 if changed else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
