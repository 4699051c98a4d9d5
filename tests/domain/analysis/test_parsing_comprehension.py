"""The comprehension check: gaps for what cannot be read, no alarms for ordinary phrasing."""

from __future__ import annotations

import pytest

from app.domain.analysis.command import read_command
from app.domain.analysis.knowledge_base import Knowledge, load_knowledge


@pytest.fixture(scope="module")
def knowledge() -> Knowledge:
    return load_knowledge()


class TestGaps:
    def test_unknown_english_verb_on_a_person(self, knowledge: Knowledge) -> None:
        gaps = read_command("Swaddle the baby tightly", knowledge).not_understood
        assert [g.part for g in gaps] == ["verb"] and "swaddle" in gaps[0].phrase

    def test_nonsense_verb(self, knowledge: Knowledge) -> None:
        gaps = read_command("Florp the kettle", knowledge).not_understood
        assert gaps and gaps[0].phrase == "florp" and gaps[0].step == 0

    def test_nonsense_object_of_a_known_verb(self, knowledge: Knowledge) -> None:
        gaps = read_command("Give grandma the zibbleworth", knowledge).not_understood
        assert [g.part for g in gaps] == ["object"] and "zibbleworth" in gaps[0].phrase

    def test_scene_name_is_understood(self, knowledge: Knowledge) -> None:
        parsed = read_command("Give grandma the zibbleworth", knowledge, {"zibbleworth"})
        assert parsed.not_understood == ()


    def test_capitalised_unknown_word_inside_a_sentence_is_a_name(self, knowledge: Knowledge
                                                                  ) -> None:
        assert read_command("Give the scarf to Ottoline", knowledge).not_understood == ()

    def test_capitalised_nonsense_opening_a_sentence_is_still_a_gap(self, knowledge: Knowledge
                                                                    ) -> None:
        assert read_command("Glorb the scissors.", knowledge).not_understood


class TestNoFalseAlarms:
    @pytest.mark.parametrize("command", [
        "Could you bring me a glass of water? I'm parched.",
        "The kettle's boiled - make a pot of tea.",
        "Breakfast: cereal, juice and toast for the kids.",
        "Tidy the lounge, the guests arrive at six.",
        "Take Grandad his paper, he's in the conservatory.",
        "Load the washing machine and put it on a quick wash.",
        "Thanks, that's everything for today.",
        "Hoover the stairs, mop the hall and empty the bins.",
        "Fold the towels and stack them in the airing cupboard.",
        "Switching the lamp off is fine, do it now.",
        "Tidy the shed: rakes back on the hooks, seeds in the tin.",
        "Meet the plumber at the door and show him round.",
    ])
    def test_everyday_commands_have_no_gap(self, knowledge: Knowledge, command: str) -> None:
        assert read_command(command, knowledge).not_understood == ()
