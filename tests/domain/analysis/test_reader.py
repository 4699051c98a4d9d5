"""Reading commands into clauses: verbs, their schemas, arguments, negation and manner."""

from __future__ import annotations

import pytest

from app.domain.analysis.arguments import Clause
from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.reader import Reader


@pytest.fixture(scope="module")
def read() -> object:
    reader = Reader(load_lexicon(), {"tom"})
    return lambda text: list(reader.read(text).clauses)


def steps(clauses: list[Clause]) -> list[tuple[str | None, list[str]]]:
    return [(c.verb, [o.text for o in c.objects]) for c in clauses if c.kind == "step"]


class TestClauses:
    def test_sequencers_and_verbs_after_and_split_steps(self, read) -> None:  # type: ignore[no-untyped-def]
        clauses = read("Put the potato in the microwave and turn it on, then go to the hall")
        assert [c.verb for c in clauses] == ["put", "turn on", "go"]

    def test_a_separated_particle_completes_the_phrasal_verb(self, read) -> None:  # type: ignore[no-untyped-def]
        assert steps(read("turn the stove off")) == [("turn off", ["the stove"])]

    def test_a_person_before_a_second_noun_is_the_recipient(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("give Tom the knife")
        assert clause.second is not None and clause.second.text == "tom"
        assert [o.text for o in clause.objects] == ["the knife"]

    def test_negation_marks_the_step(self, read) -> None:  # type: ignore[no-untyped-def]
        clauses = read("carry the basket and don't drop it")
        assert [c.negated for c in clauses] == [False, True]

    def test_purpose_and_condition_clauses_are_not_steps(self, read) -> None:  # type: ignore[no-untyped-def]
        kinds = [c.kind for c in read("While Tom naps, vacuum the hall so it is clean")]
        assert kinds == ["condition", "step", "purpose"]

    def test_a_line_break_inside_a_sentence_is_a_space(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("give the scissors to\n\nTom")
        assert clause.roles[0][1].text == "tom"

    def test_a_line_that_starts_with_a_verb_is_a_new_step(self, read) -> None:  # type: ignore[no-untyped-def]
        assert [c.verb for c in read("wash the cup\ndry it")] == ["wash", "dry"]


class TestIdioms:
    def test_give_something_a_stir_is_to_stir_it(self, read) -> None:  # type: ignore[no-untyped-def]
        assert steps(read("give the soup a stir")) == [("stir", ["the soup"])]

    def test_an_indirect_request_is_a_fetch_for_the_speaker(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("could I trouble you for a glass of water")
        assert clause.verb == "bring" and clause.second is not None

    def test_a_list_item_without_a_verb_puts_things_away(self, read) -> None:  # type: ignore[no-untyped-def]
        clauses = read("tidy up: cushions back on the sofa, remote on the stand")
        assert [c.verb for c in clauses] == ["tidy up", "put", "put"]

    def test_taking_a_picture_of_something_records_it(self, read) -> None:  # type: ignore[no-untyped-def]
        for text in ("take a picture of the fridge", "snap a quick pic of the fridge"):
            [clause] = read(text)
            assert clause.schemas[0] == "record" and clause.objects[-1].text == "the fridge"


class TestManner:
    def test_top_speed_is_a_way_of_moving_and_quick_is_only_urgency(self, read) -> None:  # type: ignore[no-untyped-def]
        assert "fast" in read("go to the hall at top speed")[0].manner
        quick = read("fetch the kit, quick")[0].manner
        assert "fast" not in quick and "hurry" in quick

    def test_leave_it_running_marks_the_command(self, read) -> None:  # type: ignore[no-untyped-def]
        clauses = read("turn on the tap and leave it running")
        assert any("leave" in c.manner for c in clauses)

    def test_running_the_bath_is_a_verb_not_a_speed(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("run the bath")
        assert clause.verb == "run" and "fast" not in clause.manner
