"""`MonitorEvents`: a dashboard's or supervisor's view of one monitoring session (websocket).

In: SafeGate's base URL and a session id. Out: the session's events as models, the first a
`Status`, then a `ViolationEvent` when a violation halts the session and a `HaltedEvent` for
every attempt refused after it. Fails: `MonitorConnectionError` when the socket cannot be
opened, closes, or nothing arrives in time; `UnexpectedAnswer` for an event that is none of the
protocol's. Listening never allows or refuses anything.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from types import TracebackType

from pydantic import ValidationError
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import ClientConnection

from safegate_client.errors import MonitorConnectionError, UnexpectedAnswer
from safegate_client.models import HaltedEvent, Status, ViolationEvent, parse_event
from safegate_client.monitor import open_socket, websocket_url

Event = Status | ViolationEvent | HaltedEvent


class MonitorEvents:
    """A listener on a session's violations and refusals; iterate over it for events."""

    def __init__(self, base_url: str, session_id: str, *, api_key: str | None = None,
                 timeout: float = 10.0) -> None:
        """Prepare a listener (connected by `with`); `timeout` bounds the opening and `next`."""
        self.url = websocket_url(base_url, f"/monitor/{session_id}/events")
        self._api_key = api_key
        self._timeout = timeout
        self._socket: ClientConnection | None = None

    def __enter__(self) -> MonitorEvents:
        self._socket = open_socket(self.url, self._api_key, self._timeout)
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        if self._socket is not None:
            self._socket.close()

    def next(self, timeout: float | None = None) -> Event:
        """The next event (the first is the session's `Status`).

        Raises:
            MonitorConnectionError: closed, or nothing arrived within the timeout.
            UnexpectedAnswer: the event is none of the protocol's.
        """
        if self._socket is None:
            raise MonitorConnectionError("not connected: use `with MonitorEvents(...)`")
        try:
            text = self._socket.recv(timeout=timeout or self._timeout)
        except (ConnectionClosed, TimeoutError, OSError) as error:
            raise MonitorConnectionError(f"event stream ended: {error}") from error
        try:
            return parse_event(json.loads(text))
        except (ValueError, ValidationError) as error:
            raise UnexpectedAnswer(f"an event that is none of the protocol's: {error}"
                                   ) from error

    def __iter__(self) -> Iterator[Event]:
        """Every event until the stream ends (closed by the server or by `with`)."""
        while True:
            try:
                yield self.next(timeout=None)
            except MonitorConnectionError:
                return
