"""The README's client examples run, as written, against a live server on loopback.

Every ```python block of the README's "Using SafeGate from Python" section is run in its own
process with the server's address in place of `http://127.0.0.1:8000` (nothing else changes),
against a real `safegate serve` (embedded default: SQLite, symbolic analyzer). Each must exit 0
and print what the README says it shows: the sync example a verified plan (`plan ok: True`)
and a clean monitor summary, the async one a decision per command.
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
SECTION = "## Using SafeGate from Python"


def readme_examples() -> list[str]:
    text = (ROOT / "README.md").read_text()
    section = text[text.index(SECTION):]
    section = section[:section.index("\n## ", len(SECTION))]
    return re.findall(r"```python\n(.*?)```", section, re.S)


def run(code: str, base_url: str, tmp_path: Path, name: str) -> subprocess.CompletedProcess[str]:
    script = tmp_path / f"{name}.py"
    script.write_text(code.replace("http://127.0.0.1:8000", base_url))
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=120, env=env, cwd=tmp_path, check=False)


class TestReadmeExamples:
    def test_there_are_a_sync_and_an_async_example(self) -> None:
        examples = readme_examples()
        assert len(examples) == 2
        assert "GateClient(" in examples[0] and "MonitorClient(" in examples[0]
        assert "AsyncGateClient(" in examples[1]
        for code in examples:
            ast.parse(code)

    @pytest.mark.slow
    def test_each_example_runs_against_a_live_server(
            self, live_server: Callable[..., Any], tmp_path: Path) -> None:
        server = live_server(SAFEGATE_LOG_LEVEL="warning")
        sync_example, async_example = readme_examples()
        ran = run(sync_example, server.base_url, tmp_path, "sync_example")
        assert ran.returncode == 0, ran.stdout[-2000:] + ran.stderr[-2000:]
        assert "authorize R4" in ran.stdout
        assert "plan ok: True []" in ran.stdout
        assert "'violations': [], 'halted': False" in ran.stdout
        assert ran.stdout.count("running {") == 4
        ran = run(async_example, server.base_url, tmp_path, "async_example")
        assert ran.returncode == 0, ran.stdout[-2000:] + ran.stderr[-2000:]
        lines = ran.stdout.strip().splitlines()
        assert lines[0].startswith("'switch the coffee machine off': authorize (R4)")
        assert lines[1].startswith("'give the knife to the child': reject (R1)")
