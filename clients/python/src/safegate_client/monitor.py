"""`MonitorClient`: a robot runtime's connection to a monitoring session (sync websocket).

In: SafeGate's base URL, a session id from `GateClient.open_monitor`, and per action the action
(`{"action": "PickupObject", "object": "mug_1"}`) with optional scene observations
(`{"scene": {...}, "robot": {...}}`, partial: listed entities replace those with the same id).
Out: nothing when the monitor allows; the after-state your `execute` callback observed.
Answers are read into the models of `safegate_client.models` (`MonitorEvents` is in
`safegate_client/events.py`).
Fails: `MonitorHalted` when the session halts (now or earlier): stop the robot;
`MonitorError` when a message could not be checked (the action is not allowed), and its subclass
`MonitorResync` when it does not follow the session's last stored step;
`MonitorConnectionError` when the socket cannot be opened, closes, or answers out of order;
`UnexpectedAnswer` for an answer that is none of the protocol's (the action is not allowed).

The client numbers its messages `seq` = first_seq, first_seq + 1, ... A runtime that reconnects
to a session goes on from the session's `last_seq` + 1 (see `GateClient.monitor_summary`). After
a `MonitorResync` whose `last_seq` is not its own last finished action, it sends its whole current
state with `sync(state, seq)` and goes on from `seq` + 1.

Reconnect and resume: when the socket drops or an answer does not come in time, the client
reconnects (`reconnects` times, with a growing pause) and sends the same message again; every
answer is durable on the server before it is sent, so the message is checked against the state
the session really reached. An `after` whose first answer was lost and that the monitor already
holds (its `resync.last_seq` is that action) counts as accepted. When the monitor asks to
resynchronise and the client was given `current_state` (a callable returning the robot's whole
state), it sends `sync` with it and the message again, once; without it, `MonitorResync` is
raised. Nothing here ever lets an action run that the monitor did not allow.

Replicas: SafeGate replicas on one PostgreSQL share every session. Behind a load balancer one URL
is enough (a reconnect lands on a live replica); without one, give the others as
`fallback_urls`: each reconnect tries the next URL in turn, and the session goes on there from
its durable state.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Mapping, Sequence
from types import TracebackType
from typing import Any

from pydantic import BaseModel, ValidationError
from websockets.exceptions import ConnectionClosed, WebSocketException
from websockets.sync.client import ClientConnection, connect

from safegate_client.errors import (
    MonitorConnectionError,
    MonitorError,
    MonitorHalted,
    MonitorResync,
    UnexpectedAnswer,
)
from safegate_client.models import Allow, ErrorAnswer, HaltedAnswer, ViolationAnswer, parse_answer
from safegate_client.wire import as_json, auth_headers

JsonObject = dict[str, Any]
Observation = Mapping[str, Any] | BaseModel
"""A (partial) state: `{"scene": {...}, "robot": {...}}`, or a `State` / `InitialState`."""
Action = Mapping[str, Any] | BaseModel
"""An action: `{"action": "PickupObject", "object": "mug_1"}`, or an `Action`."""


def websocket_url(base_url: str, path: str) -> str:
    """`http://host:port` + path as a `ws://` (or `wss://`) URL."""
    base = base_url.rstrip("/")
    if base.startswith("https://"):
        base = "wss://" + base[len("https://"):]
    elif base.startswith("http://"):
        base = "ws://" + base[len("http://"):]
    return base + path


def read_answer(text: str | bytes) -> Allow | ViolationAnswer | HaltedAnswer | ErrorAnswer:
    """A websocket answer as its model.

    Raises:
        UnexpectedAnswer: not JSON, or none of the protocol's answers.
    """
    try:
        return parse_answer(json.loads(text))
    except (ValueError, ValidationError) as error:
        raise UnexpectedAnswer(f"the monitor's answer is none of the protocol's: {error}"
                               ) from error


def open_socket(url: str, api_key: str | None, timeout: float) -> ClientConnection:
    try:
        # Entered by hand: the connection outlives this call and is closed by its owner.
        return connect(url, additional_headers=auth_headers(api_key), open_timeout=timeout,
                       max_size=2**22).__enter__()
    except (OSError, WebSocketException) as error:
        raise MonitorConnectionError(f"could not open {url}: {error}") from error


class MonitorClient:
    """One runtime's connection to a monitoring session; use it as a context manager."""

    def __init__(self, base_url: str, session_id: str, *, api_key: str | None = None,
                 first_seq: int = 1, timeout: float = 10.0, reconnects: int = 3,
                 current_state: Callable[[], Observation] | None = None,
                 fallback_urls: Sequence[str] = ()) -> None:
        """Prepare a connection (opened by `__enter__` or `connect`).

        Args:
            base_url: where SafeGate listens, e.g. `http://127.0.0.1:8000`.
            session_id: from `POST /monitor`.
            api_key: a robot key, when the server runs with `auth=keys`.
            first_seq: the seq of the first action (after a reconnect: the last one + 1).
            timeout: seconds to wait for the connection and for each answer.
            reconnects: how often to reconnect and resend one message before giving up
                (`MonitorConnectionError`); 0 never reconnects.
            current_state: the robot's whole current state (`{"scene": ..., "robot": ...}`),
                sent as `sync` when the monitor asks to resynchronise.
            fallback_urls: other replicas' base URLs; a reconnect tries the next one in turn.
        """
        self.urls = [websocket_url(url, f"/monitor/{session_id}")
                     for url in (base_url, *fallback_urls)]
        self.url = self.urls[0]
        self.session_id = session_id
        self.next_seq = first_seq
        self.reconnects = reconnects
        self._current_state = current_state
        self._api_key = api_key
        self._timeout = timeout
        self._socket: ClientConnection | None = None
        self._open = False
        self._running: tuple[int, JsonObject] | None = None

    def connect(self) -> MonitorClient:
        """Open the websocket (on the first URL that accepts it)."""
        for _ in self.urls[1:]:
            try:
                self._socket = open_socket(self.url, self._api_key, self._timeout)
                break
            except MonitorConnectionError:
                self._next_url()
        else:
            self._socket = open_socket(self.url, self._api_key, self._timeout)
        self._open = True
        return self

    def _next_url(self) -> None:
        """Move on to the next replica's URL (the same one when there is only one)."""
        self.url = self.urls[(self.urls.index(self.url) + 1) % len(self.urls)]

    def close(self) -> None:
        """Close the websocket."""
        self._open = False
        if self._socket is not None:
            self._socket.close()
            self._socket = None

    def __enter__(self) -> MonitorClient:
        return self.connect()

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        self.close()

    def _send_and_receive(self, message: JsonObject
                          ) -> tuple[Allow | ViolationAnswer | HaltedAnswer | ErrorAnswer, bool]:
        """The answer to a message, reconnecting and resending it as needed; and whether it
        was resent."""
        if not self._open:
            raise MonitorConnectionError("not connected: use `with MonitorClient(...)`")
        for attempt in range(self.reconnects + 1):
            try:
                if self._socket is None:
                    time.sleep(min(0.2 * 2 ** attempt, 5.0))
                    self._socket = open_socket(self.url, self._api_key, self._timeout)
                self._socket.send(json.dumps(message))
                return read_answer(self._socket.recv(timeout=self._timeout)), attempt > 0
            except (ConnectionClosed, TimeoutError, OSError, MonitorConnectionError) as error:
                lost = error
                self._next_url()
                if self._socket is not None:
                    # A late answer on this socket must never be taken for the next one's.
                    self._socket.close()
                    self._socket = None
        raise MonitorConnectionError(f"monitor connection lost: {lost}") from lost

    def _exchange(self, message: JsonObject, *, resyncing: bool = False) -> Allow:
        answer, resent = self._send_and_receive(message)
        if isinstance(answer, ErrorAnswer) and answer.resync is not None:
            position = answer.resync
            if resent and message["type"] == "after" and (
                    position.last_seq, position.pending_seq) == (message["seq"], None):
                return Allow(type="allow", seq=message["seq"])  # accepted before the drop
            if self._current_state is not None and not resyncing:
                return self._resume(message)
        if answer.seq != message["seq"] and not isinstance(answer, ErrorAnswer):
            raise MonitorConnectionError(f"answer for seq {answer.seq} while waiting "
                                         f"for seq {message['seq']}")
        if isinstance(answer, Allow):
            return answer
        if isinstance(answer, ViolationAnswer | HaltedAnswer):
            raise MonitorHalted(answer)
        if answer.resync is not None:
            raise MonitorResync(answer)
        raise MonitorError(answer)

    def _resume(self, message: JsonObject) -> Allow:
        """Resynchronise with `current_state`, then send `message` again (once)."""
        assert self._current_state is not None
        finished = message["seq"] if message["type"] in ("after", "sync") else message["seq"] - 1
        self._exchange({"type": "sync", "seq": finished, "state": as_json(self._current_state())},
                       resyncing=True)
        if message["type"] in ("after", "sync"):
            return Allow(type="allow", seq=message["seq"])  # the sync reported its outcome
        return self._exchange(message, resyncing=True)

    def before(self, action: Action, state: Observation | None = None) -> int:
        """Ask before running an action; returns its seq when allowed.

        Raises:
            MonitorHalted: a guard or abort failed (or the session was already halted).
            MonitorError: the message could not be checked; do not run the action.
        """
        seq = self.next_seq
        wire_action = as_json(action)
        message: JsonObject = {"type": "before", "seq": seq, "action": wire_action}
        if state is not None:
            message["state"] = as_json(state)
        self._exchange(message)
        self.next_seq = seq + 1
        self._running = (seq, wire_action)
        return seq

    def after(self, state: Observation | None = None) -> None:
        """Report that the allowed action ran, with what changed.

        Raises:
            MonitorHalted: an invariant or abort failed in the new state.
            MonitorError: no action is running, or the report could not be checked.
        """
        if self._running is None:
            raise MonitorError(ErrorAnswer(type="error", halted=False,
                                           detail="no allowed action is running"))
        seq, action = self._running
        message: JsonObject = {"type": "after", "seq": seq, "action": action}
        if state is not None:
            message["state"] = as_json(state)
        self._exchange(message)
        self._running = None

    def sync(self, state: Observation, seq: int | None = None) -> None:
        """Resynchronise: tell the monitor the robot's whole current state after action `seq`.

        Args:
            state: `{"scene": {...}, "robot": {...}}`, both required; entities not listed keep
                the monitor's last known state, so list everything that may have changed.
            seq: the last action the robot finished (default: the last one this client
                numbered); the next action gets `seq` + 1.

        Raises:
            MonitorHalted: the state breaks an invariant or an abort condition.
            MonitorError: the message could not be checked (e.g. `seq` before the monitor's
                last finished action).
        """
        seq = self.next_seq - 1 if seq is None else seq
        self._exchange({"type": "sync", "seq": seq, "state": as_json(state)})
        self.next_seq = seq + 1
        self._running = None

    def step(self, action: Action,
             execute: Callable[[], Observation | None] | None = None, *,
             state: Observation | None = None) -> Observation | None:
        """Check an action, run it, check the state it left: `before`, `execute()`, `after`.

        Args:
            action: the action to run.
            execute: runs the action on the robot and returns what changed (or None to let
                the monitor's action model predict it); None for a dry step.
            state: an observation of the scene just before the action.

        Returns:
            What `execute` returned.

        Raises:
            MonitorHalted: the session halted, before the action (it was not run) or after.
            MonitorError: a message could not be checked.
        """
        self.before(action, state)
        observed = execute() if execute is not None else None
        self.after(observed)
        return observed
