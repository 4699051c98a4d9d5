"""The dict-backed TableFacts state."""

from __future__ import annotations

import pytest

from app.domain.formula import TableFacts, Unknown


class TestTableFacts:
    def test_missing_fact_is_unknown_keyed_by_fact_key(self) -> None:
        assert TableFacts({"mug": "object"}).value("hot", ("mug",)) == Unknown("hot(mug)")

    def test_robot_always_exists(self) -> None:
        facts = TableFacts({"mug": "object"})
        assert facts.entity_type("robot") == "robot"
        assert facts.domain("robot") == ("robot",)

    def test_domains_by_type_in_order(self) -> None:
        facts = TableFacts({"b": "person", "mug": "object", "a": "person"})
        assert list(facts.domain("person")) == ["b", "a"]
        assert facts.entity_type("ghost") is None

    def test_updated_returns_changed_copy(self) -> None:
        facts = TableFacts({"mug": "object"}, {("hot", ("mug",)): True})
        cooled = facts.updated({("hot", ("mug",)): False})
        assert (facts.value("hot", ("mug",)), cooled.value("hot", ("mug",))) == (True, False)

    def test_unknown_entity_type_is_refused(self) -> None:
        with pytest.raises(ValueError, match="planet"):
            TableFacts({"mars": "planet"})
