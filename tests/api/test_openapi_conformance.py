"""The OpenAPI document tells the truth: schemathesis, every check, against a live server.

`schemathesis run --checks all` (its CLI, as an operator would run it) goes through every
operation of `/openapi.json` served by a real `safegate serve` with `SAFEGATE_AUTH=keys` (the
mode in which the document's security requirements are exact), holding an admin key, for
`SAFEGATE_CONFORMANCE_EXAMPLES` examples per operation (default 10: about 30 s) from a fixed
seed. Every answer must be documented: its status, its content type (`application/problem+json`
for every error), its headers and its body's schema; no 5xx; no route answers without a key;
undeclared methods get 405 with the path's `Allow`.

One finding is allowed, only where it is explained (and schemathesis's own generator crash,
`GENERATOR_CRASH`, which sends nothing): ST202 (a schema-valid body refused) on operations that
take a body: the edge limits of `app/api/limits.py` (numbers within ±1e15, no NUL or lone
surrogate, nesting depth) and the service's own validation (a template's formulas, a plan's
steps against the scene) refuse bodies JSON Schema cannot describe, each with a 422 naming the
field. (ST201, a JSON boolean read as a number, was found here and fixed in the request models.)
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from app.services.access import issue_api_key
from app.store.db import create_engine_for, migrate
from app.store.records import ApiKeyRole
from app.store.repository import Repository

EXAMPLES = int(os.environ.get("SAFEGATE_CONFORMANCE_EXAMPLES", "10"))
SEED = 20
BODY_OPERATIONS = {
    "POST /gate", "POST /gate/{request_id}/answers", "POST /verify", "POST /monitor",
    "POST /templates", "POST /templates/validate", "PUT /templates/{template_id}",
    "POST /extensions/reevaluate", "POST /keys",
}
ALLOWED = {("ST202", op) for op in BODY_OPERATIONS}

# Hypothesis, describing a lambda of schemathesis's generator for the gate request's large
# schema, sometimes trips a CPython 3.11 AST check (no request is sent); schemathesis reports it
# as a "Runtime Error". Any other error (the server unreachable, a crash) fails the test.
GENERATOR_CRASH = "AST constructor recursion depth mismatch"

pytestmark = pytest.mark.slow


def admin_key(database_url: str) -> str:
    engine = create_engine_for(database_url)
    try:
        migrate(engine)
        return issue_api_key(Repository(engine), ApiKeyRole.ADMIN, "conformance")[1]
    finally:
        engine.dispose()


def run_schemathesis(base_url: str, key: str, report_dir: Path) -> dict[str, Any]:
    """Run the CLI with every check; its JSON report."""
    command = [
        sys.executable, "-m", "schemathesis.cli", "run", f"{base_url}/openapi.json",
        "--checks", "all", "--max-examples", str(EXAMPLES), "--seed", str(SEED),
        "--workers", "2", "-H", f"Authorization: Bearer {key}",
        "--report", "json", "--report-dir", str(report_dir),
    ]
    completed = subprocess.run(command, capture_output=True, text=True, timeout=600,
                               check=False, cwd=report_dir)  # its cache lands there too
    reports = list(report_dir.glob("*.json"))
    assert reports, completed.stdout[-3000:] + completed.stderr[-3000:]
    report: dict[str, Any] = json.loads(reports[0].read_text())
    report["output"] = completed.stdout
    return report


class TestOpenApiConformance:
    def test_every_answer_is_documented_under_all_checks(
        self, live_server: Callable[..., Any], sqlite_url: str, tmp_path: Path
    ) -> None:
        key = admin_key(sqlite_url)
        server = live_server(SAFEGATE_AUTH="keys", SAFEGATE_LOG_LEVEL="warning")
        report = run_schemathesis(server.base_url, key, tmp_path)
        output: str = report["output"]
        # What a failing run should show: each failure with its curl command, then the summary.
        tail = output[output.find("=== FAILURES"):][-12000:]
        assert report["complete"], tail
        assert report["operations"]["tested"] == report["operations"]["total"] == 25, tail
        errors = output[output.find("=== ERRORS"):output.find("=== FAILURES")]
        blocks = re.split(r"\n_{3,} .+? _{3,}\n", errors)[1:]
        assert bool(report["errors"]) == bool(blocks), errors[-6000:]
        assert all(GENERATOR_CRASH in block for block in blocks), errors[-6000:]
        assert report["test_cases"]["generated"] > 25 * EXAMPLES, tail
        found = {(failure["code"], operation) for failure in report["failures"]
                 for operation in failure["operations"]}
        codes = {code for code, _ in found}
        assert not codes & {"ST103", "ST105"}, tail  # undocumented status / content type
        assert found <= ALLOWED, f"{sorted(found - ALLOWED)}\n{tail}"
