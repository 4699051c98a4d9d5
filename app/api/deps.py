"""Dependencies for routes: one `Annotated` alias per service, and who may call.

The services are built once in the lifespan (`app.services.container.build_components`, the
analysis pool, the monitoring service, the gatekeeper) and kept on `app.state`; each alias
below hands a route exactly one of them, so a route names what it uses and nothing else:
`SettingsDep`, `MetricsDep`, `PoolDep` (the analysis pool the deciding routes run Stages 1-5
in), `AuditTrailDep`, `CurationDep`, `CatalogDep`, `ExtensionsDep`, `KeysDep`, `ReadinessDep`,
`MonitoringDep` and `GatekeeperDep`. They work on HTTP and websocket routes alike.

Access, by role (see `app/api/auth.py` for the rules and the 401/403 answers). Each alias
declares the route's `Access` and gives the route the key the app-wide check let through:
- `ReadAccess`: reads; open in `auth=open`, any valid key with `auth=keys`.
- `RobotAccess`: gate, answers, verify, monitor; open in `auth=open`, else robot or admin.
- `CuratorKey`: template writes and re-evaluation; always a curator or admin key.
- `AdminKey`: key management; always an admin key.
- `AnyKey`: always some valid key (e.g. "who am I").
`robot_writes` is the router-wide declaration for robot routers (reads as `ReadAccess`, the
rest, websockets included, as `RobotAccess`). `check_access`, installed app-wide by
`create_app`, is the one check per request: it holds the caller against everything the matched
route declares, so with `auth=keys` no route answers without a valid key, whatever it declares.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Annotated, cast

from fastapi import Depends, Security
from fastapi.security import HTTPAuthorizationCredentials
from starlette.concurrency import run_in_threadpool
from starlette.requests import HTTPConnection

from app.api.auth import (
    ADMIN_ROLES,
    ANY_ROLE,
    CURATOR_ROLES,
    ROBOT_ROLES,
    Access,
    Gatekeeper,
    api_key_scheme,
    as_websocket_error,
    bearer_scheme,
    checked_key,
    lookup_pending,
    presented_secret,
)
from app.config import Settings
from app.domain.errors import SafeGateError
from app.metrics import Metrics
from app.services import Components
from app.services.access import KeyService
from app.services.analysis_pool import AnalysisPool
from app.services.audit_trail import AuditTrail
from app.services.curation import CurationService
from app.services.extensions import ExtensionService
from app.services.monitoring import MonitorService
from app.services.readiness import ReadinessProbe
from app.services.template_catalog import TemplateCatalog
from app.store.records import ApiKeyRecord


def _components(connection: HTTPConnection) -> Components:
    return cast(Components, connection.app.state.components)


async def get_settings(connection: HTTPConnection) -> Settings:
    return cast(Settings, connection.app.state.settings)


async def get_metrics(connection: HTTPConnection) -> Metrics:
    return _components(connection).metrics


async def get_analysis_pool(connection: HTTPConnection) -> AnalysisPool:
    return cast(AnalysisPool, connection.app.state.analysis_pool)


async def get_audit_trail(connection: HTTPConnection) -> AuditTrail:
    return _components(connection).audit_trail


async def get_curation(connection: HTTPConnection) -> CurationService:
    return _components(connection).curation


async def get_catalog(connection: HTTPConnection) -> TemplateCatalog:
    return _components(connection).catalog


async def get_extensions(connection: HTTPConnection) -> ExtensionService:
    return _components(connection).deciders.extensions


async def get_keys(connection: HTTPConnection) -> KeyService:
    return _components(connection).keys


async def get_readiness(connection: HTTPConnection) -> ReadinessProbe:
    return _components(connection).readiness


async def get_monitoring(connection: HTTPConnection) -> MonitorService:
    return cast(MonitorService, connection.app.state.monitoring)


async def get_gatekeeper(connection: HTTPConnection) -> Gatekeeper:
    return cast(Gatekeeper, connection.app.state.gatekeeper)


SettingsDep = Annotated[Settings, Depends(get_settings)]
MetricsDep = Annotated[Metrics, Depends(get_metrics)]
PoolDep = Annotated[AnalysisPool, Depends(get_analysis_pool)]
AuditTrailDep = Annotated[AuditTrail, Depends(get_audit_trail)]
CurationDep = Annotated[CurationService, Depends(get_curation)]
CatalogDep = Annotated[TemplateCatalog, Depends(get_catalog)]
ExtensionsDep = Annotated[ExtensionService, Depends(get_extensions)]
KeysDep = Annotated[KeyService, Depends(get_keys)]
ReadinessDep = Annotated[ReadinessProbe, Depends(get_readiness)]
MonitoringDep = Annotated[MonitorService, Depends(get_monitoring)]
GatekeeperDep = Annotated[Gatekeeper, Depends(get_gatekeeper)]


async def get_presented_secret(
    connection: HTTPConnection,
    gatekeeper: GatekeeperDep,
    bearer: Annotated[HTTPAuthorizationCredentials | None, Security(bearer_scheme)],
    header_key: Annotated[str | None, Security(api_key_scheme)],
) -> str | None:
    """The key the caller presented (FastAPI caches it per request for every dependency).

    On the open paths (probes, the page shell) whatever was sent is ignored, as before.
    """
    if gatekeeper.is_open(connection):
        return None
    try:
        return presented_secret(connection, bearer, header_key)
    except SafeGateError as error:
        raise as_websocket_error(connection, error) from error


SecretDep = Annotated[str | None, Depends(get_presented_secret)]


async def check_access(connection: HTTPConnection, gatekeeper: GatekeeperDep,
                       secret: SecretDep) -> None:
    """App-wide, once per request: the caller against every `Access` the route declares."""
    if gatekeeper.is_open(connection):
        gatekeeper.open_path_checked(connection)
        return
    required = gatekeeper.routes.of(connection.scope.get("route"))
    try:
        # Async so the hot path (no key, or one already looked up on this connection) costs
        # no worker thread; only a key's first database lookup is sent to one.
        if lookup_pending(connection, secret):
            await run_in_threadpool(gatekeeper.check, connection, required, secret)
        else:
            gatekeeper.check(connection, required, secret)
    except SafeGateError as error:
        raise as_websocket_error(connection, error) from error


def _declaring(access: Access) -> Callable[[HTTPConnection], Awaitable[ApiKeyRecord | None]]:
    """A dependency that declares `access` for its route and answers the checked key."""

    async def dependency(connection: HTTPConnection) -> ApiKeyRecord | None:
        try:
            return checked_key(connection)
        except SafeGateError as error:
            raise as_websocket_error(connection, error) from error

    dependency.safegate_access = access  # type: ignore[attr-defined]
    return dependency


def _requiring(access: Access) -> Callable[[HTTPConnection], Awaitable[ApiKeyRecord]]:
    """Like `_declaring`, for an `access` that always needs a key."""
    declared = _declaring(access)

    async def dependency(connection: HTTPConnection) -> ApiKeyRecord:
        key = await declared(connection)
        assert key is not None  # the check refuses a keyless caller here
        return key

    dependency.safegate_access = access  # type: ignore[attr-defined]
    return dependency


robot_writes = _declaring(Access(ROBOT_ROLES, open_when_open=True, reads=ANY_ROLE))
"""Install with `app.include_router(router, dependencies=[Depends(robot_writes)])`."""

ReadAccess = Annotated[ApiKeyRecord | None,
                       Depends(_declaring(Access(ANY_ROLE, open_when_open=True)))]
RobotAccess = Annotated[ApiKeyRecord | None,
                        Depends(_declaring(Access(ROBOT_ROLES, open_when_open=True)))]
CuratorKey = Annotated[ApiKeyRecord,
                       Depends(_requiring(Access(CURATOR_ROLES, open_when_open=False)))]
AdminKey = Annotated[ApiKeyRecord,
                     Depends(_requiring(Access(ADMIN_ROLES, open_when_open=False)))]
AnyKey = Annotated[ApiKeyRecord, Depends(_requiring(Access(ANY_ROLE, open_when_open=False)))]
