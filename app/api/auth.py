"""API keys on HTTP and websocket connections: who is calling, and may they? Checked once.

In: a connection's `Authorization: Bearer <key>` or `X-API-Key` header, read by FastAPI's
`HTTPBearer` and `APIKeyHeader` (which also declare both security schemes in the OpenAPI
document), for websockets also an `api_key` query parameter (browsers cannot set headers on
them); the `Access` each route declares (through the aliases of `app/api/deps.py`). Out: the
caller's `ApiKeyRecord`, or None for an endpoint left open in `auth=open` mode.
One app-wide dependency runs the check once per request: the `Gatekeeper` looks the key up
(once per connection) and holds it against every `Access` the matched route declares (a route
that declares none needs what every route needs: any valid key with `auth=keys`); the route's
own alias then only reads the key it let through.
Fails: `Unauthorized` (401) when a key is needed and missing, or presented but unknown, revoked
or malformed (a presented key is always checked, even where none is needed); `Forbidden` (403)
when the key's role is not accepted. On websockets both become a `WebSocketException` with close
code 1008 before the handshake is accepted.

Roles: robot (gate, answers, verify, monitor), curator (template writes, re-evaluation), admin
(keys, and everything the others may do). Template writes and re-evaluation always need a key;
with `auth=keys` every endpoint does, except the probes and the curator page's static shell
(it holds no data; the page calls the API with the key the curator types in). The OpenAPI schema
and the docs pages need a key too unless `SAFEGATE_PUBLIC_DOCS=true` opens them.
"""

from __future__ import annotations

from collections.abc import Collection, MutableMapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal

from fastapi.routing import iter_route_contexts
from fastapi.security import APIKeyHeader, HTTPAuthorizationCredentials, HTTPBearer
from starlette.exceptions import WebSocketException
from starlette.requests import HTTPConnection
from starlette.routing import BaseRoute
from starlette.status import WS_1008_POLICY_VIOLATION

from app.api.docs import DOCS_PATHS
from app.domain.errors import Forbidden, SafeGateError, Unauthorized
from app.services.access import KeyService
from app.store.records import ApiKeyRecord, ApiKeyRole

ROBOT_ROLES = frozenset({ApiKeyRole.ROBOT, ApiKeyRole.ADMIN})
CURATOR_ROLES = frozenset({ApiKeyRole.CURATOR, ApiKeyRole.ADMIN})
ADMIN_ROLES = frozenset({ApiKeyRole.ADMIN})
ANY_ROLE = frozenset(ApiKeyRole)

OPEN_PATHS = frozenset({"/healthz", "/readyz", "/curator", "/curator/"})
OPEN_PREFIXES = ("/curator/static/",)
_CACHE_ATTRIBUTE = "safegate_api_key"
_CHECKED_ATTRIBUTE = "safegate_access_checked"
_READ_METHODS = frozenset({"GET", "HEAD", "OPTIONS"})
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


@dataclass(frozen=True)
class Access:
    """What a route accepts: the roles, and whether `auth=open` lets it be called keyless.

    `reads` (when set) are the roles accepted for GET, HEAD and OPTIONS instead of `roles`
    (a robot router: anyone may read, robots write; websockets count as writes).
    """

    roles: frozenset[ApiKeyRole]
    open_when_open: bool
    reads: frozenset[ApiKeyRole] | None = None

    def roles_for(self, connection: HTTPConnection) -> frozenset[ApiKeyRole]:
        if self.reads is not None and connection.scope.get("method") in _READ_METHODS:
            return self.reads
        return self.roles


EVERY_ROUTE = Access(ANY_ROLE, open_when_open=True)
"""What every route needs, declared or not: nothing in `auth=open`, any valid key otherwise."""


def _declared_in(dependant: object) -> list[Access]:
    """The `Access` values a dependant's dependencies carry as `safegate_access`, at any depth."""
    found: list[Access] = []
    pending = list(getattr(dependant, "dependencies", ()))
    while pending:
        dependency = pending.pop()
        access = getattr(dependency.call, "safegate_access", None)
        if isinstance(access, Access):
            found.append(access)
        pending.extend(dependency.dependencies)
    return found


class RouteAccess:
    """What each route of an app declares, its routers' dependencies included.

    Built once the routes are in place (in the lifespan): a route included through a router
    is matched as the router's own route object, whose dependencies lack those its inclusion
    added (`include_router(..., dependencies=...)`), so they are read here from FastAPI's
    effective routes. A route added later is read from its own dependencies.
    """

    def __init__(self, routes: Sequence[BaseRoute]) -> None:
        self._table: dict[int, tuple[BaseRoute, list[Access]]] = {}
        for context in iter_route_contexts(routes):
            original = context.original_route
            entry = self._table.setdefault(id(original), (original, []))
            # A route included twice holds the requirements of both inclusions.
            entry[1].extend(_declared_in(getattr(context, "dependant", None)))

    def of(self, route: object) -> tuple[Access, ...]:
        """The requirements of the matched route (`scope["route"]`)."""
        entry = self._table.get(id(route))
        if entry is not None and entry[0] is route:
            return tuple(entry[1])
        return tuple(_declared_in(getattr(route, "dependant", None)))


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


