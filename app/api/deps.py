"""Dependencies for routes, as `Annotated` aliases: the services, and who may call.

`ServicesDep` is the services built in the lifespan (works on HTTP and websocket routes);
`PoolDep` the analysis pool the deciding routes run Stages 1-5 in.
`SecretDep` is the key the caller presented, read by FastAPI's `HTTPBearer` and `APIKeyHeader`
(so the OpenAPI document declares both schemes). Access, by role (see `app/api/auth.py` for the
rules and the 401/403 answers):
- `ReadAccess`: reads; open in `auth=open`, any valid key with `auth=keys`.
- `RobotAccess`: gate, answers, verify, monitor; open in `auth=open`, else robot or admin.
- `CuratorKey`: template writes and re-evaluation; always a curator or admin key.
- `AdminKey`: key management; always an admin key.
- `AnyKey`: always some valid key (e.g. "who am I").
`robot_writes` is the router-wide form for robot routers (reads as `ReadAccess`, the rest as
`RobotAccess`). `require_key_when_locked` is installed app-wide by `create_app`, so with
`auth=keys` no route, websockets included, answers without a valid key, whatever its own
dependencies say.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Annotated

from fastapi import Depends, Security
from fastapi.security import HTTPAuthorizationCredentials
from starlette.concurrency import run_in_threadpool
from starlette.exceptions import WebSocketException
from starlette.requests import HTTPConnection
from starlette.status import WS_1008_POLICY_VIOLATION

from app.api.auth import (
    ADMIN_ROLES,
    ANY_ROLE,
    CURATOR_ROLES,
    ROBOT_ROLES,
    api_key_scheme,
    authorize,
    bearer_scheme,
    is_open_path,
    lookup_pending,
    presented_secret,
)
from app.domain.errors import SafeGateError
from app.services import Services
from app.services.analysis_pool import AnalysisPool
from app.store.records import ApiKeyRecord, ApiKeyRole

_READ_METHODS = frozenset({"GET", "HEAD", "OPTIONS"})


async def get_services(connection: HTTPConnection) -> Services:
    services: Services = connection.app.state.services
    return services


ServicesDep = Annotated[Services, Depends(get_services)]


async def get_analysis_pool(connection: HTTPConnection) -> AnalysisPool:
    pool: AnalysisPool = connection.app.state.analysis_pool
    return pool


PoolDep = Annotated[AnalysisPool, Depends(get_analysis_pool)]


async def get_presented_secret(
    connection: HTTPConnection,
    services: ServicesDep,
    bearer: Annotated[HTTPAuthorizationCredentials | None, Security(bearer_scheme)],
    header_key: Annotated[str | None, Security(api_key_scheme)],
) -> str | None:
    """The key the caller presented (FastAPI caches it per request for every dependency).

    On the open paths (probes, the page shell) whatever was sent is ignored, as before.
    """
    if is_open_path(connection.url.path, public_docs=services.settings.public_docs):
        return None
    try:
        return presented_secret(connection, bearer, header_key)
    except SafeGateError as error:
        if connection.scope.get("type") == "websocket":
            raise WebSocketException(WS_1008_POLICY_VIOLATION, reason=error.detail) from error
        raise


SecretDep = Annotated[str | None, Depends(get_presented_secret)]


def _authorize_now(
    connection: HTTPConnection,
    services: Services,
    roles: frozenset[ApiKeyRole],
    open_when_open: bool,
    secret: str | None,
) -> ApiKeyRecord | None:
    try:
        return authorize(connection, services, roles, open_when_open=open_when_open,
                         secret=secret)
    except SafeGateError as error:
        if connection.scope.get("type") == "websocket":
            raise WebSocketException(WS_1008_POLICY_VIOLATION, reason=error.detail) from error
        raise


async def _authorize(
    connection: HTTPConnection,
    services: Services,
    roles: frozenset[ApiKeyRole],
    *,
    open_when_open: bool,
    secret: str | None,
) -> ApiKeyRecord | None:
    # Dependencies are async so the hot path (no key, or one already checked) costs no worker
    # thread; only a key's first database lookup is sent to one.
    if lookup_pending(connection, secret):
        return await run_in_threadpool(
            _authorize_now, connection, services, roles, open_when_open, secret)
    return _authorize_now(connection, services, roles, open_when_open, secret)


def require_role(
    *roles: ApiKeyRole,
) -> Callable[[HTTPConnection, Services, str | None], Awaitable[ApiKeyRecord]]:
    """A dependency that always needs a key with one of `roles` (401 without, 403 if wrong)."""
    accepted = frozenset(roles)

    async def dependency(connection: HTTPConnection, services: ServicesDep,
                         secret: SecretDep) -> ApiKeyRecord:
        key = await _authorize(connection, services, accepted, open_when_open=False,
                               secret=secret)
        assert key is not None  # authorize raises rather than answer None here
        return key

    return dependency


def allow_open(
    *roles: ApiKeyRole,
) -> Callable[[HTTPConnection, Services, str | None], Awaitable[ApiKeyRecord | None]]:
    """A dependency open in `auth=open` mode (None) that needs one of `roles` with `auth=keys`."""
    accepted = frozenset(roles)

    async def dependency(
        connection: HTTPConnection, services: ServicesDep, secret: SecretDep
    ) -> ApiKeyRecord | None:
        return await _authorize(connection, services, accepted, open_when_open=True,
                                secret=secret)

    return dependency


async def require_key_when_locked(connection: HTTPConnection, services: ServicesDep,
                                  secret: SecretDep) -> None:
    """App-wide: with `auth=keys` every route but the probes and the page shell needs a key."""
    if not is_open_path(connection.url.path, public_docs=services.settings.public_docs):
        await _authorize(connection, services, ANY_ROLE, open_when_open=True, secret=secret)


async def robot_writes(
    connection: HTTPConnection, services: ServicesDep, secret: SecretDep
) -> ApiKeyRecord | None:
    """Router-wide access for robot routers: reads as `ReadAccess`, the rest as `RobotAccess`.

    Install with `app.include_router(router, dependencies=[Depends(robot_writes)])`; websocket
    routes of such a router count as robot operations.
    """
    reading = connection.scope.get("method") in _READ_METHODS
    return await _authorize(
        connection, services, ANY_ROLE if reading else ROBOT_ROLES, open_when_open=True,
        secret=secret)


ReadAccess = Annotated[ApiKeyRecord | None, Depends(allow_open(*ANY_ROLE))]
RobotAccess = Annotated[ApiKeyRecord | None, Depends(allow_open(*ROBOT_ROLES))]
CuratorKey = Annotated[ApiKeyRecord, Depends(require_role(*CURATOR_ROLES))]
AdminKey = Annotated[ApiKeyRecord, Depends(require_role(*ADMIN_ROLES))]
AnyKey = Annotated[ApiKeyRecord, Depends(require_role(*ANY_ROLE))]
