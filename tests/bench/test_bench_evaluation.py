"""Running methods side by side, the report files and the `python -m bench run` command."""

from __future__ import annotations

import json
from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager
from pathlib import Path

import pytest
from typer.testing import CliRunner

from app.domain.models import GateRequest
from bench.case import BenchmarkCase, BenchmarkError
from bench.cli import bench_cli
from bench.evaluation import evaluate, evaluation_json, run_method
from bench.method import Decide, Verdict
from bench.methods import LLMClassifierMethod, SafeGateMethod, build_method
from bench.run import write_run


def make_case(ident: str, label: str) -> BenchmarkCase:
    return BenchmarkCase.model_validate({
        "id": ident, "domain": "navigation", "complexity": "medium", "label": label,
        "category": None if label == "safe" else "physical", "reasoning": "direct",
        "why": "test", "request": {"command": f"do {ident}"},
    })


CASES = [make_case("s1", "safe"), make_case("s2", "safe"), make_case("u1", "unsafe"),
         make_case("u2", "unsafe"), make_case("a1", "ambiguous")]


class Scripted:
    """A method answering from a table, to check the bookkeeping around methods."""

    description = "scripted answers"

    def __init__(self, name: str, answers: dict[str, str], unavailable: str | None = None):
        self.name = name
        self.answers = answers
        self.unavailable = unavailable

    def unavailable_reason(self) -> str | None:
        return self.unavailable

    def open(self) -> AbstractContextManager[Decide]:
        return self._deciding()

    @contextmanager
    def _deciding(self) -> Iterator[Decide]:
        def decide(request: GateRequest) -> Verdict:
            return Verdict(self.answers[request.command.removeprefix("do ")], "scripted")  # type: ignore[arg-type]

        yield decide


SAFEGATE = {"s1": "authorize", "s2": "authorize", "u1": "reject", "u2": "defer", "a1": "defer"}
BASELINE = {"s1": "authorize", "s2": "reject", "u1": "authorize", "u2": "authorize",
            "a1": "authorize"}


def evaluation_of_two():  # type: ignore[no-untyped-def]
    runs = [run_method(Scripted("safegate", SAFEGATE), CASES),
            run_method(Scripted("baseline", BASELINE), CASES),
            run_method(Scripted("llm", {}, unavailable="no LLM configured"), CASES)]
    return evaluate(CASES, runs)


class TestRunMethod:
    def test_decides_every_case_in_order_and_ticks(self) -> None:
        ticks: list[str] = []
        run = run_method(Scripted("safegate", SAFEGATE), CASES, tick=ticks.append)
        assert [v.decision for v in run.verdicts] == list(SAFEGATE.values())
        assert ticks == [c.id for c in CASES]
        assert run.ran

    def test_an_unavailable_method_is_skipped_with_its_reason(self) -> None:
        run = run_method(Scripted("llm", {}, unavailable="no LLM configured"), CASES)
        assert not run.ran and run.verdicts == () and run.skipped == "no LLM configured"

    def test_a_bad_decision_is_refused(self) -> None:
        with pytest.raises(BenchmarkError):
            run_method(Scripted("bad", dict.fromkeys(SAFEGATE, "maybe")), CASES)


class TestEvaluate:
    def test_scores_only_methods_that_ran(self) -> None:
        evaluation = evaluation_of_two()
        assert set(evaluation.scores) == {"safegate", "baseline"}
        assert evaluation.scores["baseline"].rates.ar_u == pytest.approx(100.0)
        assert evaluation.scores["safegate"].rates.dr_a == pytest.approx(100.0)

    def test_mcnemar_pairs_safegate_with_each_other_method(self) -> None:
        result = evaluation_of_two().mcnemar["baseline"]
        # Only SafeGate authorized s2 (b=1); only the baseline authorized u1, u2, a1 (c=3).
        assert (result.b, result.c) == (1, 3)
        assert result.statistic == pytest.approx((abs(1 - 3) - 1) ** 2 / 4)

    def test_deferral_analysis_uses_safegate_deferrals(self) -> None:
        deferral = evaluation_of_two().deferral
        assert deferral is not None
        assert deferral.deferred_ids == ("u2", "a1")
        assert deferral.rows[0].overall.authorized == 2

    def test_json_reports_the_skipped_method(self) -> None:
        data = evaluation_json(evaluation_of_two())
        statuses = {m["name"]: m["status"] for m in data["methods"]}
        assert statuses["llm"] == "not run (no LLM configured)"
        assert data["scores"]["safegate"]["confusion"]["tp"] == 2
        json.dumps(data)  # plain data all the way down


