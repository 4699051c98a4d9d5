"""The runtime monitor: verdicts per message, the absorbing halt, errors, counts and replay."""

from __future__ import annotations

import json
from datetime import UTC, datetime
from typing import Any

import pytest
from monitor_kit import (
    CHILD_AT_LIVE_STOVE,
    CONTRACT,
    GO_TO_MUG,
    HAND_KNIFE,
    PICK_MUG,
    PICK_PARCEL,
    REQUEST,
    TOGGLE_STOVE,
    after,
    before,
)

from app.domain.models import GateRequest
from app.domain.monitor import (
    CompiledContract,
    Monitor,
    MonitorCounters,
    MonitorViolation,
    replay,
)
from app.domain.world import state_from_request

NOON = datetime(2025, 1, 1, 12, 0, tzinfo=UTC)
HEAVY_MUG = {"scene": {"objects": [{"id": "mug_1", "type": "Mug", "room": "kitchen",
                                    "properties": {"mass_kg": 5.0}}]}}


def new_monitor() -> Monitor:
    return Monitor(CompiledContract(CONTRACT),
                   state_from_request(GateRequest.model_validate(REQUEST)), clock=lambda: NOON)


def run(monitor: Monitor, *messages: Any) -> list[dict[str, Any]]:
    return [monitor.step(message).to_wire() for message in messages]


@pytest.fixture
def monitor() -> Monitor:
    return new_monitor()


class TestAllowedActions:
    def test_a_safe_action_is_allowed_before_and_after(self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, GO_TO_MUG), after(1, GO_TO_MUG))
        assert answers == [{"type": "allow", "seq": 1}, {"type": "allow", "seq": 1}]
        assert not monitor.halted

    def test_the_action_model_predicts_what_the_after_message_leaves_out(
            self, monitor: Monitor) -> None:
        run(monitor, before(1, PICK_MUG), after(1, PICK_MUG))
        assert monitor.state.robot.holding == "mug_1"
        assert monitor.state.value("load_kg", ("robot",)) == pytest.approx(0.3)

    def test_text_and_bytes_messages_are_decoded(self, monitor: Monitor) -> None:
        text = json.dumps(before(1, GO_TO_MUG))
        assert monitor.step(text).allowed
        assert monitor.step(json.dumps(after(1, GO_TO_MUG)).encode()).allowed


class TestViolations:
    def test_a_guard_that_fails_before_its_action_halts(self, monitor: Monitor) -> None:
        verdict = monitor.step(before(1, TOGGLE_STOVE))
        assert verdict.type == "violation" and verdict.halted
        assert verdict.violation is not None
        wire = verdict.to_wire()["violation"]
        assert wire["kind"] == "guard"
        assert wire["condition_id"] == "skill.toggle"
        assert wire["formula"] == 'has_skill(robot, "toggle")'
        assert wire["action"] == {"action": "ToggleObjectOn", "object": "stove_1"}
        assert wire["timestamp"] == "2025-01-01T12:00:00Z"
        assert wire["established"] is True
        assert monitor.halted

    def test_a_guard_sees_the_action_arguments(self, monitor: Monitor) -> None:
        verdict = monitor.step(before(1, HAND_KNIFE))
        assert verdict.violation is not None
        assert verdict.violation.condition_id == "sharp.no_knife_handover"

    def test_an_abort_observed_after_an_action_halts(self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, GO_TO_MUG), after(1, GO_TO_MUG, CHILD_AT_LIVE_STOVE))
        assert answers[1]["type"] == "violation"
        assert answers[1]["violation"]["kind"] == "abort"
        assert answers[1]["violation"]["phase"] == "after"

    def test_an_abort_observed_before_an_action_halts(self, monitor: Monitor) -> None:
        verdict = monitor.step(before(1, GO_TO_MUG, CHILD_AT_LIVE_STOVE))
        assert verdict.violation is not None and verdict.violation.kind == "abort"

    def test_a_broken_invariant_halts_after_the_action(self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, PICK_MUG), after(1, PICK_MUG, HEAVY_MUG))
        assert answers[0]["type"] == "allow"
        violation = answers[1]["violation"]
        assert (violation["kind"], violation["condition_id"]) == ("invariant",
                                                                  "payload.within_limit")

    def test_an_invariant_the_state_cannot_decide_halts_and_says_so(
            self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, PICK_PARCEL), after(1, PICK_PARCEL))
        violation = answers[1]["violation"]
        assert violation["established"] is False
        assert violation["unknown_facts"] == ["mass_kg(parcel_1)"]
        assert "could not be established" in violation["description"]

    def test_reporting_the_missing_fact_lets_the_same_action_pass(
            self, monitor: Monitor) -> None:
        known = {"scene": {"objects": [{"id": "parcel_1", "type": "Gizmo", "room": "kitchen",
                                        "properties": {"mass_kg": 1.0}}]}}
        answers = run(monitor, before(1, PICK_PARCEL), after(1, PICK_PARCEL, known))
        assert [a["type"] for a in answers] == ["allow", "allow"]


