"""Fixtures for the store's tests: sample templates, gate records and contracts."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from app.domain.models import GateRequest, HazardReport, HazardTemplate
from app.store.records import ContractRecord, GateRecord
from app.store.repository import Repository

LIBRARY = Path(__file__).parent / "library"

TemplateFactory = Callable[..., HazardTemplate]


@pytest.fixture
def library_dir() -> Path:
    """The small YAML library under tests/store/library (3 templates, one of them a draft)."""
    return LIBRARY


@pytest.fixture
def make_template() -> TemplateFactory:
    """Build a valid template; keyword arguments override fields."""

    def build(**overrides: Any) -> HazardTemplate:
        fields: dict[str, Any] = {
            "id": "test.hot_mug",
            "name": "Hot mug near a person",
            "category": "physical",
            "hazard_class": "scald_hot_liquid",
            "description": "A hot mug carried near a person.",
            "severity": "high",
            "preventability": "preventable",
            "variables": [{"name": "obj", "type": "object"}],
            "invariants": [
                {
                    "id": "not_hot",
                    "formula": "not hot($obj)",
                    "description": "The mug is not hot.",
                }
            ],
        }
        fields.update(overrides)
        return HazardTemplate.model_validate(fields)

    return build


@pytest.fixture
def make_gate_record() -> Callable[..., GateRecord]:
    """Build an unsaved gate record; keyword arguments override fields."""

    def build(**overrides: Any) -> GateRecord:
        fields: dict[str, Any] = {
            "request": GateRequest.model_validate(
                {
                    "command": "bring the hot coffee to my daughter",
                    "scene": {"objects": [{"id": "mug_1", "type": "Mug", "in": "cupboard_1"}]},
                    "user": {"age_group": "child"},
                }
            ),
            "hazard_report": HazardReport(),
            "decision": "authorize",
            "rule": "R4",
            "triggers": [{"hazard": "scald_hot_liquid"}],
            "timings": {"analysis_ms": 1.5},
            "template_versions": {"thermal.hot_liquid_near_person": 2},
        }
        fields.update(overrides)
        return GateRecord.model_validate(fields)

    return build


@pytest.fixture
def saved_contract(
    repository: Repository, make_gate_record: Callable[..., GateRecord]
) -> ContractRecord:
    """A contract with 3 attempts, saved for a saved authorize record."""
    gate = repository.save_gate_record(make_gate_record())
    assert gate.id is not None
    return repository.save_contract(
        ContractRecord(
            request_id=gate.id,
            contract={"invariants": [{"id": "not_hot", "formula": "not hot(mug_1)"}]},
            template_versions={"test.hot_mug": 1},
            max_attempts=3,
        )
    )