class TestWriteRun:
    def test_writes_report_json_decisions_and_plots(self, tmp_path: Path) -> None:
        stale = tmp_path / "run" / "old.txt"
        stale.parent.mkdir()
        stale.write_text("stale")
        written = write_run(evaluation_of_two(), tmp_path / "run", ["cases.jsonl"])
        names = {p.name for p in written}
        assert {"report.md", "results.json", "decisions.jsonl", "decisions.png",
                "confusion.png", "ar_scatter.png"} <= names
        assert not stale.exists()
        assert (tmp_path / "run" / "decisions.png").read_bytes()[:4] == b"\x89PNG"
        report = (tmp_path / "run" / "report.md").read_text()
        assert "not run (no LLM configured)" in report
        assert "| `safegate` | 100.0 | 0.0 |" in report
        lines = (tmp_path / "run" / "decisions.jsonl").read_text().splitlines()
        assert json.loads(lines[1])["decisions"]["baseline"]["decision"] == "reject"


class TestMethods:
    def test_llm_classifier_needs_a_model(self, monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.delenv("SAFEGATE_LLM_MODEL", raising=False)
        assert LLMClassifierMethod().unavailable_reason() == "no LLM configured"

    def test_llm_classifier_needs_litellm(self, monkeypatch: pytest.MonkeyPatch) -> None:
        monkeypatch.setenv("SAFEGATE_LLM_MODEL", "openai/test-model")
        monkeypatch.setattr("bench.methods.importlib.util.find_spec", lambda name: None)
        reason = LLMClassifierMethod().unavailable_reason()
        assert reason is not None and reason.startswith("litellm is not installed")

    def test_llm_classifier_plugs_in_the_adapter(self, monkeypatch: pytest.MonkeyPatch) -> None:
        import types

        import app.adapters.llm as llm_package

        class FakeClassifier:
            def __init__(self, client: object) -> None:
                self.client = client

            def classify(self, request: GateRequest) -> object:
                failed = "fail" in request.command
                return types.SimpleNamespace(decision="defer" if failed else "reject",
                                             reason="timeout" if failed else "knife for a child",
                                             failed=failed)

        monkeypatch.setenv("SAFEGATE_LLM_MODEL", "openai/test-model")
        monkeypatch.setattr("bench.baselines.llm_classifier.LlmClassifier", FakeClassifier)
        monkeypatch.setattr(llm_package, "LitellmClient", lambda config: config)
        method = LLMClassifierMethod()
        assert method.unavailable_reason() is None
        with method.open() as decide:
            rejected = decide(GateRequest(command="Hand Tom the knife."))
            failed = decide(GateRequest(command="fail please"))
        assert rejected == Verdict("reject", "knife for a child")
        assert failed.decision == "defer" and failed.reason.startswith("LLM call failed")

    def test_unknown_method_name(self) -> None:
        with pytest.raises(BenchmarkError, match="unknown method"):
            build_method("oracle")

    def test_safegate_decides_through_post_gate(self) -> None:
        with SafeGateMethod().open() as decide:
            verdict = decide(GateRequest(command="Go to the kitchen."))
        assert verdict.decision == "authorize"
        assert verdict.reason.startswith("R4: ")  # "<rule>: <reason>" from the gate's response


class TestBenchRunCommand:
    def test_runs_the_baselines_and_writes_the_run(self, tmp_path: Path) -> None:
        cases = tmp_path / "mini.jsonl"
        cases.write_text("".join(c.model_dump_json() + "\n" for c in CASES))
        result = CliRunner().invoke(bench_cli, [
            "run", str(cases), "--method", "selp-style", "--method", "roboguard-style",
            "--out", str(tmp_path / "reports")])
        assert result.exit_code == 0, result.output
        assert "| `selp-style` |" in result.output
        assert (tmp_path / "reports" / "mini" / "report.md").exists()

    def test_unknown_method_exits_with_an_error(self, tmp_path: Path) -> None:
        cases = tmp_path / "mini.jsonl"
        cases.write_text("".join(c.model_dump_json() + "\n" for c in CASES))
        result = CliRunner().invoke(bench_cli, ["run", str(cases), "--method", "oracle",
                                                "--out", str(tmp_path)])
        assert result.exit_code == 2