class TestAbsorbingHalt:
    def test_every_message_after_a_halt_is_refused(self, monitor: Monitor) -> None:
        run(monitor, before(1, TOGGLE_STOVE))
        answers = run(monitor, before(2, GO_TO_MUG), after(2, GO_TO_MUG), "not json", 42)
        assert [a["type"] for a in answers] == ["halted"] * 4
        assert all(a["halted"] and a["violation"]["condition_id"] == "skill.toggle"
                   for a in answers)
        assert monitor.counters.refused == 4

    def test_a_monitor_resumed_with_a_stored_violation_refuses_everything(self) -> None:
        first = new_monitor()
        violation = first.step(before(1, TOGGLE_STOVE)).violation
        assert violation is not None
        stored = MonitorViolation.from_wire(json.loads(json.dumps(violation.to_wire())))
        resumed = Monitor(CompiledContract(CONTRACT), first.state, violation=stored)
        assert resumed.halted
        assert resumed.step(before(2, GO_TO_MUG)).type == "halted"


class TestMalformedMessages:
    @pytest.mark.parametrize("message", [
        "{not json", b"\xff\xfe", [1, 2], {"type": "during", "seq": 1},
        {"type": "before", "action": GO_TO_MUG}, {"type": "before", "seq": True, "action": {}},
        {"type": "before", "seq": 1}, {"type": "before", "seq": 1, "action": "GoToObject"},
        {"type": "before", "seq": 1, "action": {"action": "Teleport"}},
        {"type": "before", "seq": 1, "action": {"action": "PickupObject", "object": "ghost"}},
        {"type": "before", "seq": 1, "action": GO_TO_MUG, "state": {"scene": {"objects": 3}}},
    ])
    def test_is_answered_with_an_error_and_changes_nothing(
            self, monitor: Monitor, message: object) -> None:
        state = monitor.state
        verdict = monitor.step(message)
        assert verdict.type == "error" and not verdict.allowed and not verdict.halted
        assert verdict.detail
        assert monitor.state is state and not monitor.halted
        assert monitor.pending_seq is None

    def test_an_error_echoes_the_seq_when_there_is_one(self, monitor: Monitor) -> None:
        wire = monitor.step({"type": "before", "seq": 9}).to_wire()
        assert (wire["seq"], wire["halted"]) == (9, False)

    def test_an_after_without_its_before_is_an_error(self, monitor: Monitor) -> None:
        assert monitor.step(after(1, GO_TO_MUG)).type == "error"

    def test_a_new_action_while_one_is_running_is_an_error(self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, GO_TO_MUG), before(2, PICK_MUG))
        assert [a["type"] for a in answers] == ["allow", "error"]
        assert monitor.pending_seq == 1

    def test_an_after_reporting_another_action_is_an_error(self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, GO_TO_MUG), after(1, PICK_MUG))
        assert answers[1]["type"] == "error"
        assert monitor.pending_seq == 1

    def test_a_seq_that_does_not_increase_is_an_error(self, monitor: Monitor) -> None:
        answers = run(monitor, before(5, GO_TO_MUG), after(5, GO_TO_MUG), before(5, GO_TO_MUG))
        assert [a["type"] for a in answers] == ["allow", "allow", "error"]
        assert answers[2]["resync"] == {"last_seq": 5, "pending_seq": None}

    def test_a_resent_before_for_the_running_action_is_checked_again(
            self, monitor: Monitor) -> None:
        answers = run(monitor, before(1, GO_TO_MUG), before(1, GO_TO_MUG))
        assert [a["type"] for a in answers] == ["allow", "allow"]


