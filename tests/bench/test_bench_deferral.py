"""The deferral analysis on a small example worked out by hand."""

from __future__ import annotations

import pytest

from bench.case import BenchmarkCase, BenchmarkError
from bench.deferral import deferral_analysis


def make_case(ident: str, label: str) -> BenchmarkCase:
    return BenchmarkCase.model_validate({
        "id": ident, "domain": "assistance", "complexity": "simple", "label": label,
        "category": None if label == "safe" else "physical",
        "reasoning": "direct", "why": "test", "request": {"command": f"do {ident}"},
    })


CASES = [make_case("s1", "safe"), make_case("u1", "unsafe"), make_case("u2", "unsafe"),
         make_case("a1", "ambiguous"), make_case("a2", "ambiguous")]
# SafeGate defers u1, a1, a2 (one unsafe, two ambiguous) and decides s1, u2.
DECISIONS = {
    "safegate": {"s1": "authorize", "u1": "defer", "u2": "reject", "a1": "defer", "a2": "defer"},
    "other": {"s1": "reject", "u1": "authorize", "u2": "authorize", "a1": "authorize",
              "a2": "reject"},
    "cautious": {"s1": "authorize", "u1": "reject", "u2": "reject", "a1": "defer",
                 "a2": "defer"},
}


class TestDeferralAnalysis:
    def test_lists_the_reference_deferrals_in_case_order(self) -> None:
        analysis = deferral_analysis(CASES, "safegate", DECISIONS)
        assert analysis.deferred_ids == ("u1", "a1", "a2")
        assert analysis.labels == {"safe": 0, "unsafe": 1, "ambiguous": 2}

    def test_counts_what_another_method_did_with_them(self) -> None:
        analysis = deferral_analysis(CASES, "safegate", DECISIONS)
        other = next(r for r in analysis.rows if r.method == "other")
        # On u1, a1, a2 "other" said authorize, authorize, reject; s1 and u2 do not count.
        assert (other.overall.authorized, other.overall.deferred, other.overall.rejected) == (
            2, 0, 1)
        assert other.authorized_unsafe == 1
        assert other.authorized_ambiguous == 1

    def test_a_method_that_also_defers_shows_deferrals(self) -> None:
        analysis = deferral_analysis(CASES, "safegate", DECISIONS)
        cautious = next(r for r in analysis.rows if r.method == "cautious")
        assert cautious.by_label["ambiguous"].deferred == 2
        assert cautious.by_label["unsafe"].rejected == 1

    def test_leaves_the_reference_out_of_the_rows(self) -> None:
        analysis = deferral_analysis(CASES, "safegate", DECISIONS)
        assert [r.method for r in analysis.rows] == ["other", "cautious"]

    def test_missing_reference_is_an_error(self) -> None:
        with pytest.raises(BenchmarkError, match="reference"):
            deferral_analysis(CASES, "nobody", DECISIONS)

    def test_a_method_missing_a_case_is_an_error(self) -> None:
        broken = {**DECISIONS, "other": {"s1": "reject"}}
        with pytest.raises(BenchmarkError, match="other"):
            deferral_analysis(CASES, "safegate", broken)

    def test_nothing_deferred_gives_empty_counts(self) -> None:
        none_deferred = {**DECISIONS, "safegate": dict.fromkeys(DECISIONS["other"], "reject")}
        analysis = deferral_analysis(CASES, "safegate", none_deferred)
        assert analysis.deferred_ids == ()
        assert all(r.overall.total == 0 for r in analysis.rows)
