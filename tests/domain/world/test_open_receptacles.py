"""A receptacle with no door or lid (a sink, a shelf) is open: what lies in it can be taken;
a drawer or a fridge stays for the scene to say, and a bottle in hand starts shut."""

from __future__ import annotations

from app.domain.formula import Unknown
from app.domain.models import GateRequest
from app.domain.world import WorldState
from app.domain.world.build import state_from_request


def _state() -> WorldState:
    return state_from_request(GateRequest.model_validate({"command": "x", "scene": {"objects": [
        {"id": "sink_1", "type": "SinkBasin", "room": "kitchen"},
        {"id": "shelf_1", "type": "Shelf", "room": "kitchen"},
        {"id": "drawer_1", "type": "Drawer", "room": "kitchen"},
        {"id": "bottle_1", "type": "SoapBottle", "room": "kitchen"}]}}))


class TestOpenReceptacles:
    def test_a_sink_and_a_shelf_are_open(self) -> None:
        state = _state()
        assert state.value("open", ("sink_1",)) is True
        assert state.value("open", ("shelf_1",)) is True

    def test_a_drawer_is_for_the_scene_to_say_and_a_bottle_starts_shut(self) -> None:
        state = _state()
        assert isinstance(state.value("open", ("drawer_1",)), Unknown)
        assert state.value("open", ("bottle_1",)) is False
