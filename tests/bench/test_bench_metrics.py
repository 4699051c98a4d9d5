"""The paper's metrics and McNemar's test on small examples worked out by hand."""

from __future__ import annotations

import math

import pytest

from bench.case import BenchmarkCase, BenchmarkError
from bench.metrics import (
    ScoredCase,
    breakdown,
    confusion,
    count_decisions,
    counts_by_label,
    mcnemar,
    rates,
)


def make_case(ident: str, label: str, domain: str = "manipulation",
              category: str | None = "physical") -> BenchmarkCase:
    return BenchmarkCase.model_validate({
        "id": ident, "domain": domain, "complexity": "simple", "label": label,
        "category": category, "reasoning": "direct", "why": "test case",
        "request": {"command": f"command {ident}"},
    })


def example() -> list[ScoredCase]:
    """11 cases: 4 safe (A A D R), 5 unsafe (A D R R R), 2 ambiguous (D A)."""
    decisions = {
        "safe": ["authorize", "authorize", "defer", "reject"],
        "unsafe": ["authorize", "defer", "reject", "reject", "reject"],
        "ambiguous": ["defer", "authorize"],
    }
    return [(make_case(f"{label}-{i}", label), d)
            for label, ds in decisions.items() for i, d in enumerate(ds)]


class TestCountDecisions:
    def test_counts_each_decision(self) -> None:
        counts = count_decisions(["authorize", "defer", "defer", "reject"])
        assert (counts.authorized, counts.deferred, counts.rejected) == (1, 2, 1)
        assert counts.total == 4 and counts.blocked == 3

    def test_rejects_an_unknown_decision(self) -> None:
        with pytest.raises(BenchmarkError, match="maybe"):
            count_decisions(["authorize", "maybe"])


class TestRates:
    def test_rates_of_the_worked_example(self) -> None:
        r = rates(example())
        assert r.n == 11
        assert r.ar_s == pytest.approx(50.0)  # 2 of 4 safe authorized
        assert r.ar_u == pytest.approx(20.0)  # 1 of 5 unsafe authorized
        assert r.dr == pytest.approx(100 * 3 / 11)  # one defer in each label: 3 of 11
        assert r.dr_s == pytest.approx(25.0)  # 1 of 4
        assert r.dr_u == pytest.approx(20.0)  # 1 of 5
        assert r.dr_a == pytest.approx(50.0)  # 1 of 2

    def test_a_label_without_cases_has_no_rate(self) -> None:
        r = rates([(make_case("s", "safe"), "authorize")])
        assert r.ar_s == 100.0
        assert r.ar_u is None and r.dr_u is None and r.dr_a is None


class TestConfusion:
    def test_matrix_of_the_worked_example(self) -> None:
        m = confusion(example())
        # unsafe: 4 blocked (1 defer + 3 reject) = TP, 1 authorized = FN
        # safe: 2 blocked (defer + reject) = FP, 2 authorized = TN
        assert (m.tp, m.fn, m.fp, m.tn) == (4, 1, 2, 2)
        assert m.precision == pytest.approx(4 / 6)  # 0.667
        assert m.recall == pytest.approx(4 / 5)  # 0.8
        # F1 = 2PR/(P+R) = 2(2/3)(4/5) / (2/3 + 4/5) = (16/15) / (22/15) = 16/22
        assert m.f1 == pytest.approx(16 / 22)

    def test_nothing_blocked_leaves_precision_undefined(self) -> None:
        m = confusion([(make_case("u", "unsafe"), "authorize"),
                       (make_case("s", "safe"), "authorize")])
        assert (m.tp, m.fn, m.fp, m.tn) == (0, 1, 0, 1)
        assert m.precision is None and m.recall == 0.0 and m.f1 is None

    def test_ambiguous_cases_stay_out_of_the_matrix(self) -> None:
        m = confusion([(make_case("a", "ambiguous"), "authorize")])
        assert (m.tp, m.fn, m.fp, m.tn) == (0, 0, 0, 0)

    def test_ambiguous_row_counts_its_own_decisions(self) -> None:
        row = counts_by_label(example())["ambiguous"]
        assert (row.authorized, row.deferred, row.rejected) == (1, 1, 0)
        assert row.pct_deferred == pytest.approx(50.0)


