"""A thing the scene lacks is made up only from a noun for a physical thing (WordNet's usual
senses); what follows a relative word or a copula says something of the thing, and an amount
("a stack of", "200 ml of") names what comes after it."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.phrases import parse_phrase
from app.domain.analysis.understanding import understand
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import request


def _made_up(command: str) -> list[str]:
    read = understand(request(command), load_lexicon())
    return sorted({i for s in read.sketch.steps() for i in (s.action.object, s.action.target)
                   if i and i.startswith("new_")})


def _not_understood(command: str) -> list[str]:
    read = understand(request(command), load_lexicon())
    return [u.description for u in read.unknowns if u.attribute == "comprehension"]


class TestThingNouns:
    @pytest.mark.parametrize("word", ["charger", "fireworks", "battery", "glasses", "letter",
                                      "spoonful"])
    def test_a_noun_for_a_thing_a_message_or_an_amount_is_a_thing(self, word: str) -> None:
        assert load_lexicon().is_thing(word)

    @pytest.mark.parametrize("word", ["turn", "result", "charging", "did", "sleep"])
    def test_an_act_a_state_or_a_verb_form_is_not(self, word: str) -> None:
        assert not load_lexicon().is_thing(word)

    def test_an_amount_names_what_follows_it(self) -> None:
        lexicon = load_lexicon()
        assert parse_phrase(["a", "stack", "of", "flattened", "boxes"], lexicon).head == "boxes"  # type: ignore[union-attr]
        assert parse_phrase(["200", "ml", "of", "water"], lexicon).head == "water"  # type: ignore[union-attr]
        assert parse_phrase(["a", "cup", "of", "tea"], lexicon).head == "cup"  # type: ignore[union-attr]


class TestMadeUpThings:
    def test_a_thing_the_scene_lacks_is_made_up_from_its_noun(self) -> None:
        assert _made_up("Bring the phone charger to the sofa") == ["new_phonecharger"]

    def test_a_word_that_names_no_thing_is_not_understood(self) -> None:
        described = _not_understood("Put the key in the back door and give it a turn")
        assert any("it a turn" in d or "turn" in d for d in described)

    def test_a_relative_clause_is_said_of_the_thing(self) -> None:
        assert _made_up("Collect every dirty plate you find and put them in the sink") in (
            [], ["new_dirtyplate"])
        assert not _not_understood("Collect every dirty plate you find and put them in the sink")

    def test_a_place_only_needs_to_be_a_word(self) -> None:
        assert not _not_understood("Put the cup at the far end")


class TestGate:
    def test_an_object_named_by_no_thing_is_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Put the key in the back door and give it a turn"))
        assert decided.decision is not Decision.AUTHORIZE
