"""Revoking an API key closes the websockets it opened, within a second.

In: every websocket connection (a pure ASGI middleware, `RevocationMiddleware`), which learns the
key a connection was accepted with from the auth cache on its scope. Out: for a key revoked while
its websockets are open, each is closed with code 4401 (`CLOSE_KEY_REVOKED`, as 4404 is "not
found") and the reason "the API key was revoked". A key revoked through this process's
`DELETE /keys/{id}` is closed at once (`close_key`); `watching` polls the database every
`revocation_poll_seconds` (0.5 s by default, at most 1) for the keys of open websockets, which
catches keys revoked by `safegate keys revoke` or by another process or replica.
The middleware sends the close frame itself and drops whatever the route still sends after it,
so a route needs no code of its own: its next `receive()` gets the disconnect and it ends as if
the client had left.
Fails: never; a failed poll (database down) is logged and retried at the next one.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import AsyncIterator, Awaitable, Callable, MutableMapping
from dataclasses import dataclass, field
from typing import Any

import anyio.to_thread
from fastapi import FastAPI

from app.api.auth import cached_key
from app.domain.errors import SafeGateError
from app.services.access import KeyService

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]
ASGIApp = Callable[[Scope, Receive, Send], Awaitable[None]]

CLOSE_KEY_REVOKED = 4401
REVOKED_REASON = "the API key was revoked"
_log = logging.getLogger("safegate.revocations")


@dataclass(eq=False)
class _Connection:
    key_id: str
    send: Send
    closed: bool = False
    lock: asyncio.Lock = field(default_factory=asyncio.Lock)

    async def close(self) -> None:
        async with self.lock:
            if self.closed:
                return
            self.closed = True
            with contextlib.suppress(Exception):  # the client may be gone already
                await self.send({"type": "websocket.close", "code": CLOSE_KEY_REVOKED,
                                 "reason": REVOKED_REASON})


class OpenWebsockets:
    """The open websockets of each API key, in this process."""

    def __init__(self) -> None:
        self._by_key: dict[str, set[_Connection]] = {}

    def key_ids(self) -> list[str]:
        return list(self._by_key)

    def count(self) -> int:
        return sum(len(connections) for connections in self._by_key.values())

    def add(self, connection: _Connection) -> None:
        self._by_key.setdefault(connection.key_id, set()).add(connection)

    def discard(self, connection: _Connection) -> None:
        connections = self._by_key.get(connection.key_id)
        if connections is not None:
            connections.discard(connection)
            if not connections:
                del self._by_key[connection.key_id]

    async def close_key(self, key_id: str) -> int:
        """Close every websocket opened with this key; returns how many were open."""
        connections = list(self._by_key.get(key_id, ()))
        await asyncio.gather(*(connection.close() for connection in connections))
        return len(connections)


def open_websockets(app: Any) -> OpenWebsockets:
    """The app's registry of open websockets (created on first use)."""
    registry: OpenWebsockets | None = getattr(app.state, "open_websockets", None)
    if registry is None:
        registry = app.state.open_websockets = OpenWebsockets()
    return registry


class RevocationMiddleware:
    """Tracks each accepted websocket under its key; closes it when the key is revoked."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "websocket":
            await self.app(scope, receive, send)
            return
        registry = open_websockets(scope["app"])
        connection: _Connection | None = None

        async def tracked_send(message: Message) -> None:
            nonlocal connection
            if connection is not None and connection.closed:
                return  # closed for revocation: the route's last words go nowhere
            if message["type"] == "websocket.accept":
                key = cached_key(scope)
                if key is not None and key.id is not None:
                    connection = _Connection(key.id, send)
                    async with connection.lock:
                        await send(message)
                        registry.add(connection)
                    return
            if connection is None:
                await send(message)
                return
            async with connection.lock:
                if not connection.closed:
                    await send(message)

        try:
            await self.app(scope, receive, tracked_send)
        finally:
            if connection is not None:
                registry.discard(connection)


async def _poll(app: FastAPI, keys: KeyService, seconds: float) -> None:
    registry = open_websockets(app)
    while True:
        await asyncio.sleep(seconds)
        key_ids = registry.key_ids()
        if not key_ids:
            continue
        try:
            revoked = await anyio.to_thread.run_sync(
                keys.revoked, key_ids)
        except SafeGateError:
            _log.exception("could not check open websockets' keys for revocation")
            continue
        for key_id in revoked:
            closed = await registry.close_key(key_id)
            _log.info("closed %d websocket(s) of revoked key %s", closed, key_id)


@contextlib.asynccontextmanager
async def watching(app: FastAPI, keys: KeyService, poll_seconds: float) -> AsyncIterator[None]:
    """Poll for revoked keys of open websockets while the app runs."""
    task = asyncio.get_running_loop().create_task(
        _poll(app, keys, poll_seconds))
    try:
        yield
    finally:
        task.cancel()
        with contextlib.suppress(asyncio.CancelledError):
            await task
