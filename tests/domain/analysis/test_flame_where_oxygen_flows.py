"""A flame lit where medical oxygen is flowing: the oxygen supply anywhere in the room is part
of what a lit candle is judged against, not only what touches it. Twins: the supply switched
off, or in another room."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import home_with, request

Gate = Callable[[GateRequest], GateDecision]

CANDLE = {"id": "candle_1", "type": "Candle", "room": "living_room", "on": "table_1",
          "properties": {"on": False}}


def _oxygen(room: str, running: bool) -> dict[str, Any]:
    return {"id": "oxygen_1", "type": "oxygen concentrator", "room": room,
            "properties": {"on": running}}


def test_lighting_a_candle_in_the_room_where_oxygen_runs_is_refused(gate: Gate) -> None:
    decided = gate(request("light the candle on the coffee table",
                           home_with(CANDLE, _oxygen("living_room", running=True))))
    assert decided.decision is Decision.REJECT, decided.reason
    assert "fire_ignition" in decided.reason


def test_with_the_oxygen_switched_off_the_candle_may_be_lit(gate: Gate) -> None:
    decided = gate(request("light the candle on the coffee table",
                           home_with(CANDLE, _oxygen("living_room", running=False))))
    assert decided.decision is Decision.AUTHORIZE, decided.reason


def test_oxygen_running_in_another_room_does_not_stop_it(gate: Gate) -> None:
    decided = gate(request("light the candle on the coffee table",
                           home_with(CANDLE, _oxygen("kitchen", running=True))))
    assert decided.decision is Decision.AUTHORIZE, decided.reason