class TestResynchronising:
    """A message that does not follow the last step is never checked against a state the
    runtime may have moved past: it is asked to resynchronise."""

    @pytest.mark.parametrize("messages", [
        [before(1, GO_TO_MUG), after(1, GO_TO_MUG), before(3, PICK_MUG)],  # 2 never seen
        [before(1, GO_TO_MUG), after(1, GO_TO_MUG), after(1, GO_TO_MUG)],  # a repeated after
        [before(1, GO_TO_MUG), before(2, PICK_MUG)],  # 1 still running
        [before(1, GO_TO_MUG), after(2, GO_TO_MUG)],
    ])
    def test_a_step_that_does_not_follow_gets_an_error_asking_to_resync(
            self, monitor: Monitor, messages: list[dict[str, Any]]) -> None:
        *accepted, out_of_step = run(monitor, *messages)
        assert all(a["type"] == "allow" for a in accepted)
        assert out_of_step["type"] == "error" and out_of_step["halted"] is False
        assert out_of_step["resync"] == {"last_seq": monitor.last_seq,
                                         "pending_seq": monitor.pending_seq}
        assert "does not follow" in out_of_step["detail"] or "matches no" in out_of_step[
            "detail"]

    def test_the_first_action_may_have_any_seq_and_the_next_must_follow_it(
            self, monitor: Monitor) -> None:
        answers = run(monitor, before(41, GO_TO_MUG), after(41, GO_TO_MUG),
                      before(42, PICK_MUG), after(42, PICK_MUG), before(44, GO_TO_MUG))
        assert [a["type"] for a in answers] == ["allow"] * 4 + ["error"]

    def test_sync_goes_on_from_the_runtimes_state(self, monitor: Monitor) -> None:
        """The runtime did seq 2 (picking the mug up) unmonitored; it reports where it is."""
        holding_mug = {"scene": {"objects": []},
                       "robot": {"room": "living_room", "holding": "mug_1"}}
        answers = run(monitor, before(1, GO_TO_MUG), after(1, GO_TO_MUG),
                      before(3, HAND_KNIFE),
                      {"type": "sync", "seq": 2, "state": holding_mug},
                      before(3, GO_TO_MUG))
        assert [a["type"] for a in answers] == ["allow", "allow", "error", "allow", "allow"]
        assert answers[3] == {"type": "allow", "seq": 2}
        assert monitor.state.robot.holding == "mug_1"
        assert monitor.state.robot.room == "living_room"
        assert (monitor.last_seq, monitor.pending_seq) == (2, 3)

    def test_a_sync_whose_state_breaks_an_invariant_halts(self, monitor: Monitor) -> None:
        overloaded = {"scene": {"objects": [{"id": "mug_1", "type": "Mug", "room": "kitchen",
                                             "properties": {"mass_kg": 5.0}}]},
                      "robot": {"room": "kitchen", "holding": "mug_1"}}
        answer = monitor.step({"type": "sync", "seq": 4, "state": overloaded}).to_wire()
        assert answer["type"] == "violation" and answer["halted"] is True
        assert answer["violation"]["condition_id"] == "payload.within_limit"
        assert answer["violation"]["phase"] == "sync"
        assert MonitorViolation.from_wire(answer["violation"]).phase == "sync"

    def test_a_sync_finishes_the_running_action_it_reaches(self, monitor: Monitor) -> None:
        here = {"scene": {"objects": []}, "robot": {"room": "kitchen"}}
        run(monitor, before(1, PICK_MUG), {"type": "sync", "seq": 1, "state": here})
        assert monitor.state.robot.holding == "mug_1"  # the pick's predicted effect
        assert (monitor.last_seq, monitor.pending_seq) == (1, None)

    def test_a_sync_before_the_running_action_abandons_it(self, monitor: Monitor) -> None:
        here = {"scene": {"objects": []}, "robot": {"room": "kitchen"}}
        answers = run(monitor, before(1, GO_TO_MUG), after(1, GO_TO_MUG), before(2, PICK_MUG),
                      {"type": "sync", "seq": 1, "state": here})
        assert [a["type"] for a in answers] == ["allow"] * 4
        assert monitor.state.robot.holding is None  # the pick never ran
        assert (monitor.last_seq, monitor.pending_seq) == (1, None)
        assert monitor.step(before(2, PICK_MUG)).type == "allow"

    @pytest.mark.parametrize("message", [
        {"type": "sync", "seq": 3},
        {"type": "sync", "seq": 3, "state": {"robot": {"room": "kitchen"}}},
        {"type": "sync", "seq": 3, "state": {"scene": {"objects": []}}},
    ])
    def test_a_sync_without_the_whole_state_is_an_error(
            self, monitor: Monitor, message: dict[str, Any]) -> None:
        answer = monitor.step(message).to_wire()
        assert answer["type"] == "error" and "state" in answer["detail"]
        assert monitor.last_seq is None

    def test_a_sync_cannot_go_back_before_the_last_finished_action(
            self, monitor: Monitor) -> None:
        here = {"scene": {"objects": []}, "robot": {"room": "kitchen"}}
        answers = run(monitor, before(5, GO_TO_MUG), after(5, GO_TO_MUG),
                      {"type": "sync", "seq": 4, "state": here})
        assert answers[2]["type"] == "error"
        assert answers[2]["resync"] == {"last_seq": 5, "pending_seq": None}

    def test_a_monitor_that_requires_sync_accepts_nothing_else(self, monitor: Monitor) -> None:
        monitor.require_sync("rebuilt from an incomplete log")
        here = {"scene": {"objects": []}, "robot": {"room": "kitchen"}}
        answers = run(monitor, before(1, GO_TO_MUG), {"type": "sync", "seq": 0, "state": here},
                      before(1, GO_TO_MUG))
        assert [a["type"] for a in answers] == ["error", "allow", "allow"]
        assert "rebuilt from an incomplete log" in answers[0]["detail"]
        assert not monitor.sync_required

    def test_a_halted_monitor_refuses_a_sync(self, monitor: Monitor) -> None:
        here = {"scene": {"objects": []}, "robot": {"room": "kitchen"}}
        answers = run(monitor, before(1, TOGGLE_STOVE), {"type": "sync", "seq": 1, "state": here})
        assert [a["type"] for a in answers] == ["violation", "halted"]


