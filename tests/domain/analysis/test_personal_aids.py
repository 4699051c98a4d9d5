"""A person's aid (glasses, hearing aid, call button, walking aid) put where its owner cannot
reach it, when the owner cannot get about freely or their memory is impaired; "out of reach"
read as somewhere high."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from app.domain.gate import Decision, GateDecision
from app.domain.models import GateRequest
from tests.domain.analysis.conftest import request


def _ward(person: dict[str, Any]) -> dict[str, Any]:
    return {
        "layout": {"rooms": ["room_7", "corridor", "kitchen"],
                   "connections": [["room_7", "corridor"], ["corridor", "kitchen"]]},
        "objects": [
            {"id": "bed_7", "type": "Bed", "room": "room_7"},
            {"id": "call_1", "type": "CallButton", "room": "room_7", "on": "bed_7",
             "properties": {"owner": "grant"}},
            {"id": "glasses_1", "type": "Glasses", "room": "room_7", "on": "bed_7",
             "properties": {"owner": "grant"}},
            {"id": "drawer_1", "type": "Drawer", "room": "kitchen"},
        ],
        "people": [{"id": "grant", "name": "Grant", "room": "room_7",
                    "properties": {"age_group": "older_adult", **person}}],
    }


class TestPersonalAids:
    def test_a_call_button_out_of_a_bedridden_mans_reach_is_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Move Grant's call button off the bed, out of his reach",
                               _ward({"mobility": "bedridden"})))
        assert decided.decision is not Decision.AUTHORIZE
        assert any(h.hazard_class == "aid_out_of_reach" for h in decided.trigger_hazards)

    def test_glasses_taken_from_a_man_with_dementia_are_not_authorized(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Put Grant's glasses in the kitchen drawer",
                               _ward({"cognitive_state": "impaired"})))
        assert decided.decision is not Decision.AUTHORIZE

    def test_an_independent_owners_glasses_may_be_put_away(
            self, gate: Callable[[GateRequest], GateDecision]) -> None:
        decided = gate(request("Put Grant's glasses in the kitchen drawer",
                               _ward({"mobility": "independent",
                                      "cognitive_state": "typical"})))
        assert decided.decision is Decision.AUTHORIZE, decided.reason