def checked_key(connection: HTTPConnection) -> ApiKeyRecord | None:
    """The key the app-wide check let through on this connection (None: open, none sent).

    Raises:
        Unauthorized: no check ran on this connection (an app built without it): fail closed.
    """
    if not connection.scope.get("state", {}).get(_CHECKED_ATTRIBUTE):
        raise Unauthorized("the API key was not checked on this connection")
    return cached_key(connection.scope)


def is_open_path(path: str, *, public_docs: bool = False) -> bool:
    """Whether a path needs no key even with `auth=keys`: the probes, the page's static shell,
    and the schema and docs pages when `public_docs` (SAFEGATE_PUBLIC_DOCS) opens them."""
    return (path in OPEN_PATHS or path.startswith(OPEN_PREFIXES)
            or (public_docs and path in DOCS_PATHS))


class Gatekeeper:
    """Checks callers against routes' `Access`, looking each connection's key up once."""

    def __init__(self, keys: KeyService, routes: RouteAccess, *, mode: Literal["open", "keys"],
                 public_docs: bool) -> None:
        """Args:
            keys: where presented keys are looked up.
            routes: what each route declares.
            mode: `SAFEGATE_AUTH`: `open` lets keyless callers use the open routes.
            public_docs: `SAFEGATE_PUBLIC_DOCS`: the schema and docs pages need no key.
        """
        self._keys = keys
        self.routes = routes
        self.mode = mode
        self.public_docs = public_docs

    def is_open(self, connection: HTTPConnection) -> bool:
        """Whether this connection's path needs no key at all (probes, page shell, docs)."""
        return is_open_path(connection.url.path, public_docs=self.public_docs)

    def authenticate(self, connection: HTTPConnection,
                     secret: str | None = None) -> ApiKeyRecord | None:
        """The caller's active key (looked up once per connection), or None when none was sent.

        Raises:
            Unauthorized: a key was sent but is unknown, revoked or malformed.
        """
        state = connection.scope.setdefault("state", {})
        if _CACHE_ATTRIBUTE in state:
            cached: ApiKeyRecord | None = state[_CACHE_ATTRIBUTE]
            return cached
        key = None
        if secret is not None:
            key = self._keys.find(secret)
            if key is None:
                raise Unauthorized("the API key is unknown or revoked")
        state[_CACHE_ATTRIBUTE] = key
        return key

    def check(self, connection: HTTPConnection, required: Collection[Access],
              secret: str | None) -> ApiKeyRecord | None:
        """Hold the caller against every requirement of the route, once.

        Args:
            connection: the HTTP request or websocket.
            required: what the route declares (`EVERY_ROUTE` is always added).
            secret: the key presented, as `presented_secret` read it.

        Returns:
            The caller's key, or None when every requirement is open and no key was sent.

        Raises:
            Unauthorized: a key is needed and missing, or the key sent is not valid.
            Forbidden: the key's role is not accepted by some requirement.
        """
        key = self.authenticate(connection, secret)
        for access in (EVERY_ROUTE, *required):
            self._hold(connection, key, access)
        connection.scope["state"][_CHECKED_ATTRIBUTE] = True
        return key

    def _hold(self, connection: HTTPConnection, key: ApiKeyRecord | None,
              access: Access) -> None:
        if key is None:
            if access.open_when_open and self.mode == "open":
                return
            raise Unauthorized(f"this endpoint needs an API key; {_HOW}")
        roles = access.roles_for(connection)
        if key.role not in roles:
            wanted = " or ".join(sorted(role.value for role in roles))
            raise Forbidden(f"a {key.role.value} key may not do this; it needs a {wanted} key")

    def open_path_checked(self, connection: HTTPConnection) -> None:
        """Mark an open path's connection as checked (its key, if any, is ignored)."""
        state = connection.scope.setdefault("state", {})
        state.setdefault(_CACHE_ATTRIBUTE, None)
        state[_CHECKED_ATTRIBUTE] = True


def as_websocket_error(connection: HTTPConnection, error: SafeGateError) -> Exception:
    """On a websocket, a 401/403 becomes close code 1008 before the handshake; else as is."""
    if connection.scope.get("type") == "websocket":
        return WebSocketException(WS_1008_POLICY_VIOLATION, reason=error.detail)
    return error
