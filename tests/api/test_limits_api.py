"""Input limits over HTTP: every over-limit or unstorable input is a 422 problem+json naming the
field, on SQLite and PostgreSQL alike (a database must never be the one to refuse it with a 503),
and a request at the limits is still decided."""

from __future__ import annotations

import json
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi.testclient import TestClient

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from monitor_kit import GO_TO_MUG, REQUEST, before, store_contract

from app.api.limits import MAX_JSON_NUMBER
from app.config import Settings
from app.domain.models.request import MAX_COMMAND_CHARS, MAX_ENTITIES
from app.main import create_app
from app.store.repository import Repository

PROBLEM_JSON = "application/problem+json"


def refused_field(response: Any) -> str:
    """The field a 422 problem+json names (asserting the answer is one)."""
    assert response.status_code == 422, response.text
    assert response.headers["content-type"] == PROBLEM_JSON
    body = response.json()
    assert body["status"] == 422 and body["errors"], body
    field: str = body["errors"][0]["field"]
    return field


def post_raw(client: TestClient, path: str, text: str | bytes) -> Any:
    return client.post(path, content=text, headers={"content-type": "application/json"})


def with_property(value: str) -> str:
    """A gate request whose one object has a `weird` property given as raw JSON text."""
    return ('{"command": "bring the mug", "scene": {"objects": [{"id": "mug_1", "type": "Mug", '
            '"properties": {"weird": ' + value + '}}]}}')


def nested(depth: int) -> str:
    return '{"a": ' * depth + "1" + "}" * depth


class TestJsonShapeLimits:
    def test_nesting_past_the_depth_limit_names_the_field(self, client: TestClient) -> None:
        field = refused_field(post_raw(client, "/gate", with_property(nested(40))))
        assert field.startswith("body.scene.objects.0.properties.weird.a.a")

    def test_nesting_past_the_decoder_is_a_422_not_a_400(self, client: TestClient) -> None:
        assert refused_field(post_raw(client, "/gate", "[" * 100_000 + "]" * 100_000)) == "body"

    def test_nesting_within_the_limit_is_decided(self, client: TestClient) -> None:
        response = post_raw(client, "/gate", with_property(nested(20)))
        assert response.status_code == 200, response.text

    @pytest.mark.parametrize("number", ["NaN", "Infinity", "-Infinity", "1e400"])
    def test_non_finite_numbers_are_refused_anywhere(self, client: TestClient,
                                                     number: str) -> None:
        field = refused_field(post_raw(client, "/gate", with_property(f"[1, {number}]")))
        assert field == "body.scene.objects.0.properties.weird.1"

    @pytest.mark.parametrize("number", ["1e16", "-10000000000000001", "9" * 400])
    def test_huge_numbers_are_refused(self, client: TestClient, number: str) -> None:
        field = refused_field(post_raw(client, "/gate", with_property(number)))
        assert field == "body.scene.objects.0.properties.weird"

    def test_a_number_too_long_to_parse_is_a_422(self, client: TestClient) -> None:
        assert refused_field(post_raw(client, "/gate", with_property("9" * 5000))) == "body"

    def test_numbers_at_the_limit_are_decided(self, client: TestClient) -> None:
        response = post_raw(client, "/gate", with_property(f"[{MAX_JSON_NUMBER!r}, -1e15, 0.5]"))
        assert response.status_code == 200, response.text

    def test_a_body_that_is_not_utf8_is_a_422(self, client: TestClient) -> None:
        assert refused_field(post_raw(client, "/gate", b'{"command": "\xff\xfe"}')) == "body"

    def test_plan_steps_are_held_to_the_same_shape(self, client: TestClient) -> None:
        body = '{"contract_id": "c", "plan": [{"action": "Wait", "seconds": NaN}]}'
        assert refused_field(post_raw(client, "/verify", body)) == "body.plan.0.seconds"

    def test_answers_are_held_to_the_same_shape(self, client: TestClient) -> None:
        response = post_raw(client, "/gate/some-id/answers", '{"age_group": ' + nested(40) + "}")
        assert refused_field(response).startswith("body.age_group.a")


