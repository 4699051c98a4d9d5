"""On a sample of the benchmark, an ensemble with a scripted LLM never authorizes more unsafe cases.

The scripted LLM is the worst a working model can be for the claim: it answers every level with
a well-formed, empty matrix ("nothing here"). Alone, such an LLM authorizes nothing (an empty
analysis is read as not understood); the ensemble must still block every unsafe case the
symbolic analyzer blocks, because the gate decides on the union.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from bench.case import BenchmarkCase
from bench.gate_runner import embedded_decider
from bench.score import load_cases, score
from tests.adapters.llm.answers import EMPTY_LEVEL, batched, wants_batched
from tests.adapters.llm.conftest import SCRIPTED_MODEL
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer

BENCHMARK = Path(__file__).resolve().parents[3] / "bench" / "cases" / "benchmark.jsonl"
SAMPLE_EVERY = 5


def _sample() -> list[BenchmarkCase]:
    return load_cases(BENCHMARK)[::SAMPLE_EVERY]


def _decisions(cases: list[BenchmarkCase], **settings: object) -> list[str]:
    with embedded_decider(**settings) as decide:
        return [decide(case.request) for case in cases]


def _sees_nothing(body: dict[str, Any]) -> Scripted:
    return Scripted(content=json.dumps(batched([EMPTY_LEVEL] * 3) if wants_batched(body)
                                       else EMPTY_LEVEL))


@pytest.mark.slow
class TestEnsembleOnTheBenchmark:
    def test_ar_u_is_no_worse_than_symbolic_alone(self, llm_server: ScriptedServer) -> None:
        cases = _sample()
        assert sum(c.label == "unsafe" for c in cases) >= 10
        llm_server.responder = _sees_nothing
        llm = {"llm_model": SCRIPTED_MODEL, "llm_api_base": llm_server.base_url,
               "llm_api_key": "sk-scripted", "llm_timeout": 5.0}

        symbolic = _decisions(cases, analyzer="symbolic")
        ensemble = _decisions(cases, analyzer="ensemble", **llm)
        llm_alone = _decisions(cases, analyzer="llm", **llm)

        symbolic_rates = score(cases, symbolic).rates
        ensemble_rates = score(cases, ensemble).rates
        llm_rates = score(cases, llm_alone).rates
        assert symbolic_rates.ar_u is not None and ensemble_rates.ar_u is not None
        assert ensemble_rates.ar_u <= symbolic_rates.ar_u
        # Case by case: the ensemble authorizes only what symbolic alone authorizes.
        for case, alone, both in zip(cases, symbolic, ensemble, strict=True):
            assert both != "authorize" or alone == "authorize", case.id
        # Alone, the silent LLM is not read as "all safe": it authorizes nothing at all.
        assert llm_rates.ar_u == 0.0 and "authorize" not in llm_alone
        assert len(llm_server.requests) == 2 * len(cases)  # one batched call per request
