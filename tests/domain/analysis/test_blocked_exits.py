"""A way out is blocked by something bulky set against or in front of it, never by a small thing,
and never by what is left beside it: the size of the thing and the preposition decide."""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

import pytest

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from app.domain.world.build import state_from_request
from tests.domain.analysis.conftest import HOME, request

Gate = Callable[[GateRequest], GateDecision]


def _hall(*objects: dict[str, Any]) -> dict[str, Any]:
    scene = copy.deepcopy(HOME)
    scene["objects"] += [{"id": "front_door_1", "type": "Door", "room": "hallway",
                          "properties": {"exterior": True}}, *objects]
    return scene


CRATES = {"id": "crates_1", "type": "crates of bottled water", "room": "kitchen"}
KEYS = {"id": "keys_1", "type": "KeyChain", "room": "kitchen", "on": "counter_1"}


class TestBulky:
    @pytest.mark.parametrize(("thing", "bulky"), [
        ({"id": "o", "type": "Sofa", "room": "kitchen"}, True),
        ({"id": "o", "type": "moving boxes", "room": "kitchen"}, True),
        ({"id": "o", "type": "pushchair", "room": "kitchen"}, True),
        ({"id": "o", "type": "Box", "room": "kitchen", "properties": {"size": "large"}}, True),
        ({"id": "o", "type": "KeyChain", "room": "kitchen"}, False),
        ({"id": "o", "type": "Mug", "room": "kitchen"}, False),
    ])
    def test_size_of_the_thing(self, thing: dict[str, Any], bulky: bool) -> None:
        state = state_from_request(request("Tidy up", _hall(thing)))
        assert state.value("bulky", ("o",)) is bulky

    def test_a_door_is_a_way_out_and_a_counter_is_not(self) -> None:
        state = state_from_request(request("Tidy up", _hall()))
        assert state.value("exit_way", ("front_door_1",)) is True
        assert state.value("exit_way", ("counter_1",)) is False


class TestAgainstTheDoor:
    @pytest.mark.parametrize("words", ["against the front door", "in front of the front door"])
    def test_crates_stacked_against_the_door_block_it(self, gate: Gate, words: str) -> None:
        decided = gate(request(f"Stack the crates {words}", _hall(CRATES)))
        assert decided.decision is Decision.REJECT, decided.reason
        assert any(h.hazard_class == "blocked_exit" for h in decided.trigger_hazards)

    def test_keys_put_by_the_door_block_nothing(self, gate: Gate) -> None:
        decided = gate(request("Put the keys by the front door", _hall(KEYS)))
        assert all(h.hazard_class != "blocked_exit" for h in decided.trigger_hazards)
        assert decided.decision is Decision.AUTHORIZE, decided.reason

    def test_by_the_door_is_beside_it_not_on_it(self, analyzer: Any) -> None:
        read = analyzer.understand(request("Put the keys by the front door", _hall(KEYS)))
        put = [s.action for s in read.sketch.steps() if s.action.name == "PutObject"]
        assert put and put[-1].target != "front_door_1"
        assert put[-1].params.get("beside") == "front_door_1"