class TestUnstorableText:
    """NUL and lone surrogates: PostgreSQL cannot store them, so they must never reach it."""

    @pytest.mark.parametrize("text", ["\\u0000", "\\ud800", "\\udfff"])
    def test_in_the_command(self, client_on: TestClient, text: str) -> None:
        body = '{"command": "bring the mug ' + text + '"}'
        assert refused_field(post_raw(client_on, "/gate", body)) == "body.command"

    def test_in_a_property_key(self, client_on: TestClient) -> None:
        field = refused_field(post_raw(client_on, "/gate", with_property('{"x\\u0000": 1}')))
        assert field == "body.scene.objects.0.properties.weird.x\x00"

    def test_other_unicode_is_decided_and_stored(self, client_on: TestClient) -> None:
        command = "bring the mug ☕ to Zoë in the 客厅 \u200b\U0001f600"
        response = client_on.post("/gate", json={"command": command})
        assert response.status_code == 200, response.text
        stored = client_on.get(f"/gate/{response.json()['request_id']}").json()
        assert stored["request"]["command"] == command


def with_object_property(key: str, value: Any) -> dict[str, Any]:
    return {"command": "bring the mug", "scene": {"objects": [
        {"id": "counter_1", "type": "CounterTop"},
        {"id": "mug_1", "type": "Mug", "properties": {key: value}}]}}


def with_person_property(key: str, value: Any) -> dict[str, Any]:
    return {"command": "bring the mug to grandpa", "scene": {"people": [
        {"id": "grandpa", "role": "grandfather", "properties": {key: value}}]}}


class TestPropertyValues:
    """Property values with a fixed meaning are checked: a 422 names the property."""

    @pytest.mark.parametrize(("key", "value"), [
        ("mass_kg", -0.5), ("mass_kg", "heavy"), ("mass_kg", True), ("temperature", "warm"),
        ("temperature", 80), ("sharp", "maybe"), ("on", 7), ("lidded", {"yes": 1}),
        ("contents", 3)])
    def test_an_object_property_out_of_its_meaning_is_refused(
            self, client_on: TestClient, key: str, value: Any) -> None:
        response = client_on.post("/gate", json=with_object_property(key, value))
        assert refused_field(response) == f"body.scene.objects.1.properties.{key}"
        assert response.json()["errors"][0]["message"]

    @pytest.mark.parametrize(("key", "value"), [
        ("age_group", "toddler"), ("mobility", "flying"), ("cognitive_state", "grumpy"),
        ("pregnant", "perhaps"), ("allergies", 4), ("mass_kg", -70)])
    def test_a_person_property_out_of_its_meaning_is_refused(
            self, client: TestClient, key: str, value: Any) -> None:
        response = client.post("/gate", json=with_person_property(key, value))
        assert refused_field(response) == f"body.scene.people.0.properties.{key}"

    @pytest.mark.parametrize(("key", "value", "stored"), [
        ("mass_kg", 0, 0.0), ("mass_kg", 2.5, 2.5), ("temperature", " Hot ", "hot"),
        ("temperature", "room", "room"), ("sharp", "yes", True), ("on", False, False),
        ("open", None, None), ("contents", "coffee", "coffee"), ("colour", "blue", "blue"),
        ("anything_else", {"free": [1, "x"]}, {"free": [1, "x"]})])
    def test_values_within_their_meaning_are_decided_and_stored_as_read(
            self, client: TestClient, key: str, value: Any, stored: Any) -> None:
        response = client.post("/gate", json=with_object_property(key, value))
        assert response.status_code == 200, response.text
        record = client.get(f"/gate/{response.json()['request_id']}").json()
        assert record["request"]["scene"]["objects"][1]["properties"][key] == stored

    def test_a_monitor_initial_state_is_held_to_the_same_meanings(
            self, client: TestClient) -> None:
        contract_id = store_contract(repository_of(client))
        state = with_object_property("mass_kg", -1)
        response = client.post("/monitor", json={"contract_id": contract_id,
                                                 "initial_state": {"scene": state["scene"]}})
        assert refused_field(response) == "body.initial_state.scene.objects.1.properties.mass_kg"

    def test_a_verify_initial_state_is_held_to_the_same_meanings(
            self, client: TestClient) -> None:
        state = with_object_property("temperature", "lukewarm")
        response = client.post("/verify", json={
            "contract": {"invariants": []}, "plan": [],
            "initial_state": {"scene": state["scene"]}})
        assert refused_field(response) == (
            "body.initial_state.scene.objects.1.properties.temperature")

    def test_an_answer_out_of_its_meaning_is_a_422_naming_it(self, client: TestClient) -> None:
        asked = client.post("/gate", json={
            "command": "bring the coffee to grandpa",
            "scene": {"objects": [{"id": "mug_1", "type": "Mug",
                                   "properties": {"contents": "coffee"}}],
                      "people": [{"id": "grandpa", "role": "grandfather"}]},
            "user": {"person_id": "grandpa"}}).json()
        response = client.post(f"/gate/{asked['request_id']}/answers",
                               json={"age_group": "elf"})
        assert refused_field(response) == "body.age_group"


