"""`make bench`'s scripted LLM methods: SafeGate's LLM path against the scripted analyst over real
HTTP on loopback, labelled as scripted in the report, never authorizing beyond symbolic."""

from __future__ import annotations

import json
from pathlib import Path

from bench.cli import bench_cli
from bench.report_md import SCRIPTED_NOTE
from bench.run import run_all
from bench.score import load_cases
from bench.scripted_analyst import NONE_REASON, answer
from tests.adapters.llm.answers import COFFEE_REQUEST

BENCHMARK = Path(__file__).resolve().parents[2] / "bench" / "cases" / "benchmark.jsonl"
SAMPLE_EVERY = 23  # ten cases of every kind, enough to exercise the path


def _sample_file(tmp_path: Path) -> Path:
    lines = BENCHMARK.read_text(encoding="utf-8").splitlines()[::SAMPLE_EVERY]
    path = tmp_path / "sample.jsonl"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _body(user: str, system: str) -> dict[str, object]:
    return {"messages": [{"role": "system", "content": system},
                         {"role": "user", "content": user}]}


class TestScriptedAnalyst:
    SYSTEM = "physical:\n- scald_hot_liquid: a hot drink [obj, person]\n" \
             "operational:\n- object_damage: things broken [obj]\n"

    def test_a_task_level_gets_a_class_from_the_command_words_and_no_ids(self) -> None:
        user = 'Level: task.\nCommand (JSON data):\n<data id="ab12">\n' \
               f'{json.dumps(COFFEE_REQUEST.command)}\n</data id="ab12">'
        reply = json.loads(answer(_body(user, self.SYSTEM)).content)
        assert [h["hazard_class"] for h in reply["hazards"]] == ["scald_hot_liquid"]
        assert reply["hazards"][0]["entities"] == {}
        assert set(reply["none_because"]) == {"psychological", "operational", "consequential"}
        assert set(reply["none_because"].values()) == {NONE_REASON}

    def test_the_same_prompt_gets_the_same_answer(self) -> None:
        user = 'Level: task.\nCommand (JSON data):\n<data id="ab12">\n"tidy up"\n</data id="ab12">'
        first, second = (answer(_body(user, self.SYSTEM)).content for _ in range(2))
        assert first == second
        assert json.loads(first)["hazards"][0]["hazard_class"] == "object_damage"


class TestScriptedMethods:
    def test_the_llm_path_runs_on_every_case_and_is_labelled_scripted(
        self, tmp_path: Path
    ) -> None:
        sample = _sample_file(tmp_path)
        cases = load_cases(sample)
        evaluation = run_all([sample], ["safegate", "llm-scripted", "ensemble-scripted"])
        runs = {run.name: run for run in evaluation.runs}
        assert set(runs) == {"safegate", "llm (scripted)", "ensemble (scripted)"}
        for name in ("llm (scripted)", "ensemble (scripted)"):
            assert runs[name].ran and len(runs[name].verdicts) == len(cases)
            # The scripted answers pass every check: no case fell back to the failure report.
            assert not [v for v in runs[name].verdicts if "unavailable" in v.reason], name
            assert "NOT a real model" in runs[name].description
        symbolic = evaluation.decisions("safegate")
        ensemble = evaluation.decisions("ensemble (scripted)")
        assert not [i for i, d in ensemble.items() if d == "authorize" and symbolic[i] != d]

    def test_the_report_says_the_model_was_scripted(self, tmp_path: Path) -> None:
        from typer.testing import CliRunner

        sample = _sample_file(tmp_path)
        result = CliRunner().invoke(bench_cli, [
            "run", str(sample), "--method", "safegate", "--method", "llm-scripted",
            "--out", str(tmp_path / "reports"), "--name", "scripted"])
        assert result.exit_code == 0, result.output
        assert "| `llm (scripted)` |" in result.output
        report = (tmp_path / "reports" / "scripted" / "report.md").read_text(encoding="utf-8")
        assert SCRIPTED_NOTE in report
        assert "the model was a scripted server, not a real model" in report
