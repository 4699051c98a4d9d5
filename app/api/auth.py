"""API keys on HTTP and websocket connections: who is calling, and may they?

In: a connection's `Authorization: Bearer <key>` or `X-API-Key` header, read by FastAPI's
`HTTPBearer` and `APIKeyHeader` (which also declare both security schemes in the OpenAPI
document), for websockets also an `api_key` query parameter (browsers cannot set headers on
them); the services (settings and
repository) and the roles an endpoint accepts. Out: the caller's `ApiKeyRecord`, or None for an
endpoint left open in `auth=open` mode. Fails: `Unauthorized` (401) when a key is needed and
missing, or presented but unknown, revoked or malformed (a presented key is always checked, even
where none is needed); `Forbidden` (403) when the key's role is not accepted. On websockets both
become a `WebSocketException` with close code 1008 before the handshake is accepted.

Roles: robot (gate, answers, verify, monitor), curator (template writes, re-evaluation), admin
(keys, and everything the others may do). Template writes and re-evaluation always need a key;
with `auth=keys` every endpoint does, except the probes and the curator page's static shell
(it holds no data; the page calls the API with the key the curator types in). The OpenAPI schema
and the docs pages need a key too unless `SAFEGATE_PUBLIC_DOCS=true` opens them.
"""

from __future__ import annotations

from collections.abc import Collection, MutableMapping
from typing import Any

from fastapi.security import APIKeyHeader, HTTPAuthorizationCredentials, HTTPBearer
from starlette.exceptions import WebSocketException
from starlette.requests import HTTPConnection
from starlette.status import WS_1008_POLICY_VIOLATION
from starlette.websockets import WebSocket

from app.api.docs import DOCS_PATHS
from app.domain.errors import Forbidden, SafeGateError, Unauthorized
from app.services import Services
from app.services.access import find_key
from app.store.records import ApiKeyRecord, ApiKeyRole

ROBOT_ROLES = frozenset({ApiKeyRole.ROBOT, ApiKeyRole.ADMIN})
CURATOR_ROLES = frozenset({ApiKeyRole.CURATOR, ApiKeyRole.ADMIN})
ADMIN_ROLES = frozenset({ApiKeyRole.ADMIN})
ANY_ROLE = frozenset(ApiKeyRole)

OPEN_PATHS = frozenset({"/healthz", "/readyz", "/curator", "/curator/"})
OPEN_PREFIXES = ("/curator/static/",)
_CACHE_ATTRIBUTE = "safegate_api_key"
_HOW = "send 'Authorization: Bearer <key>' or 'X-API-Key: <key>'"


bearer_scheme = HTTPBearer(
    scheme_name="BearerKey", auto_error=False,
    description="An API key as `Authorization: Bearer <key>` (`safegate keys create --role ...`). "
                "With `SAFEGATE_AUTH=open` (the embedded default) reads, the gate, `/verify` "
                "and the monitor need none; template writes and `/keys` always do.")
api_key_scheme = APIKeyHeader(
    name="X-API-Key", scheme_name="ApiKeyHeader", auto_error=False,
    description="The same API key as an `X-API-Key` header (websockets also take an `api_key` "
                "query parameter, since browsers cannot set their headers).")


def presented_secret(connection: HTTPConnection, bearer: HTTPAuthorizationCredentials | None,
                     header_key: str | None) -> str | None:
    """The key the client sent, or None when it sent none.

    Args:
        connection: the HTTP request or websocket.
        bearer: what `bearer_scheme` read (None for no `Authorization` header, or one that is
            not `Bearer <key>`).
        header_key: what `api_key_scheme` read (None for no or an empty `X-API-Key`).

    Raises:
        Unauthorized: an `Authorization` header that is not `Bearer <key>`.
    """
    headers = connection.headers
    if "authorization" in headers:
        token = "" if bearer is None else bearer.credentials.strip()
        if not token:
            raise Unauthorized(f"malformed Authorization header; {_HOW}")
        return token
    if header_key is not None or "x-api-key" in headers:
        # An empty X-API-Key is a key that is presented and matches none.
        return (header_key or "").strip()
    if connection.scope.get("type") == "websocket":
        return connection.query_params.get("api_key")
    return None


