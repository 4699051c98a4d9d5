"""The OpenAPI document says what a client needs: errors, security, enums, examples, summaries.

In-process (`TestClient`), on the served `/openapi.json`; the live, fuzzed conformance of the
same document is `test_openapi_conformance.py`.
"""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient

PROBLEM_JSON = "application/problem+json"


@pytest.fixture
def document(client: TestClient) -> dict[str, Any]:
    answer = client.get("/openapi.json")
    assert answer.status_code == 200
    schema: dict[str, Any] = answer.json()
    return schema


def operations(document: dict[str, Any]) -> list[tuple[str, str, dict[str, Any]]]:
    return [(method.upper(), path, operation)
            for path, item in document["paths"].items() for method, operation in item.items()]


class TestErrorsAreDeclared:
    def test_every_error_response_is_problem_json_and_nothing_else(
        self, document: dict[str, Any]
    ) -> None:
        declared = 0
        for method, path, operation in operations(document):
            for status, response in operation["responses"].items():
                if status.startswith(("4", "5")):
                    assert list(response["content"]) == [PROBLEM_JSON], (method, path, status)
                    assert response["content"][PROBLEM_JSON]["schema"] == {
                        "$ref": "#/components/schemas/Problem"}
                    declared += 1
        assert declared > 100
        assert "HTTPValidationError" not in document["components"]["schemas"]

    @pytest.mark.parametrize(("method", "path", "statuses"), [
        ("POST", "/gate", {"401", "403", "413", "422", "503"}),
        ("POST", "/verify", {"401", "403", "404", "409", "413", "422", "503"}),
        ("GET", "/contracts/{contract_id}", {"401", "404", "422", "503"}),
        ("POST", "/templates/{template_id}/activate", {"401", "403", "404", "409", "422"}),
        ("DELETE", "/keys/{key_id}", {"401", "403", "404", "422", "503"}),
    ])
    def test_the_statuses_a_route_can_answer_are_listed(
        self, document: dict[str, Any], method: str, path: str, statuses: set[str]
    ) -> None:
        responses = document["paths"][path][method.lower()]["responses"]
        assert statuses <= set(responses)

    def test_a_busy_gate_documents_retry_after(self, document: dict[str, Any]) -> None:
        busy = document["paths"]["/gate"]["post"]["responses"]["503"]
        assert "Retry-After" in busy["headers"]

    def test_the_problem_schema_names_the_offending_fields(
        self, document: dict[str, Any]
    ) -> None:
        problem = document["components"]["schemas"]["Problem"]
        assert {"type", "title", "status", "detail"} <= set(problem["required"])
        assert "errors" in problem["properties"]


class TestSecurity:
    def test_both_key_schemes_are_declared(self, document: dict[str, Any]) -> None:
        schemes = document["components"]["securitySchemes"]
        assert schemes["BearerKey"] == {**schemes["BearerKey"], "type": "http",
                                        "scheme": "bearer"}
        assert schemes["ApiKeyHeader"]["name"] == "X-API-Key"

    def test_every_operation_but_the_probes_takes_a_key(
        self, document: dict[str, Any]
    ) -> None:
        for method, path, operation in operations(document):
            if path in ("/healthz", "/readyz"):
                assert "security" not in operation, path
                assert "401" not in operation["responses"], path
            else:
                assert operation["security"] == [{"BearerKey": []}, {"ApiKeyHeader": []}], (
                    method, path)
                assert "401" in operation["responses"], (method, path)


class TestDescriptions:
    def test_every_operation_has_a_written_summary_and_a_description(
        self, document: dict[str, Any]
    ) -> None:
        for method, path, operation in operations(document):
            # FastAPI's generated summaries title-case the function's name ("Post Gate").
            words = operation["summary"].split()
            assert len(words) > 2 and not all(w[:1].isupper() for w in words), (method, path)
            assert operation.get("description"), (method, path)

    def test_the_gate_answer_has_enums_with_the_wire_values(
        self, document: dict[str, Any]
    ) -> None:
        schemas = document["components"]["schemas"]
        assert schemas["Decision"]["enum"] == ["authorize", "defer", "reject"]
        assert schemas["Rule"]["enum"] == ["R1", "R1b", "R2", "R3", "R3b", "R4"]
        hazard = schemas["HazardOut"]["properties"]
        for field in ("level", "category", "severity", "preventability", "confidence"):
            assert "$ref" in hazard[field], field

    def test_every_json_request_body_has_an_example(self, document: dict[str, Any]) -> None:
        schemas = document["components"]["schemas"]
        for method, path, operation in operations(document):
            body = operation.get("requestBody", {}).get("content", {}).get("application/json")
            if body is None:
                continue
            schema = body["schema"]
            named = schema.get("$ref", "").rsplit("/", 1)[-1]
            has_example = ("examples" in body or "example" in body or "examples" in schema
                           or bool(named and "examples" in schemas[named]))
            assert has_example, (method, path)


class TestMethodsAndParameters:
    def test_a_wrong_method_names_every_method_of_the_path(self, client: TestClient) -> None:
        answer = client.request("PATCH", "/keys")
        assert answer.status_code == 405
        assert answer.headers["allow"] == "GET, POST"
        assert answer.headers["content-type"] == PROBLEM_JSON
        assert client.request("PATCH", "/keys/me").headers["allow"] == "GET"
        assert client.request("PATCH", "/keys/k1").headers["allow"] == "DELETE"

    def test_a_template_version_past_any_integer_is_a_422_not_a_500(
        self, client: TestClient
    ) -> None:
        template_id = client.get("/templates").json()["templates"][0]["id"]
        answer = client.get(f"/templates/{template_id}/versions/9223372036854775808")
        assert answer.status_code == 422
        assert answer.json()["errors"][0]["field"] == "path.version"


def _resolved(document: dict[str, Any], schema: dict[str, Any]) -> dict[str, Any]:
    if "$ref" in schema:
        resolved: dict[str, Any] = document["components"]["schemas"][
            schema["$ref"].rsplit("/", 1)[1]]
        return resolved
    return schema


class TestEveryAnswerIsTyped:
    def test_every_json_answer_has_a_model_with_named_fields(
        self, document: dict[str, Any]
    ) -> None:
        untyped = []
        for method, path, operation in operations(document):
            success = next(r for code, r in operation["responses"].items()
                           if code.startswith("2"))
            schema = success.get("content", {}).get("application/json", {}).get("schema")
            if "application/json" in success.get("content", {}) and (
                    not schema or "properties" not in _resolved(document, schema)):
                untyped.append(f"{method} {path}")
        assert untyped == []

    def test_every_operation_declares_its_errors(self, document: dict[str, Any]) -> None:
        silent = [f"{method} {path}" for method, path, operation in operations(document)
                  if not any(code.startswith(("4", "5")) for code in operation["responses"])]
        assert silent == []

    def test_the_audit_record_names_its_decision_and_rule_enums(
        self, document: dict[str, Any]
    ) -> None:
        record = document["components"]["schemas"]["GateRecordResponse"]
        assert record["properties"]["decision"] == {"$ref": "#/components/schemas/Decision"}
        assert record["properties"]["rule"] == {"$ref": "#/components/schemas/Rule"}
        assert {"request_id", "followed_by", "request", "hazard_report"} <= set(
            record["required"])