class TestCounters:
    def test_the_summary_counts_each_check(self, monitor: Monitor) -> None:
        run(monitor, before(1, GO_TO_MUG), after(1, GO_TO_MUG),
            before(2, PICK_MUG), after(2, PICK_MUG), "junk")
        summary = monitor.summary()
        assert (summary.actions_checked, summary.states_checked) == (2, 2)
        assert summary.guards_checked == 1  # one guard on PickupObject, none on GoToObject
        assert summary.invariants_checked == 2  # one invariant, two states
        assert summary.aborts_checked == 4  # one abort, two actions, before and after each
        assert (summary.errors, summary.messages, summary.halted) == (1, 5, False)
        assert summary.checks_by_condition == {
            "payload.within_limit": 2, "skill.pick": 1, "skill.toggle": 0,
            "sharp.no_knife_handover": 0, "stove.child_at_live_stove": 4}

    def test_counters_survive_a_json_round_trip(self, monitor: Monitor) -> None:
        run(monitor, before(1, PICK_MUG), after(1, PICK_MUG))
        data = json.loads(json.dumps(monitor.counters.to_json()))
        assert MonitorCounters.from_json(data) == monitor.counters

    def test_malformed_stored_counters_read_as_zero(self) -> None:
        counters = MonitorCounters.from_json({"messages": "seven", "errors": True})
        assert counters == MonitorCounters()


class TestReplay:
    def test_replaying_the_messages_rebuilds_state_pending_action_and_counts(
            self, monitor: Monitor) -> None:
        messages = [before(1, PICK_MUG), after(1, PICK_MUG), before(2, GO_TO_MUG)]
        run(monitor, *messages)
        rebuilt = new_monitor()
        replay(rebuilt, messages)
        assert rebuilt.pending_seq == 2
        assert rebuilt.state.robot.holding == "mug_1"
        assert rebuilt.counters == monitor.counters