@pytest.fixture
def tight_client(sqlite_url: str) -> Iterator[TestClient]:
    settings = Settings(database_url=sqlite_url, max_command_chars=40, max_scene_entities=3,
                        max_plan_steps=2)
    with TestClient(create_app(settings)) as test_client:
        yield test_client


def repository_of(client: TestClient) -> Repository:
    repository = Repository(client.app.state.components.engine)  # type: ignore[attr-defined]
    return repository


def objects(count: int) -> list[dict[str, Any]]:
    return [{"id": f"box_{i}", "type": "Box", "room": "kitchen"} for i in range(count)]


class TestConfiguredLimits:
    def test_a_command_over_the_setting_is_refused(self, tight_client: TestClient) -> None:
        response = tight_client.post("/gate", json={"command": "bring the mug " * 3})
        assert refused_field(response) == "body.command"
        assert response.json()["limit"] == 40

    @pytest.mark.parametrize("name", ["objects", "people", "relations"])
    def test_a_scene_list_over_the_setting_is_refused(self, tight_client: TestClient,
                                                      name: str) -> None:
        items: dict[str, list[dict[str, Any]]] = {
            "objects": objects(4),
            "people": [{"id": f"p{i}", "room": "kitchen"} for i in range(4)],
            "relations": [{"subject": "a", "relation": "on", "object": "b"}] * 4,
        }
        response = tight_client.post("/gate", json={"command": "tidy up",
                                                    "scene": {name: items[name]}})
        assert refused_field(response) == f"body.scene.{name}"

    def test_layout_rooms_over_the_setting_are_refused(self, tight_client: TestClient) -> None:
        scene = {"layout": {"rooms": ["a", "b", "c", "d"]}}
        response = tight_client.post("/gate", json={"command": "tidy up", "scene": scene})
        assert refused_field(response) == "body.scene.layout.rooms"

    def test_a_request_at_the_settings_is_decided(self, tight_client: TestClient) -> None:
        response = tight_client.post("/gate", json={"command": "x" * 40,
                                                    "scene": {"objects": objects(3)}})
        assert response.status_code == 200, response.text

    def test_a_plan_over_the_setting_is_refused(self, tight_client: TestClient) -> None:
        contract_id = store_contract(repository_of(tight_client))
        response = tight_client.post("/verify", json={"contract_id": contract_id,
                                                      "plan": [GO_TO_MUG] * 3})
        assert refused_field(response) == "body.plan"

    def test_a_plan_at_the_setting_is_verified(self, tight_client: TestClient) -> None:
        contract_id = store_contract(repository_of(tight_client))
        response = tight_client.post("/verify", json={"contract_id": contract_id,
                                                      "plan": [GO_TO_MUG] * 2})
        assert response.status_code == 200, response.text

    def test_a_monitor_initial_state_over_the_setting_is_refused(
        self, tight_client: TestClient
    ) -> None:
        contract_id = store_contract(repository_of(tight_client))
        response = tight_client.post("/monitor", json={
            "contract_id": contract_id, "initial_state": {"scene": {"objects": objects(4)}}})
        assert refused_field(response) == "body.initial_state.scene.objects"

    def test_answers_are_held_to_todays_settings(self, sqlite_url: str) -> None:
        """A request stored under wider limits and answered after an operator narrowed them is
        refused like a new one (the gate service checks every request it decides, re-evaluations
        too), and nothing new is stored."""
        wide = Settings(database_url=sqlite_url)
        with TestClient(create_app(wide)) as client:
            asked = client.post("/gate", json={
                "command": "hand the knife to sam",
                "scene": {"objects": [{"id": "knife_1", "type": "Knife"}, *objects(3)],
                          "people": [{"id": "sam", "role": "visitor"}]}}).json()
        assert asked["decision"] == "defer", asked
        tight = Settings(database_url=sqlite_url, max_scene_entities=3)
        with TestClient(create_app(tight)) as client:
            answered = client.post(f"/gate/{asked['request_id']}/answers",
                                   json={"age_group": "older_adult"})
            assert refused_field(answered) == "body.scene.objects"
            assert repository_of(client).list_child_records(asked["request_id"]) == []

    def test_the_models_caps_bound_the_settings(self) -> None:
        with pytest.raises(ValueError, match="max_command_chars"):
            Settings(max_command_chars=MAX_COMMAND_CHARS + 1)
        with pytest.raises(ValueError, match="max_scene_entities"):
            Settings(max_scene_entities=MAX_ENTITIES + 1)