def lookup_pending(connection: HTTPConnection, secret: str | None) -> bool:
    """Whether `authenticate` would query the database: a key was sent and not yet looked up.

    Async callers use it to stay on the event loop for the common cases (no key, or a key
    already checked on this connection) and go to a worker thread only for the lookup.
    """
    return secret is not None and _CACHE_ATTRIBUTE not in connection.scope.get("state", {})


def cached_key(scope: MutableMapping[str, Any]) -> ApiKeyRecord | None:
    """The key this connection was authenticated with, or None (none sent, or not checked yet)."""
    key: ApiKeyRecord | None = scope.get("state", {}).get(_CACHE_ATTRIBUTE)
    return key


def authenticate(connection: HTTPConnection, services: Services,
                 secret: str | None = None) -> ApiKeyRecord | None:
    """The caller's active key (looked up once per connection), or None when none was sent.

    The first call on a connection is the app-wide dependency's, with the `secret` it read
    through the security schemes (`presented_secret`); later calls (a route's own check, e.g.
    `authorize_websocket`) get the key it found.

    Raises:
        Unauthorized: a key was sent but is unknown, revoked or malformed.
    """
    state = connection.scope.setdefault("state", {})
    if _CACHE_ATTRIBUTE in state:
        cached: ApiKeyRecord | None = state[_CACHE_ATTRIBUTE]
        return cached
    key = None
    if secret is not None:
        key = find_key(services.repository, secret)
        if key is None:
            raise Unauthorized("the API key is unknown or revoked")
    state[_CACHE_ATTRIBUTE] = key
    return key


def authorize(
    connection: HTTPConnection,
    services: Services,
    roles: Collection[ApiKeyRole],
    *,
    open_when_open: bool,
    secret: str | None = None,
) -> ApiKeyRecord | None:
    """Check the caller against the roles an endpoint accepts.

    Args:
        connection: the HTTP request or websocket.
        services: the app's services (settings and repository).
        roles: the roles accepted.
        open_when_open: True when the endpoint needs no key in `auth=open` mode.
        secret: the key presented, as `presented_secret` read it (see `authenticate`).

    Returns:
        The caller's key, or None when the endpoint is open and no key was sent.

    Raises:
        Unauthorized: a key is needed and missing, or the key sent is not valid.
        Forbidden: the key's role is not among `roles`.
    """
    key = authenticate(connection, services, secret)
    if key is None:
        if open_when_open and services.settings.auth == "open":
            return None
        raise Unauthorized(f"this endpoint needs an API key; {_HOW}")
    if key.role not in roles:
        wanted = " or ".join(sorted(role.value for role in roles))
        raise Forbidden(f"a {key.role.value} key may not do this; it needs a {wanted} key")
    return key


def is_open_path(path: str, *, public_docs: bool = False) -> bool:
    """Whether a path needs no key even with `auth=keys`: the probes, the page's static shell,
    and the schema and docs pages when `public_docs` (SAFEGATE_PUBLIC_DOCS) opens them."""
    return (path in OPEN_PATHS or path.startswith(OPEN_PREFIXES)
            or (public_docs and path in DOCS_PATHS))


def authorize_websocket(
    websocket: WebSocket,
    services: Services,
    roles: Collection[ApiKeyRole] = ROBOT_ROLES,
    *,
    open_when_open: bool = True,
) -> ApiKeyRecord | None:
    """`authorize` for a websocket; call it before `websocket.accept()`.

    Args:
        websocket: the connection, whose key (header or `api_key` query parameter) the
            app-wide dependency has read already; without it, no key counts as sent.
        services: the app's services.
        roles: the roles accepted (robots by default: the monitor's clients).
        open_when_open: True when no key is needed in `auth=open` mode.

    Returns:
        The caller's key, or None when the endpoint is open and no key was sent.

    Raises:
        WebSocketException: code 1008 (policy violation) with the reason; Starlette then
            refuses the handshake.
    """
    try:
        return authorize(websocket, services, roles, open_when_open=open_when_open)
    except SafeGateError as error:
        raise WebSocketException(WS_1008_POLICY_VIOLATION, reason=error.detail) from error
