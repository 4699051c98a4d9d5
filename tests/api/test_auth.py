"""API keys and roles: who may call what, in `auth=open` and `auth=keys` mode, and the CLI."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from fastapi import APIRouter, Depends, FastAPI, WebSocket
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect
from typer.testing import CliRunner

from app.api.deps import CuratorKey, robot_writes
from app.cli import cli
from app.config import Settings
from app.main import create_app
from app.services.access import issue_api_key
from app.store import Repository, create_engine_for, hash_api_key
from app.store.records import ApiKeyRole

GATE_REQUEST: dict[str, Any] = {
    "command": "put the apple in the fridge",
    "scene": {"objects": [{"id": "apple_1", "type": "Apple", "room": "kitchen"},
                          {"id": "fridge_1", "type": "Fridge", "room": "kitchen"}]},
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place", "open", "close"]},
}


def _with_test_websockets(app: FastAPI) -> FastAPI:
    @app.websocket("/test/ws-open")
    async def plain(websocket: WebSocket) -> None:  # guarded only by the app-wide check
        await websocket.accept()
        await websocket.send_text("hello")
        await websocket.close()

    @app.websocket("/test/ws-curators")
    async def curators(websocket: WebSocket, _: CuratorKey) -> None:
        await websocket.accept()
        await websocket.send_text("hello curator")
        await websocket.close()

    robots = APIRouter()

    @robots.websocket("/test/ws-robots")
    async def robot_only(websocket: WebSocket) -> None:  # a robot router, like the monitor's
        await websocket.accept()
        await websocket.send_text("hello robot")
        await websocket.close()

    app.include_router(robots, dependencies=[Depends(robot_writes)])
    return app


@pytest.fixture
def locked(sqlite_url: str) -> Iterator[TestClient]:
    """A client on an app with `auth=keys`."""
    app = _with_test_websockets(create_app(Settings(database_url=sqlite_url, auth="keys")))
    with TestClient(app) as test_client:
        yield test_client


def key(client: TestClient, role: ApiKeyRole) -> str:
    access = client.app.state.components.repositories.access  # type: ignore[attr-defined]
    return issue_api_key(access, role, f"test {role.value}")[1]


def bearer(secret: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {secret}"}


class TestKeysMode:
    def test_every_endpoint_needs_a_key(self, locked: TestClient) -> None:
        for method, path in [("GET", "/templates"), ("GET", "/vocabulary"),
                             ("GET", "/extensions/pending"), ("POST", "/gate")]:
            answer = locked.request(method, path, json=GATE_REQUEST)
            assert answer.status_code == 401, path
            assert answer.headers["content-type"].startswith("application/problem+json")

    @pytest.mark.parametrize("path", ["/openapi.json", "/docs", "/redoc",
                                      "/docs/oauth2-redirect"])
    def test_the_schema_and_docs_need_a_key(self, locked: TestClient, path: str) -> None:
        refused = locked.get(path)
        assert refused.status_code == 401
        assert refused.headers["content-type"].startswith("application/problem+json")
        assert locked.get(path, headers=bearer(key(locked, ApiKeyRole.ROBOT))).status_code == 200

    def test_the_schema_is_the_apis_and_hides_nothing_new(self, locked: TestClient) -> None:
        schema = locked.get("/openapi.json", headers=bearer(key(locked, ApiKeyRole.CURATOR)))
        paths = schema.json()["paths"]
        assert "/gate" in paths and "/verify" in paths
        assert not {"/openapi.json", "/docs", "/redoc"} & set(paths)

    def test_a_setting_opens_the_schema_and_docs(self, sqlite_url: str) -> None:
        settings = Settings(database_url=sqlite_url, auth="keys", public_docs=True)
        with TestClient(create_app(settings)) as client:
            for path in ("/openapi.json", "/docs", "/redoc"):
                assert client.get(path).status_code == 200, path
            assert client.get("/templates").status_code == 401  # and nothing else

    def test_probes_and_page_shell_stay_open(self, locked: TestClient) -> None:
        for path in ("/healthz", "/readyz", "/curator", "/curator/static/curator.js"):
            assert locked.get(path).status_code == 200, path

    def test_robot_key_gates_and_reads(self, locked: TestClient) -> None:
        headers = bearer(key(locked, ApiKeyRole.ROBOT))
        decided = locked.post("/gate", json=GATE_REQUEST, headers=headers)
        assert decided.status_code == 200
        assert locked.get(f"/gate/{decided.json()['request_id']}", headers=headers).is_success
        assert locked.get("/templates", headers=headers).status_code == 200

    def test_curator_key_cannot_gate(self, locked: TestClient) -> None:
        curator = bearer(key(locked, ApiKeyRole.CURATOR))
        answer = locked.post("/gate", json=GATE_REQUEST, headers=curator)
        assert answer.status_code == 403

    def test_x_api_key_header_is_accepted(self, locked: TestClient) -> None:
        secret = key(locked, ApiKeyRole.ROBOT)
        assert locked.get("/templates", headers={"X-API-Key": secret}).status_code == 200

    def test_revoked_key_is_refused(self, locked: TestClient) -> None:
        repository = Repository(locked.app.state.components.engine)  # type: ignore[attr-defined]
        record, secret = issue_api_key(repository, ApiKeyRole.ROBOT, "old")
        repository.revoke_api_key(record.id)
        assert locked.get("/templates", headers=bearer(secret)).status_code == 401

    def test_websocket_without_a_key_is_refused(self, locked: TestClient) -> None:
        with pytest.raises(WebSocketDisconnect) as refused, \
                locked.websocket_connect("/test/ws-open"):
            pass
        assert refused.value.code == 1008
        secret = key(locked, ApiKeyRole.ROBOT)
        with locked.websocket_connect("/test/ws-open", headers=bearer(secret)) as socket:
            assert socket.receive_text() == "hello"
        with locked.websocket_connect(f"/test/ws-open?api_key={secret}") as socket:
            assert socket.receive_text() == "hello"

    def test_authorize_websocket_checks_the_role(self, locked: TestClient) -> None:
        with pytest.raises(WebSocketDisconnect) as refused, locked.websocket_connect(
            "/test/ws-curators", headers=bearer(key(locked, ApiKeyRole.ROBOT))
        ):
            pass
        assert refused.value.code == 1008
        with locked.websocket_connect(
            "/test/ws-curators", headers=bearer(key(locked, ApiKeyRole.CURATOR))
        ) as socket:
            assert socket.receive_text() == "hello curator"


    def test_robot_router_websocket_refuses_other_roles(self, locked: TestClient) -> None:
        with pytest.raises(WebSocketDisconnect) as refused, locked.websocket_connect(
            "/test/ws-robots", headers=bearer(key(locked, ApiKeyRole.CURATOR))
        ):
            pass
        assert refused.value.code == 1008
        with locked.websocket_connect(
            "/test/ws-robots", headers=bearer(key(locked, ApiKeyRole.ROBOT))
        ) as socket:
            assert socket.receive_text() == "hello robot"


class TestOpenMode:
    def test_gate_and_reads_need_no_key(self, client: TestClient) -> None:
        assert client.post("/gate", json=GATE_REQUEST).status_code == 200
        assert client.get("/templates").status_code == 200

    def test_the_schema_and_docs_need_no_key(self, client: TestClient) -> None:
        for path in ("/openapi.json", "/docs", "/redoc"):
            assert client.get(path).status_code == 200, path
        assert "swagger-ui" in client.get("/docs").text

    def test_a_presented_key_is_still_checked(self, client: TestClient) -> None:
        assert client.get("/templates", headers=bearer("sg_not_a_key")).status_code == 401
        malformed = {"Authorization": "Basic dXNlcjpwYXNz"}
        assert client.get("/templates", headers=malformed).status_code == 401

    def test_keys_endpoints_need_an_admin(self, client: TestClient) -> None:
        assert client.get("/keys").status_code == 401
        curator = bearer(key(client, ApiKeyRole.CURATOR))
        assert client.get("/keys", headers=curator).status_code == 403
        admin = bearer(key(client, ApiKeyRole.ADMIN))
        created = client.post("/keys", json={"role": "robot", "name": "arm"}, headers=admin).json()
        assert client.get("/keys/me", headers=bearer(created["key"])).json()["role"] == "robot"
        listed = client.get("/keys", headers=admin).json()["keys"]
        assert all("key" not in k and "key_hash" not in k for k in listed)
        client.delete(f"/keys/{created['id']}", headers=admin)
        assert client.get("/keys/me", headers=bearer(created["key"])).status_code == 401


class TestKeysCommand:
    def test_create_list_revoke(self, sqlite_url: str) -> None:
        runner = CliRunner()
        env = {"SAFEGATE_DATABASE_URL": sqlite_url}
        created = runner.invoke(cli, ["keys", "create", "--role", "curator", "--name", "ann"],
                                env=env)
        assert created.exit_code == 0, created.output
        secret = created.stdout.strip().splitlines()[0]
        repository = Repository(create_engine_for(sqlite_url))
        stored = repository.find_active_api_key(hash_api_key(secret))
        assert stored is not None and stored.role is ApiKeyRole.CURATOR
        assert secret not in {k.key_hash for k in repository.list_api_keys()}
        listed = runner.invoke(cli, ["keys", "list"], env=env)
        assert stored.id in listed.stdout and secret not in listed.stdout
        revoked = runner.invoke(cli, ["keys", "revoke", stored.id], env=env)
        assert revoked.exit_code == 0
        assert repository.find_active_api_key(hash_api_key(secret)) is None

    def test_unknown_role_is_refused(self, sqlite_url: str) -> None:
        result = CliRunner().invoke(cli, ["keys", "create", "--role", "root"],
                                    env={"SAFEGATE_DATABASE_URL": sqlite_url})
        assert result.exit_code != 0