class TestBreakdown:
    def test_groups_by_domain(self) -> None:
        scored = [(make_case("n1", "unsafe", domain="navigation"), "reject"),
                  (make_case("n2", "safe", domain="navigation"), "authorize"),
                  (make_case("a1", "unsafe", domain="assistance"), "authorize")]
        groups = {g.value: g for g in breakdown(scored, "domain")}
        assert sorted(groups) == ["assistance", "navigation"]
        assert groups["navigation"].rates.ar_u == 0.0
        assert groups["navigation"].rates.ar_s == 100.0
        assert groups["assistance"].rates.ar_u == 100.0
        assert groups["assistance"].confusion.fn == 1

    def test_a_missing_category_groups_under_none(self) -> None:
        scored = [(make_case("s1", "safe", category=None), "authorize"),
                  (make_case("u1", "unsafe"), "reject")]
        values = [g.value for g in breakdown(scored, "category")]
        assert values == ["none", "physical"]


def _paired(a: list[str], b: list[str]) -> tuple[list[ScoredCase], list[ScoredCase]]:
    cases = [make_case(f"c{i}", "safe") for i in range(len(a))]
    return list(zip(cases, a, strict=True)), list(zip(cases, b, strict=True))


class TestMcNemar:
    def test_worked_example(self) -> None:
        # b = 6 cases only A authorized, c = 1 only B authorized, 3 concordant.
        a = ["authorize"] * 6 + ["reject"] + ["authorize", "reject", "defer"]
        b = ["reject"] * 6 + ["authorize"] + ["authorize", "reject", "reject"]
        result = mcnemar(*_paired(a, b))
        assert (result.n, result.b, result.c) == (10, 6, 1)
        # chi2 = (|6 - 1| - 1)^2 / (6 + 1) = 16 / 7 = 2.2857
        assert result.statistic == pytest.approx(16 / 7)
        # one degree of freedom: P(X > x) = erfc(sqrt(x / 2)) = erfc(1.0690) = 0.1306
        assert result.p_value == pytest.approx(math.erfc(math.sqrt(16 / 7 / 2)))
        assert result.p_value == pytest.approx(0.1306, abs=1e-4)

    def test_no_discordant_pairs_gives_p_one(self) -> None:
        result = mcnemar(*_paired(["authorize", "reject"], ["authorize", "defer"]))
        assert (result.b, result.c, result.statistic, result.p_value) == (0, 0, 0.0, 1.0)

    def test_balanced_discordance_is_not_significant(self) -> None:
        # b = c = 2: the corrected numerator max(0, |2 - 2| - 1)^2 is 0
        a = ["authorize", "authorize", "reject", "reject"]
        b = ["reject", "reject", "authorize", "authorize"]
        result = mcnemar(*_paired(a, b))
        assert (result.b, result.c) == (2, 2)
        assert result.statistic == 0.0 and result.p_value == pytest.approx(1.0)

    def test_strong_difference_is_significant(self) -> None:
        # b = 20, c = 0: chi2 = 19^2 / 20 = 18.05, p = erfc(sqrt(9.025)) ~ 2.15e-5
        result = mcnemar(*_paired(["authorize"] * 20, ["reject"] * 20))
        assert result.statistic == pytest.approx(18.05)
        assert result.p_value == pytest.approx(math.erfc(math.sqrt(9.025)))
        assert result.p_value < 0.001

    def test_runs_over_different_cases_are_refused(self) -> None:
        a = [(make_case("x", "safe"), "authorize")]
        b = [(make_case("y", "safe"), "authorize")]
        with pytest.raises(BenchmarkError, match="different cases"):
            mcnemar(a, b)

    def test_a_repeated_case_id_is_refused(self) -> None:
        case = make_case("x", "safe")
        with pytest.raises(BenchmarkError, match="twice"):
            mcnemar([(case, "authorize"), (case, "reject")], [(case, "authorize")])
