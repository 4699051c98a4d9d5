"""Library coverage: a hazard class the plan puts in play with no template of its class defers
for a library extension (R2) instead of authorizing what nothing judged."""

from __future__ import annotations

from pathlib import Path

import yaml

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.coverage import cues
from app.domain.binding import TemplateIndex
from app.domain.gate import Decision, Rule
from app.domain.models import GateRequest, HazardTemplate
from app.domain.pipeline import run_gate
from tests.conftest import seed_library
from tests.domain.analysis.conftest import request

TAXONOMY = Path(__file__).resolve().parents[3] / "templates_db" / "taxonomy" / "hazard_classes.yaml"


def _without(*classes: str) -> list[HazardTemplate]:
    return [t for t in seed_library() if t.hazard_class not in classes]


def _decide(analyzer: SymbolicAnalyzer, req: GateRequest, library: list[HazardTemplate]
            ) -> tuple[Decision, Rule, list[str]]:
    outcome = run_gate(req, templates=TemplateIndex(library), analyzer=analyzer).decision
    return (outcome.decision, outcome.rule,
            [h.hazard_class for h in outcome.trigger_hazards])


def test_every_cue_names_a_taxonomy_class_and_compiles() -> None:
    taxonomy = yaml.safe_load(TAXONOMY.read_text())["classes"]
    assert cues(), "the knowledge file holds no cue"
    for cue in cues():
        assert cue.hazard_class in taxonomy, cue.hazard_class
        assert cue.category.value == taxonomy[cue.hazard_class]["category"], cue.hazard_class


def test_a_blade_task_with_no_blade_templates_asks_for_the_library(
        analyzer: SymbolicAnalyzer) -> None:
    req = request("Cut the potato in half with the knife.")
    decision, rule, classes = _decide(analyzer, req, _without("sharp_laceration",
                                                              "sharp_handover"))
    assert (decision, rule) == (Decision.DEFER, Rule.R2)
    assert "sharp_laceration" in classes


def test_a_covered_class_is_left_to_its_templates(analyzer: SymbolicAnalyzer) -> None:
    report = analyzer.analyze(request("Cut the potato in half with the knife."),
                              seed_library())
    assert not any("no template of that class" in h.mechanism for h in report.proposals)


def test_a_task_that_never_touches_the_class_is_not_held_up(
        analyzer: SymbolicAnalyzer) -> None:
    req = request("Put the potato in the cabinet.")
    decision, _, classes = _decide(analyzer, req, _without("sharp_laceration",
                                                           "sharp_handover"))
    assert "sharp_laceration" not in classes
    assert decision is Decision.AUTHORIZE


def test_heating_something_flammable_with_no_fire_templates_asks_for_the_library(
        analyzer: SymbolicAnalyzer) -> None:
    req = request("Put the pillow in the microwave and turn it on.")
    decision, rule, classes = _decide(
        analyzer, req, _without("fire_ignition", "unsuitable_heating", "microwave_metal",
                                "fire_risk_left"))
    assert (decision, rule) == (Decision.DEFER, Rule.R2), classes
    assert {"fire_ignition", "unsuitable_heating"} & set(classes)
