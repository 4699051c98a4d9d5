"""Benchmark: characters the LLM analyzer sends to the model per gate request, on the benchmark.

In: `bench/cases/benchmark.jsonl` (232 requests) and the seed library. Each request is analysed
by `LlmAnalyzer` with an in-process recording client (no network, no model) that answers every
call with the same small, valid level answer, so only what SafeGate sends differs between code
versions. Out: a Rich table of characters per request (messages alone, and with the JSON schema
sent in `response_format`) and calls per request: median, p90, mean, max; for each mode the
code has (level by level, and batched where `LlmAnalyzer` takes `batch_levels`), the mode a
service runs by default (`SAFEGATE_LLM_BATCH_LEVELS` unset) marked "(default)".
Run it on two checkouts to compare them, e.g. main against this branch:
    PYTHONPATH=<checkout> .venv/bin/python bench/perf/llm_prompt_size.py
"""

from __future__ import annotations

import inspect
import json
import statistics
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.table import Table

import app
from app.adapters.llm import ChatAnswer, LlmAnalyzer
from app.config import Settings
from app.domain.models import GateRequest
from app.store.seed import load_library

ROOT = Path(app.__file__).resolve().parents[1]
CASES = ROOT / "bench" / "cases" / "benchmark.jsonl"
# One non-critical unknown per level and its four cells answered "none, because ...": valid for
# every version, and no extra round (repair or entities) is asked for.
LEVEL = {"hazards": [], "unknowns": [{"attribute": "age_group", "description": "age unknown",
                                       "critical": False, "why": "may matter"}],
         "none_because": {c: "none, because the recording client reports none"
                          for c in ("physical", "psychological", "operational",
                                    "consequential")}}


class RecordingClient:
    """A `ChatClient` that counts what it is sent and answers with `LEVEL` (or all three)."""

    model = "recording/none"
    identity = "recording/none"

    def __init__(self) -> None:
        self.calls: list[tuple[int, int]] = []

    def complete(self, messages: Sequence[Mapping[str, str]], *, schema_name: str,
                 schema: Mapping[str, Any]) -> ChatAnswer:
        text = sum(len(m["content"]) for m in messages)
        self.calls.append((text, text + len(json.dumps(schema))))
        batched = "task" in schema.get("properties", {})
        answer = {"task": LEVEL, "deployment": LEVEL, "user": LEVEL} if batched else LEVEL
        return ChatAnswer(text=json.dumps(answer), finish_reason="stop")


def _row(label: str, values: Sequence[float]) -> list[str]:
    ordered = sorted(values)
    p90 = ordered[min(len(ordered) - 1, int(0.9 * len(ordered)))]
    return [label, f"{statistics.median(ordered):,.0f}", f"{p90:,.0f}",
            f"{statistics.fmean(ordered):,.0f}", f"{ordered[-1]:,.0f}"]


def main() -> int:
    """Analyse every benchmark request once and print the table."""
    library = tuple(load_library(ROOT / "templates_db"))
    requests = [GateRequest.model_validate(json.loads(line)["request"])
                for line in CASES.read_text().splitlines() if line.strip()]
    table = Table(title=f"Characters sent to the LLM per request ({len(requests)} requests, "
                        f"code at {Path(app.__file__).resolve().parents[1]})")
    for column in ("mode", "per request", "median", "p90", "mean", "max"):
        table.add_column(column, justify="left" if column in ("mode", "per request") else "right")
    modes: dict[str, dict[str, Any]] = {"level by level": {}}
    if "batch_levels" in inspect.signature(LlmAnalyzer).parameters:
        modes = {"level by level": {"batch_levels": False}, "batched": {"batch_levels": True}}
    # The mode a service runs when SAFEGATE_LLM_BATCH_LEVELS is not set.
    default = "batched" if getattr(Settings(), "llm_batch_levels", False) else "level by level"
    modes = {f"{m} (default)" if m == default else m: o for m, o in modes.items()}
    for mode, options in modes.items():
        text: list[float] = []
        with_schema: list[float] = []
        calls: list[float] = []
        for request in requests:
            client = RecordingClient()
            LlmAnalyzer(client, **options).analyze(request, library)
            text.append(sum(c[0] for c in client.calls))
            with_schema.append(sum(c[1] for c in client.calls))
            calls.append(len(client.calls))
        table.add_row(mode, *_row("characters, messages", text))
        table.add_row(mode, *_row("characters, + response_format schema", with_schema))
        table.add_row(mode, *_row("LLM calls", calls))
    Console(width=110).print(table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
