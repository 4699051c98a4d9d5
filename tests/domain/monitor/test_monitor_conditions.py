"""Compiling a contract for monitoring, and the fail-closed evaluation of condition groups."""

from __future__ import annotations

import pytest
from monitor_kit import ABORT, CONTRACT, GUARD, INVARIANT, REQUEST, condition

from app.domain.contracts import Contract
from app.domain.errors import FormulaError
from app.domain.models import GateRequest
from app.domain.monitor import CompiledContract, first_failure
from app.domain.world import WorldState, state_from_request


@pytest.fixture
def state() -> WorldState:
    return state_from_request(GateRequest.model_validate(REQUEST))


class TestCompiledContract:
    def test_guards_are_grouped_under_their_canonical_action(self) -> None:
        contract = Contract(guards=(condition(GUARD, "g.pick", "true", "pick"),))
        compiled = CompiledContract(contract)
        assert [g.condition.id for g in compiled.guards_for("PickupObject")] == ["g.pick"]
        assert compiled.guards_for("PutObject") == ()

    def test_a_guard_naming_no_action_guards_every_action(self) -> None:
        contract = Contract(guards=(condition(GUARD, "g.any", "true"),
                                    condition(GUARD, "g.put", "true", "PutObject")))
        compiled = CompiledContract(contract)
        assert [g.condition.id for g in compiled.guards_for("PutObject")] == ["g.any", "g.put"]
        assert [g.condition.id for g in compiled.guards_for("Wait")] == ["g.any"]

    def test_a_guard_on_an_unknown_action_cannot_be_monitored(self) -> None:
        contract = Contract(guards=(condition(GUARD, "g.fly", "true", "Fly"),))
        with pytest.raises(FormulaError, match="unknown action"):
            CompiledContract(contract)

    def test_a_condition_that_does_not_parse_cannot_be_monitored(self) -> None:
        contract = Contract(invariants=(condition(INVARIANT, "i.bad", "holding(robot,"),))
        with pytest.raises(FormulaError, match=r"i\.bad"):
            CompiledContract(contract)

    def test_an_action_argument_outside_a_guard_is_refused(self) -> None:
        contract = Contract(aborts=(condition(ABORT, "a.bad", "@object == #mug_1"),))
        with pytest.raises(FormulaError):
            CompiledContract(contract)

    def test_conditions_sharing_an_id_get_distinct_keys_by_binding(self) -> None:
        first = condition(INVARIANT, "t.c", "true").model_copy(update={"bindings": {"obj": "a"}})
        second = condition(INVARIANT, "t.c", "true").model_copy(update={"bindings": {"obj": "b"}})
        compiled = CompiledContract(Contract(invariants=(first, second)))
        assert [c.key for c in compiled.invariants] == ["t.c[obj=a]", "t.c[obj=b]"]


class TestFirstFailure:
    def test_nothing_fails_when_every_condition_has_its_required_value(
            self, state: WorldState) -> None:
        compiled = CompiledContract(CONTRACT)
        assert first_failure(compiled.invariants, state, None, must_be=True) is None
        assert first_failure(compiled.aborts, state, None, must_be=False) is None

    def test_a_true_abort_fails_and_a_false_invariant_fails(self, state: WorldState) -> None:
        contract = CompiledContract(Contract(
            invariants=(condition(INVARIANT, "i.no", "has_skill(robot, \"toggle\")"),),
            aborts=(condition(ABORT, "a.yes", "child(#child_1)"),)))
        invariant = first_failure(contract.invariants, state, None, must_be=True)
        abort = first_failure(contract.aborts, state, None, must_be=False)
        assert invariant is not None and invariant.established
        assert abort is not None and abort.established
        assert abort.compiled.condition.id == "a.yes"

    @pytest.mark.faults
    def test_an_unknown_fails_closed_and_names_the_missing_facts(
            self, state: WorldState) -> None:
        contract = CompiledContract(Contract(
            invariants=(condition(INVARIANT, "i.light", "mass_kg(#parcel_1) <= 1"),)))
        failure = first_failure(contract.invariants, state, None, must_be=True)
        assert failure is not None
        assert not failure.established
        assert failure.unknown_facts == ("mass_kg(parcel_1)",)

    @pytest.mark.faults
    def test_an_unknown_abort_fails_closed(self, state: WorldState) -> None:
        contract = CompiledContract(Contract(
            aborts=(condition(ABORT, "a.heavy", "mass_kg(#parcel_1) > 1"),)))
        failure = first_failure(contract.aborts, state, None, must_be=False)
        assert failure is not None and not failure.established

    def test_a_definite_failure_is_reported_before_an_earlier_unknown(
            self, state: WorldState) -> None:
        contract = CompiledContract(Contract(invariants=(
            condition(INVARIANT, "i.unknown", "mass_kg(#parcel_1) <= 1"),
            condition(INVARIANT, "i.false", "mass_kg(#mug_1) > 1"),
        )))
        failure = first_failure(contract.invariants, state, None, must_be=True)
        assert failure is not None and failure.compiled.condition.id == "i.false"

    def test_guards_read_the_action_arguments(self, state: WorldState) -> None:
        guards = CompiledContract(CONTRACT).guards_for("HandOver")
        assert first_failure(guards, state, {"object": "mug_1", "target": "p1"},
                             must_be=True) is None
        failure = first_failure(guards, state, {"object": "knife_1", "target": "p1"},
                                must_be=True)
        assert failure is not None and failure.compiled.condition.id == "sharp.no_knife_handover"
