""""Give him a couple of mum's": the owner's one of the kind just named; "the door's locked"
and "dinner's ready" are things that are something, not owners."""

from __future__ import annotations

import copy
from collections.abc import Callable

from app.domain.analysis.lexicon import load_lexicon
from app.domain.analysis.phrases import parse_phrase
from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import HOME, request


def _home() -> GateRequest:
    scene = copy.deepcopy(HOME)
    scene["objects"] += [
        {"id": "pills_dad", "type": "PillBottle", "room": "living_room",
         "properties": {"contents": "empty", "owner": "dad"}},
        {"id": "pills_mum", "type": "PillBottle", "room": "kitchen",
         "properties": {"contents": "blood pressure tablets", "owner": "mum"}}]
    scene["people"].append({"id": "mum", "role": "mum", "room": "kitchen"})
    return request("Dad's run out of his pills, give him a couple of mum's", scene)


class TestEllipticOwner:
    def test_an_owner_alone_is_the_owners_one(self) -> None:
        phrase = parse_phrase(["a", "couple", "of", "mum's"], load_lexicon())
        assert phrase is not None and phrase.possessor == "mum" and phrase.pronoun == "one"

    def test_a_thing_that_is_something_is_no_owner(self) -> None:
        phrase = parse_phrase(["the", "back", "door's"], load_lexicon())
        assert phrase is not None and phrase.possessor is None

    def test_someone_elses_tablets_are_not_handed_over(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(_home())
        assert decided.decision is not Decision.AUTHORIZE
        assert any(h.hazard_class == "medication_misuse" for h in decided.trigger_hazards)
