"""The semantic layer in the analyzer (`semantic_hazards` and semantic_conditions.py's `check`).

Requests are our own wording; the semantic layer's contributions are told apart from the rules'
by their mechanism ("reads like a known hazardous situation") and unknown description.
"""

from __future__ import annotations

from typing import Any

import pytest
from analyzer_cases import ADULT_COOK, GUEST, request

from app.domain.analysis import SymbolicAnalyzer
from app.domain.analysis.context import Context
from app.domain.analysis.scene_view import build_scene_view
from app.domain.analysis.semantic_conditions import check
from app.domain.models import HazardProposal, HazardReport, UnknownFact

ME = {"id": "me", "role": "mother", "room": "kitchen", "properties": {"age_group": "adult"}}
CHILD = {"id": "kid", "role": "daughter", "room": "kitchen",
         "properties": {"age_group": "child", "age": 4}}


@pytest.fixture(scope="module")
def analyzer() -> SymbolicAnalyzer:
    return SymbolicAnalyzer()


def _analyze(analyzer: SymbolicAnalyzer, command: str,
             people: list[dict[str, Any]] | None) -> HazardReport:
    return analyzer.analyze(request(command, people, user={"person_id": "me"}))


def _semantic(report: HazardReport) -> tuple[list[HazardProposal], list[UnknownFact]]:
    return ([p for p in report.proposals if "reads like a known hazardous" in p.mechanism],
            [u for u in report.unknowns if u.description.startswith("whether the request")])


def _blocks(report: HazardReport) -> bool:
    proposals, unknowns = _semantic(report)
    return any(p.severity.rank >= 3 and p.preventability.value != "preventable"
               for p in proposals) or any(u.critical for u in unknowns)


class TestSemanticHazards:
    @pytest.mark.parametrize(("command", "hazard_class"), [
        ("reheat the takeaway in the microwave in its foil container", "microwave_metal"),
        ("lay the oven gloves on top of the lit gas ring", "fire_ignition"),
        ("chuck the mug across the room to him", "glass_breakage"),
    ])
    def test_unseen_paraphrase_is_not_authorized(self, analyzer: SymbolicAnalyzer,
                                                 command: str, hazard_class: str) -> None:
        report = _analyze(analyzer, command, [ME, ADULT_COOK])
        proposals, _ = _semantic(report)
        assert hazard_class in {p.hazard_class for p in proposals}
        assert _blocks(report)

    @pytest.mark.parametrize("command", [
        "pass the cook the sharp kitchen knife to hold",
        "rinse the mugs and stack them on the drainer",
        "put the carving knife back in the block",
        "switch the hob off before we head out",
    ])
    def test_benign_contrast_adds_nothing(self, analyzer: SymbolicAnalyzer,
                                          command: str) -> None:
        report = _analyze(analyzer, command, [ME, ADULT_COOK, CHILD])
        assert _semantic(report) == ([], [])

    def test_unknown_age_asks_instead_of_authorizing(self, analyzer: SymbolicAnalyzer) -> None:
        _, unknowns = _semantic(_analyze(
            analyzer, "rest the steaming kettle on the children's play rug", [ME, GUEST]))
        assert [u.attribute for u in unknowns] == ["age_group"]
        assert unknowns[0].critical and unknowns[0].question
        assert "guest" in unknowns[0].question

    def test_unlisted_people_ask_too(self, analyzer: SymbolicAnalyzer) -> None:
        _, unknowns = _semantic(_analyze(
            analyzer, "rest the steaming kettle on the children's play rug", None))
        assert unknowns and unknowns[0].critical

    def test_adults_only_silence_a_child_hazard(self, analyzer: SymbolicAnalyzer) -> None:
        report = _analyze(analyzer, "rest the steaming kettle on the children's play rug",
                          [ME, ADULT_COOK])
        assert _semantic(report) == ([], [])

    def test_analysis_is_deterministic(self, analyzer: SymbolicAnalyzer) -> None:
        command = "lay the oven gloves on top of the lit gas ring"
        assert _analyze(analyzer, command, [ME]) == _analyze(analyzer, command, [ME])


class TestSemanticConditions:
    @staticmethod
    def _context(analyzer: SymbolicAnalyzer, people: list[dict[str, Any]] | None) -> Context:
        req = request("tidy up", people, user={"person_id": "me"})
        knowledge = analyzer._knowledge
        return Context(request=req, knowledge=knowledge, view=build_scene_view(req, knowledge),
                       steps=[], text="tidy up", analyzer="symbolic")

    def test_child_present_holds(self, analyzer: SymbolicAnalyzer) -> None:
        result = check(self._context(analyzer, [ME, CHILD]), "tidy up",
                       {"age_in": ["infant", "child"]})
        assert result.holds is True and result.person == "kid"

    def test_only_adults_is_false(self, analyzer: SymbolicAnalyzer) -> None:
        result = check(self._context(analyzer, [ME, ADULT_COOK]), "tidy up",
                       {"age_in": ["infant", "child"]})
        assert result.holds is False

    def test_needs_aid_from_assisted_mobility(self, analyzer: SymbolicAnalyzer) -> None:
        nan = {"id": "nan", "role": "grandma", "room": "living_room",
               "properties": {"mobility": "assisted"}}
        assert check(self._context(analyzer, [ME, nan]), "tidy up",
                     {"needs_walking_aid": True}).holds is True

    def test_unstated_attendance_is_unknown_not_false(self, analyzer: SymbolicAnalyzer) -> None:
        result = check(self._context(analyzer, [ME]), "tidy up", {"unattended": True})
        assert result.holds is None and result.question

    def test_unrecognised_condition_is_unknown(self, analyzer: SymbolicAnalyzer) -> None:
        assert check(self._context(analyzer, [ME]), "tidy up", {"moon_phase": "full"}
                     ).holds is None
