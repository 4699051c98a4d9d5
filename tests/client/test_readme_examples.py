"""The README's client examples run, as written, against a live server on loopback, in a fresh
venv that holds the SDK alone.

Every ```python block of the README's "Using SafeGate from Python" section is run in its own
process with the server's address in place of `http://127.0.0.1:8000` (nothing else changes),
against a real `safegate serve` (embedded default: SQLite, symbolic analyzer). The process is
the Python of a new venv into which `pip install ./clients/python` put `safegate-client` and
its three dependencies only (the README's install step): so the examples, and the SDK, need
nothing of the server. Each must exit 0 and print what the README says it shows: the sync
example a verified plan (`plan ok: True []`) and a clean monitor summary, the async one a
decision per command.
"""

from __future__ import annotations

import ast
import os
import re
import subprocess
import venv
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


def clean_env() -> dict[str, str]:
    """This process's environment without anything that would put the server on the path."""
    return {name: value for name, value in os.environ.items()
            if name not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}


@pytest.fixture(scope="module")
def sdk_python(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The Python of a fresh venv with `pip install ./clients/python` done, as the README says."""
    home = tmp_path_factory.mktemp("sdk-venv")
    venv.EnvBuilder(with_pip=True).create(home)
    python = home / "bin" / "python"
    installed = subprocess.run(
        [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
         str(ROOT / "clients" / "python")],
        capture_output=True, text=True, timeout=600, env=clean_env(), cwd=home, check=False)
    assert installed.returncode == 0, installed.stdout[-2000:] + installed.stderr[-2000:]
    return python


def run(python: Path, code: str, base_url: str, tmp_path: Path,
        name: str) -> subprocess.CompletedProcess[str]:
    script = tmp_path / f"{name}.py"
    script.write_text(code.replace("http://127.0.0.1:8000", base_url))
    return subprocess.run([str(python), str(script)], capture_output=True, text=True,
                          timeout=120, env=clean_env(), cwd=tmp_path, check=False)


class TestReadmeExamples:
    def test_there_are_a_sync_and_an_async_example(self) -> None:
        examples = readme_examples()
        assert len(examples) == 2
        assert "GateClient(" in examples[0] and "MonitorClient(" in examples[0]
        assert "AsyncGateClient(" in examples[1]
        for code in examples:
            ast.parse(code)
            assert "from safegate_client import" in code and "app." not in code

    @pytest.mark.slow
    def test_the_fresh_venv_has_the_sdk_and_nothing_of_the_server(
            self, sdk_python: Path, tmp_path: Path) -> None:
        probe = ("import importlib.util, safegate_client\n"
                 "print(safegate_client.__version__, [m for m in ('app', 'fastapi', "
                 "'sqlalchemy', 'z3', 'uvicorn') if importlib.util.find_spec(m)])")
        ran = subprocess.run([str(sdk_python), "-c", probe], capture_output=True, text=True,
                             timeout=60, env=clean_env(), cwd=tmp_path, check=False)
        assert ran.returncode == 0, ran.stderr[-2000:]
        assert ran.stdout.split() == ["0.1.0", "[]"]

    @pytest.mark.slow
    def test_each_example_runs_against_a_live_server(
            self, live_server: Callable[..., Any], sdk_python: Path, tmp_path: Path) -> None:
        server = live_server(SAFEGATE_LOG_LEVEL="warning")
        sync_example, async_example = readme_examples()
        ran = run(sdk_python, sync_example, server.base_url, tmp_path, "sync_example")
        assert ran.returncode == 0, ran.stdout[-2000:] + ran.stderr[-2000:]
        assert "authorize R4" in ran.stdout
        assert "plan ok: True []" in ran.stdout
        assert "checked 4 actions; halted: False violations: []" in ran.stdout
        assert ran.stdout.count("running {") == 4
        ran = run(sdk_python, async_example, server.base_url, tmp_path, "async_example")
        assert ran.returncode == 0, ran.stdout[-2000:] + ran.stderr[-2000:]
        lines = ran.stdout.strip().splitlines()
        assert lines[0].startswith("'switch the coffee machine off': authorize (R4)")
        assert lines[1].startswith("'give the knife to the child': reject (R1)")
