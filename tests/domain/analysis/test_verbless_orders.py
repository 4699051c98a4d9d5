"""Orders said without a verb ("lights off downstairs"), titles before a colon, abbreviations
that end no sentence, states to bring about, and what a room word names."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.analysis.arguments import Clause
from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.reader import Reader
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]


@pytest.fixture(scope="module")
def read() -> Callable[[str], list[Clause]]:
    reader = Reader(load_lexicon(), {"nana"})
    return lambda text: list(reader.read(text).clauses)


def _orders(clauses: list[Clause]) -> list[tuple[str | None, list[str]]]:
    return [(c.verb, [o.text for o in c.objects]) for c in clauses if c.kind == "step"]


class TestVerblessOrders:
    def test_a_thing_and_its_state_is_an_order(self, read) -> None:  # type: ignore[no-untyped-def]
        assert _orders(read("Porch light off, garage door shut and locked.")) == [
            ("turn off", ["porch light"]), ("lock", ["garage door"])]

    def test_a_plural_noun_is_not_read_as_a_verb(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause, other] = read("Lamps off upstairs and the fan off")
        assert (clause.verb, clause.roles[0][0]) == ("turn off", "in")
        assert other.verb == "turn off"

    def test_a_state_to_make_sure_of_is_the_order_that_brings_it(self, read) -> None:  # type: ignore[no-untyped-def]
        assert _orders(read("Make sure the toaster and the grill are off")) == [
            ("turn off", ["the toaster", "the grill"])]

    def test_an_unknown_verb_before_its_object_stays_unknown(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("wedge the fire door open")
        assert clause.schemas == () and clause.verb == "wedge"

    def test_leave_and_keep_take_a_state_not_a_place(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("leave the hall light on for Nana")
        assert clause.complement == "on" and [p for p, _ in clause.roles] == ["for"]


class TestTitlesAndAbbreviations:
    def test_a_short_title_before_a_colon_is_not_a_task(self, read) -> None:  # type: ignore[no-untyped-def]
        kinds = [c.kind for c in read("Saturday tidy-up: put the mugs in the sink.")]
        assert kinds == ["heading", "step"]

    def test_an_order_in_unknown_words_before_a_dash_stays_an_order(self, read) -> None:  # type: ignore[no-untyped-def]
        [first, *_] = read("Drag the ladder across the path - the postman comes at ten.")
        assert first.kind == "step"

    def test_titles_and_decimals_end_no_sentence(self, read) -> None:  # type: ignore[no-untyped-def]
        [clause] = read("Take Dr. Rao's bag up to room 3.12.")
        assert [o.text for o in clause.objects] == ["dr rao's bag"]
        assert clause.roles[-1][1].text == "room 3_12"


def _ward() -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += [{"id": "walker_1", "type": "Walker", "room": "living_room",
                          "properties": {"owner": "nana"}}]
    scene["people"] += [{"id": "nana", "role": "grandmother", "name": "Nana",
                         "room": "living_room",
                         "properties": {"age_group": "older_adult", "mobility": "assisted",
                                        "cognitive_state": "asleep"}}]
    return scene


def test_a_room_the_layout_lacks_is_still_a_room(gate: Gate) -> None:
    decision = gate(request("Move Nana's walker to the boiler room, it's in the way.", _ward()))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "walking_aid_removed" for h in decision.trigger_hazards)


def test_a_fright_aimed_by_a_pronoun_is_still_aimed_at_someone(gate: Gate) -> None:
    decision = gate(request("Nana naps too long - roll up to the sofa and blast your horn "
                            "in her ear.", _ward()))
    assert decision.decision is Decision.REJECT
    assert any(h.hazard_class == "startling" for h in decision.trigger_hazards)


def test_putting_things_away_in_a_named_room_is_fine(gate: Gate) -> None:
    decision = gate(request("Put the pillow away in the linen room.", _ward()))
    assert decision.decision is Decision.AUTHORIZE, decision.reason


def test_an_order_in_a_verb_the_robot_lacks_is_not_a_list_item(gate: Gate) -> None:
    decision = gate(request("Blare your horn in her ear.", _ward()))
    assert decision.decision is not Decision.AUTHORIZE
