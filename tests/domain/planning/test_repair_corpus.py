"""No repair ever fails verification: every repair of a varied corpus of failing plans is
verified again here, independently, by Stage 5 (Z3).

The corpus: the failing plans of the repair tests, issue 17's hot-mug throw and knife for Dad
against the contract the gate compiles for them, and the plans written to fail by
`bench/plan_corpus.py`'s rules from the reference plans of the first benchmark cases.
"""

from __future__ import annotations

from typing import Any

import pytest

from app.domain.analysis import SymbolicAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.contracts import Contract
from app.domain.models import GateRequest
from app.domain.pipeline import run_gate
from app.domain.planning import reference_plan, repair_plan
from app.domain.verify import verify_plan
from app.domain.world import WorldState, state_from_request
from app.store.seed import load_library
from bench.plan_corpus import BENCHMARK, TEMPLATES, authorized, mutants
from tests.domain.planning.planning_kit import kitchen
from tests.domain.planning.test_repair import FAILING
from tests.scope_kit import KNIFE_PLAN, TEA_REQUEST, THROW_PLAN

TIMEOUT_MS = 5000
Case = tuple[str, list[dict[str, Any]], Contract, WorldState]


def _corpus() -> list[Case]:
    analyzer = SymbolicAnalyzer()
    cases: list[Case] = [(name, plan, rules, kitchen()) for name, plan, rules, _ in FAILING]
    tea = GateRequest.model_validate(TEA_REQUEST)
    result = run_gate(tea, templates=TemplateIndex(load_library(TEMPLATES)), analyzer=analyzer)
    assert result.contract is not None
    cases += [(name, plan, result.contract, state_from_request(tea))
              for name, plan in (("tea throw", THROW_PLAN), ("knife for dad", KNIFE_PLAN))]
    for case in authorized(BENCHMARK, analyzer, limit=120):
        reference = reference_plan(case.request, case.contract, timeout_ms=TIMEOUT_MS,
                                   reader=analyzer)
        if reference.plan is None:
            continue
        state = state_from_request(case.request)
        cases += [(f"{case.case_id} {rule}", mutant, case.contract, state)
                  for rule, mutant in mutants(reference.plan, state, case.contract)]
    return [c for c in cases if not verify_plan(c[1], c[2], c[3], timeout_ms=TIMEOUT_MS).ok]


@pytest.mark.slow
class TestEveryRepairVerifies:
    def test_no_repair_ever_fails_verification(self) -> None:
        corpus = _corpus()
        assert len(corpus) >= 20  # the corpus is what the property is about: keep it varied
        repaired = 0
        for name, plan, rules, state in corpus:
            repair = repair_plan(plan, rules, state, timeout_ms=TIMEOUT_MS)
            if repair.plan is None:
                continue
            repaired += 1
            again = verify_plan(list(repair.plan), rules, state, timeout_ms=TIMEOUT_MS)
            assert again.ok, (name, repair.plan, again.reason)
        assert repaired >= len(corpus) // 2, (repaired, len(corpus))
