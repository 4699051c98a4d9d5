"""The service stands alone: what the wheel ships and what importing the service loads.

In: `pyproject.toml` and a fresh interpreter importing the service's entry points. Out: pytest
verdicts. The packages setuptools finds with the project's own `packages.find` settings are
`app` and its subpackages only (bench/ and sim/ run from a source checkout); scipy and
matplotlib are dependencies of the `bench` extra, not of the server; and loading the app, its
command line and every API route imports neither the evaluation, the simulator nor those two
libraries. (import-linter checks the same boundary statically: `app` -> `bench`/`sim`.)
"""

from __future__ import annotations

import re
import subprocess
import sys
import tomllib
from pathlib import Path

from setuptools import find_namespace_packages

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
EVALUATION_ONLY = ("scipy", "matplotlib")


def _names(requirements: list[str]) -> set[str]:
    return {re.split(r"[<>=!~\[;\s]", r, maxsplit=1)[0].lower() for r in requirements}


class TestWheel:
    def test_ships_the_service_package_only(self) -> None:
        find = PYPROJECT["tool"]["setuptools"]["packages"]["find"]
        packages = find_namespace_packages(where=str(ROOT), include=find["include"],
                                           exclude=find.get("exclude", ()))
        assert "app" in packages
        assert {p.split(".")[0] for p in packages} == {"app"}

    def test_the_server_needs_no_statistics_or_plotting(self) -> None:
        project = PYPROJECT["project"]
        assert not _names(project["dependencies"]) & set(EVALUATION_ONLY)
        assert _names(project["optional-dependencies"]["bench"]) >= set(EVALUATION_ONLY)


class TestImports:
    def test_the_service_loads_without_the_evaluation(self) -> None:
        probe = (
            "import sys\n"
            "from app.main import create_app\n"
            "from app.cli import cli\n"
            "import app.api.routes\n"
            "from app.config import Settings\n"
            "create_app(Settings(database_url='sqlite://'))\n"
            f"loaded = sorted(m for m in sys.modules if m.split('.')[0] in "
            f"{('bench', 'sim', *EVALUATION_ONLY)!r})\n"
            "print(','.join(loaded))\n"
        )
        done = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True,
                              text=True, timeout=120, check=False)
        assert done.returncode == 0, done.stderr
        assert done.stdout.strip() == ""
