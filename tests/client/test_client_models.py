"""The SDK's committed wire models are what the live service describes, and read its wire format
exactly.

- Drift: `clients/python/codegen.py` (the generator `make client-models` runs) is run again on
  the OpenAPI document a live `safegate serve` answers at `/openapi.json`, and on
  `docs/api/asyncapi.yaml` (itself tested against the websockets by
  `tests/api/test_api_docs.py`); the output must equal the committed `models/api.py` and
  `models/monitor.py`, so a changed route or schema fails here until the models are regenerated.
- Round trip: every request example of the OpenAPI document read into the SDK's model and
  written back is the same JSON (nothing renamed, lost or invented on the way out).
"""

from __future__ import annotations

import importlib.util
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import httpx
import pytest
from pydantic import BaseModel
from safegate_client import models

ROOT = Path(__file__).resolve().parents[2]
REGENERATE = "the committed SDK models drift from the service: run `make client-models`"


def codegen() -> ModuleType:
    spec = importlib.util.spec_from_file_location("safegate_codegen",
                                                  ROOT / "clients" / "python" / "codegen.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def generator() -> ModuleType:
    return codegen()


@pytest.fixture
def live_openapi(live_server: Callable[..., Any]) -> dict[str, Any]:
    server = live_server(SAFEGATE_LOG_LEVEL="warning")
    document: dict[str, Any] = httpx.get(server.base_url + "/openapi.json", timeout=30).json()
    return document


class TestModelDrift:
    @pytest.mark.slow
    def test_the_api_models_are_those_of_the_live_openapi_document(
            self, generator: ModuleType, live_openapi: dict[str, Any]) -> None:
        committed = generator.API_MODELS.read_text()
        assert generator.render_api(live_openapi) == committed, REGENERATE

    @pytest.mark.slow
    def test_the_monitor_models_are_those_of_the_asyncapi_document(
            self, generator: ModuleType) -> None:
        committed = generator.MONITOR_MODELS.read_text()
        assert generator.render_monitor(generator.ASYNCAPI.read_text()) == committed, REGENERATE


def request_examples(document: dict[str, Any]) -> list[tuple[str, dict[str, Any]]]:
    """(schema name, example) for every example of the document: on a component schema, or
    on a request body whose schema is a component."""
    found = [(name, example) for name, schema in document["components"]["schemas"].items()
             for example in schema.get("examples", []) if isinstance(example, dict)]
    for operations in document["paths"].values():
        for operation in operations.values():
            body = operation.get("requestBody", {}).get("content", {}).get("application/json",
                                                                            {})
            reference = body.get("schema", {}).get("$ref", "")
            if reference.startswith("#/components/schemas/"):
                name = reference.rsplit("/", 1)[1]
                found += [(name, named["value"]) for named in body.get("examples", {}).values()]
    return found


class TestWireFormat:
    @pytest.mark.slow
    def test_request_examples_round_trip_through_the_models(
            self, live_openapi: dict[str, Any]) -> None:
        examples = request_examples(live_openapi)
        assert {name for name, _ in examples} >= {"GateRequest", "VerifyRequest",
                                                  "MonitorOpenRequest"}
        for name, example in examples:
            model: type[BaseModel] = getattr(models.api, name)
            again = model.model_validate(example).model_dump(mode="json", by_alias=True,
                                                             exclude_unset=True)
            assert again == example, name

    def test_monitor_answers_are_told_apart_by_type(self) -> None:
        assert isinstance(models.parse_answer({"type": "allow", "seq": 7}), models.Allow)
        error = models.parse_answer({"type": "error", "seq": 5, "halted": False, "detail": "x",
                                     "resync": {"last_seq": 1, "pending_seq": None}})
        assert isinstance(error, models.ErrorAnswer) and error.resync is not None
        assert error.resync.last_seq == 1

    def test_an_unknown_answer_is_refused_not_guessed(self) -> None:
        with pytest.raises(ValueError):
            models.parse_answer({"type": "allowed", "seq": 7})
        with pytest.raises(ValueError):
            models.parse_answer({"type": "violation", "seq": 7, "halted": False})
