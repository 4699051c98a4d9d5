"""Loading benchmark files, scoring decisions and rendering the report."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from rich.console import Console

from app.domain.models import GateRequest
from bench.case import BenchmarkError
from bench.metrics import McNemarResult
from bench.score import load_cases, render_mcnemar, render_report, score, score_files


def line(ident: str, label: str, **extra: Any) -> str:
    record = {"id": ident, "domain": "assistance", "complexity": "medium", "label": label,
              "category": None if label == "safe" else "physical", "reasoning": "direct",
              "why": "because", "request": {"command": f"do {ident}",
                                            "user": {"age_group": "adult"}}}
    record.update(extra)
    return json.dumps(record)


def write(path: Path, *lines: str) -> Path:
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


class TestLoadCases:
    def test_parses_cases_and_their_requests(self, tmp_path: Path) -> None:
        path = write(tmp_path / "b.jsonl", line("a", "safe"), "", line("b", "unsafe"))
        cases = load_cases(path)
        assert [c.id for c in cases] == ["a", "b"]
        assert isinstance(cases[0].request, GateRequest)
        assert cases[0].request.user is not None
        assert cases[0].request.user.age_group == "adult"

    def test_ignores_extra_keys(self, tmp_path: Path) -> None:
        path = write(tmp_path / "b.jsonl", line("a", "safe", steps=3, source="elsewhere"))
        assert load_cases(path)[0].id == "a"

    def test_malformed_json_names_file_and_line(self, tmp_path: Path) -> None:
        path = write(tmp_path / "bad.jsonl", line("a", "safe"), "{not json")
        with pytest.raises(BenchmarkError, match=r"bad\.jsonl:2: not valid JSON"):
            load_cases(path)

    def test_invalid_label_names_file_and_line(self, tmp_path: Path) -> None:
        path = write(tmp_path / "bad.jsonl", line("a", "harmless"))
        with pytest.raises(BenchmarkError, match=r"bad\.jsonl:1: not a benchmark case"):
            load_cases(path)

    def test_invalid_request_is_refused(self, tmp_path: Path) -> None:
        path = write(tmp_path / "bad.jsonl", line("a", "safe", request={"scene": {}}))
        with pytest.raises(BenchmarkError, match="command"):
            load_cases(path)

    def test_repeated_id_is_refused(self, tmp_path: Path) -> None:
        path = write(tmp_path / "dup.jsonl", line("a", "safe"), line("a", "unsafe"))
        with pytest.raises(BenchmarkError, match=r"dup\.jsonl:2: case id 'a'"):
            load_cases(path)


class TestScore:
    def test_scores_a_list_of_decisions(self, tmp_path: Path) -> None:
        cases = load_cases(write(tmp_path / "b.jsonl", line("s", "safe"), line("u", "unsafe"),
                                 line("a", "ambiguous")))
        report = score(cases, ["authorize", "authorize", "defer"])
        assert report.n == 3
        assert report.rates.ar_s == 100.0 and report.rates.ar_u == 100.0
        assert report.unsafe_authorized == ("u",)
        assert report.ambiguous.deferred == 1
        assert report.confusion.fn == 1

    def test_scores_a_mapping_by_case_id(self, tmp_path: Path) -> None:
        cases = load_cases(write(tmp_path / "b.jsonl", line("s", "safe"), line("u", "unsafe")))
        report = score(cases, {"u": "reject", "s": "defer"})
        assert report.safe_blocked == ("s",)
        assert report.unsafe_authorized == ()

    def test_a_missing_decision_is_refused(self, tmp_path: Path) -> None:
        cases = load_cases(write(tmp_path / "b.jsonl", line("s", "safe"), line("u", "unsafe")))
        with pytest.raises(BenchmarkError):
            score(cases, ["authorize"])
        with pytest.raises(BenchmarkError, match="missing"):
            score(cases, {"s": "authorize"})


class TestScoreFiles:
    def test_runs_every_case_through_decide(self, tmp_path: Path) -> None:
        first = write(tmp_path / "one.jsonl", line("s", "safe"), line("u", "unsafe"))
        second = write(tmp_path / "two.jsonl", line("a", "ambiguous"))
        seen: list[str] = []

        def decide(request: GateRequest) -> str:
            seen.append(request.command)
            return "reject" if "u" in request.command else "defer"

        report = score_files([first, second], decide)
        assert seen == ["do s", "do u", "do a"]
        assert report.rates.dr_a == 100.0 and report.rates.ar_u == 0.0
        assert report.confusion.fp == 1

    def test_a_case_id_repeated_across_files_is_refused(self, tmp_path: Path) -> None:
        first = write(tmp_path / "one.jsonl", line("s", "safe"))
        second = write(tmp_path / "two.jsonl", line("s", "unsafe"))
        with pytest.raises(BenchmarkError, match="already loaded"):
            score_files([first, second], lambda _: "reject")


class TestRenderReport:
    def test_prints_the_metrics(self, tmp_path: Path) -> None:
        cases = load_cases(write(tmp_path / "b.jsonl", line("s1", "safe"), line("s2", "safe"),
                                 line("u", "unsafe")))
        report = score(cases, ["authorize", "defer", "authorize"])
        console = Console(record=True, width=140)
        console.print(render_report(report))
        text = console.export_text()
        assert "AR-S%" in text and "DR-A%" in text
        assert "50.0" in text  # AR-S: one of two safe cases authorized
        assert "Unsafe cases authorized: u" in text
        assert "By complexity" in text

    def test_mcnemar_line_names_both_methods(self) -> None:
        text = render_mcnemar("gate", "llm", McNemarResult(n=10, b=6, c=1, statistic=16 / 7,
                                                           p_value=0.1306))
        assert "gate vs llm" in text and "b=6" in text and "p=0.1306" in text
