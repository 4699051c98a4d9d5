"""Questions for unknowns, and answers folded back into the request so analysis can re-run."""

from __future__ import annotations

from analyzer_cases import GUEST, gate_outcome, request

from app.domain.analysis import SymbolicAnalyzer, apply_answers, phrase_question, question_for
from app.domain.models import UnknownFact


class TestPhraseQuestion:
    def test_age(self) -> None:
        assert phrase_question("age_group", "the guest in the living room") == (
            "How old is the guest in the living room?")

    def test_contents(self) -> None:
        assert phrase_question("contents", "the cup on the counter") == (
            "What is in the cup on the counter?")

    def test_unlisted_attribute_still_reads_as_a_question(self) -> None:
        assert phrase_question("shoe_size", "grandpa").endswith("?")

    def test_question_for_prefers_the_unknowns_own(self) -> None:
        unknown = UnknownFact(attribute="age_group", description="x", critical=True, why="y",
                              entity="guest", question="How old is Sam?")
        assert question_for(unknown) == "How old is Sam?"


class TestApplyAnswers:
    def test_age_answer_lets_the_task_through(self) -> None:
        analyzer = SymbolicAnalyzer()
        req = request("bring the hot coffee to the guest in the living room", [GUEST])
        first = analyzer.analyze(req)
        assert gate_outcome(first) == "defer"
        answered = apply_answers(req, {"age_group": "adult"}, first.unknowns)
        guest = next(p for p in answered.scene.people if p.id == "guest")  # type: ignore[union-attr]
        assert guest.properties["age_group"] == "adult"
        assert gate_outcome(analyzer.analyze(answered)) == "authorize"

    def test_child_answer_makes_it_unsafe(self) -> None:
        analyzer = SymbolicAnalyzer()
        req = request("bring the hot coffee to the guest in the living room", [GUEST])
        answered = apply_answers(req, {"age_group": "child"}, analyzer.analyze(req).unknowns)
        assert gate_outcome(analyzer.analyze(answered)) == "reject"

    def test_contents_answer_is_written_on_the_object(self) -> None:
        analyzer = SymbolicAnalyzer()
        req = request("give grandpa the cup on the counter",
                      [{"id": "grandpa", "role": "grandpa", "room": "living_room"}])
        answered = apply_answers(req, {"contents": "water"}, analyzer.analyze(req).unknowns)
        cup = next(o for o in answered.scene.objects if o.id == "cup_1")  # type: ignore[union-attr]
        assert cup.properties["contents"] == "water"
        assert not any(u.critical for u in analyzer.analyze(answered).unknowns)

    def test_nobody_present_lists_the_people(self) -> None:
        objects = [{"id": "disposal_1", "type": "garbage disposal", "room": "kitchen"}]
        req = request("turn on the garbage disposal", None, objects=objects)
        analyzer = SymbolicAnalyzer()
        answered = apply_answers(req, {"person_present": False},
                                 analyzer.analyze(req).unknowns)
        assert answered.scene is not None and "people" in answered.scene.model_fields_set
        assert gate_outcome(analyzer.analyze(answered)) == "authorize"

    def test_answer_for_a_person_the_scene_lacked(self) -> None:
        analyzer = SymbolicAnalyzer()
        req = request("give the scissors to my son", scene=False)
        first = analyzer.analyze(req)
        assert gate_outcome(first) == "defer"
        answered = apply_answers(req, {"age_group": "adult"}, first.unknowns)
        assert gate_outcome(analyzer.analyze(answered)) == "authorize"

    def test_original_request_is_unchanged(self) -> None:
        req = request("bring the hot coffee to the guest in the living room", [GUEST])
        unknowns = SymbolicAnalyzer().analyze(req).unknowns
        apply_answers(req, {"age_group": "adult"}, unknowns)
        assert "age_group" not in req.scene.people[0].properties  # type: ignore[union-attr]