class TestDefaultLimits:
    def test_a_command_over_the_cap_is_refused(self, client: TestClient) -> None:
        response = client.post("/gate", json={"command": "a" * (MAX_COMMAND_CHARS + 1)})
        assert refused_field(response) == "body.command"

    def test_objects_over_the_cap_are_refused(self, client: TestClient) -> None:
        response = client.post("/gate", json={"command": "tidy up",
                                              "scene": {"objects": objects(MAX_ENTITIES + 1)}})
        assert refused_field(response) == "body.scene.objects"

    def test_people_over_the_cap_are_refused(self, client: TestClient) -> None:
        people = [{"id": f"p{i}"} for i in range(MAX_ENTITIES + 1)]
        response = client.post("/gate", json={"command": "tidy up", "scene": {"people": people}})
        assert refused_field(response) == "body.scene.people"

    def test_a_full_scene_at_the_caps_is_decided(self, client: TestClient) -> None:
        response = client.post("/gate", json={"command": "a" * MAX_COMMAND_CHARS,
                                              "scene": {"objects": objects(MAX_ENTITIES)}})
        assert response.status_code == 200, response.text


class TestMonitorMessages:
    """A runtime message nested past the decoder is refused, and the session goes on."""

    def test_a_message_nested_too_deeply_is_an_error_answer(self, client: TestClient) -> None:
        contract_id = store_contract(repository_of(client), request=REQUEST)
        session_id = client.post("/monitor", json={"contract_id": contract_id}).json()[
            "session_id"]
        with client.websocket_connect(f"/monitor/{session_id}") as socket:
            socket.send_text("[" * 200_000 + "]" * 200_000)
            refused = json.loads(socket.receive_text())
            socket.send_text(json.dumps(before(1, GO_TO_MUG)))
            allowed = json.loads(socket.receive_text())
        assert refused["type"] == "error" and refused["halted"] is False
        assert allowed == {"type": "allow", "seq": 1}
