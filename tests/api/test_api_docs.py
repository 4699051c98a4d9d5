"""`docs/api/` and the OpenAPI examples cannot rot: every example is sent to a live server.

- Every JSON block in `docs/api/*.md` marked `<!-- example: METHOD PATH -> outcome -->` is sent
  over real HTTP to `safegate serve` on loopback and must be accepted (2xx); a gate example's
  outcome is the decision it must get, a verify example's `ok` or `violation`. Ids in the
  examples (`contract_id`, the deferred request to answer) are replaced by the ones this
  server issued for the documented requests before them.
- The monitor conversation in `docs/api/monitor.md` (`→` sent, `←` answered) is replayed on a
  real websocket: every answer must hold the documented fields, and fit its message's schema in
  `docs/api/asyncapi.yaml`.
- `docs/api/asyncapi.yaml` parses, every `$ref` in it resolves, its message examples fit their
  schemas, and its channels are exactly the app's websocket routes.
- Every request example of the OpenAPI document is accepted the same way.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import jsonschema
import pytest
import yaml
from fastapi.routing import iter_route_contexts
from starlette.routing import WebSocketRoute
from websockets.sync.client import connect

from app.config import Settings
from app.main import create_app
from tests.api.conftest import LiveServer

DOCS = Path(__file__).resolve().parents[2] / "docs" / "api"
ASYNCAPI = DOCS / "asyncapi.yaml"
_EXAMPLE = re.compile(r"<!-- example: (\S+) (\S+)(?: -> ([^>]*?))? -->\s*```(\w+)\n(.*?)```",
                      re.S)


def examples(page: str) -> list[tuple[str, str, str, str]]:
    """(method, path, outcome, block text) for every marked example of a page, in order."""
    text = (DOCS / page).read_text()
    return [(m[1], m[2], (m[3] or "").strip(), m[5]) for m in _EXAMPLE.finditer(text)]


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LiveServer]:
    directory = tmp_path_factory.mktemp("docs")
    live = LiveServer(database_url=f"sqlite:///{directory / 'docs.db'}",
                      env={"SAFEGATE_LOG_LEVEL": "warning"}).start()
    yield live
    live.stop()


def asyncapi() -> dict[str, Any]:
    document: dict[str, Any] = yaml.safe_load(ASYNCAPI.read_text())
    return document


def schema_of(document: dict[str, Any], name: str) -> dict[str, Any]:
    """A component schema, resolvable on its own (the document's components come along)."""
    return {"$ref": f"#/components/schemas/{name}", "components": document["components"]}


def subset(expected: Any, actual: Any) -> bool:
    """Whether `actual` holds everything `expected` says (objects: key by key; `detail` only
    up to a documented `(...)`)."""
    if isinstance(expected, dict):
        return isinstance(actual, dict) and all(
            key in actual and (
                str(actual[key]).startswith(value.removesuffix("(...)"))
                if key == "detail" and isinstance(value, str) else subset(value, actual[key]))
            for key, value in expected.items())
    return bool(expected == actual)


class TestHttpExamples:
    def test_every_documented_request_is_accepted_as_described(
        self, server: LiveServer
    ) -> None:
        issued: dict[str, str] = {}
        sent = 0
        with httpx.Client(base_url=server.base_url, timeout=60) as http:
            for page in ("gate.md", "plans-and-verify.md", "monitor.md"):
                for method, path, outcome, block in examples(page):
                    if method == "WS":
                        continue
                    body = json.loads(block)
                    if "contract_id" in body:
                        body["contract_id"] = issued["contract_id"]
                    url = path.replace("{request_id}", issued.get("deferred", ""))
                    answer = http.request(method, url, json=body)
                    assert answer.is_success, (page, path, answer.text)
                    sent += 1
                    result = answer.json()
                    if path == "/gate":
                        assert result["decision"] == outcome, (page, result["reason"])
                        if outcome == "authorize":
                            issued["contract_id"] = result["contract_id"]
                        if outcome == "defer":
                            issued["deferred"] = result["request_id"]
                    if path == "/verify":
                        assert result["ok"] is (outcome == "ok"), result
        assert sent == 7

    def test_every_openapi_request_example_is_accepted(self, server: LiveServer) -> None:
        with httpx.Client(base_url=server.base_url, timeout=60) as http:
            document = http.get("/openapi.json").json()
            authorize = document["paths"]["/gate"]["post"]["requestBody"]["content"][
                "application/json"]["examples"]["authorize"]["value"]
            contract_id = http.post("/gate", json=authorize).json()["contract_id"]
            schemas = document["components"]["schemas"]
            tried = 0
            for name in ("VerifyRequest", "MonitorOpenRequest"):
                for example in schemas[name]["examples"]:
                    path = "/verify" if name == "VerifyRequest" else "/monitor"
                    answer = http.post(path, json={**example, "contract_id": contract_id})
                    assert answer.is_success, (name, answer.text)
                    tried += 1
            for outcome, example in document["paths"]["/gate"]["post"]["requestBody"][
                    "content"]["application/json"]["examples"].items():
                answer = http.post("/gate", json=example["value"])
                assert answer.json()["decision"] == outcome, example["summary"]
                tried += 1
        assert tried == 5


class TestMonitorConversation:
    def test_the_documented_run_gets_the_documented_answers(self, server: LiveServer) -> None:
        [(_, _, _, block)] = [e for e in examples("monitor.md") if e[0] == "WS"]
        lines = [line for line in block.splitlines() if line.strip()]
        document = asyncapi()
        with httpx.Client(base_url=server.base_url, timeout=60) as http:
            gate_example = json.loads(examples("gate.md")[0][3])
            contract_id = http.post("/gate", json=gate_example).json()["contract_id"]
            session_id = http.post("/monitor", json={"contract_id": contract_id}).json()[
                "session_id"]
        answered = 0
        with connect(f"{server.ws_url}/monitor/{session_id}") as socket:
            for sent, expected in zip(lines[::2], lines[1::2], strict=True):
                assert sent.startswith("→ ") and expected.startswith("← ")
                socket.send(sent[2:])
                answer = json.loads(socket.recv(timeout=30))
                wanted = json.loads(expected[2:])
                assert subset(wanted, answer), (sent, answer)
                name = {"allow": "Allow", "violation": "ViolationAnswer",
                        "halted": "HaltedAnswer", "error": "ErrorAnswer"}[answer["type"]]
                jsonschema.validate(answer, schema_of(document, name))
                answered += 1
        assert answered == 8


class TestAsyncApiDocument:
    def test_it_parses_and_every_reference_resolves(self) -> None:
        document = asyncapi()
        assert document["asyncapi"].startswith("3.")
        refs = re.findall(r"\$ref: '([^']+)'", ASYNCAPI.read_text())
        assert len(refs) > 20
        for ref in refs:
            node: Any = document
            for part in ref.removeprefix("#/").split("/"):
                node = node[part]
            assert isinstance(node, dict), ref

    def test_message_examples_fit_their_payload_schemas(self) -> None:
        document = asyncapi()
        checked = 0
        for message in document["components"]["messages"].values():
            for example in message.get("examples", []):
                ref = message["payload"]["$ref"].rsplit("/", 1)[1]
                jsonschema.validate(example["payload"], schema_of(document, ref))
                checked += 1
        assert checked >= 5

    def test_its_channels_are_the_apps_websocket_routes(self, sqlite_url: str) -> None:
        app = create_app(Settings(database_url=sqlite_url))
        routes = {route.path for route in iter_route_contexts(app.routes)
                  if isinstance(route.original_route, WebSocketRoute)}
        addresses = {channel["address"] for channel in asyncapi()["channels"].values()}
        assert routes == addresses == {"/monitor/{session_id}", "/monitor/{session_id}/events"}
