"""Graceful shutdown: SIGTERM during a slow request lets it finish, recorded, then the process
exits cleanly and takes no new work.

The slow request is a gate request whose body the client sends in two parts, 1.5 s apart;
SIGTERM arrives in between. uvicorn (`safegate serve`, `timeout_graceful_shutdown=10`) stops
listening at once, finishes the request, runs the app's shutdown, and exits by the signal.
"""

from __future__ import annotations

import json
import signal
import threading
import time
from collections.abc import Callable, Iterator
from typing import Any

import httpx
import pytest

pytestmark = [pytest.mark.faults, pytest.mark.slow]

BODY = json.dumps({"command": "bring the mug to the kitchen", "robot": {"name": "stretch"},
                   "scene": {"objects": [{"id": "mug_1", "type": "Mug", "room": "kitchen"}]}}
                  ).encode()
PAUSE_SECONDS = 1.5


class TestGracefulShutdown:
    def test_sigterm_lets_the_request_in_flight_finish(
        self, live_server: Callable[..., Any]
    ) -> None:
        server = live_server(SAFEGATE_LOG_LEVEL="warning")
        half_sent = threading.Event()
        outcome: dict[str, Any] = {}

        def slow_body() -> Iterator[bytes]:
            yield BODY[:20]
            half_sent.set()
            time.sleep(PAUSE_SECONDS)
            yield BODY[20:]

        def send() -> None:
            try:
                outcome["response"] = httpx.post(
                    server.base_url + "/gate", content=slow_body(), timeout=30,
                    headers={"content-type": "application/json",
                             "content-length": str(len(BODY))})
            except httpx.HTTPError as error:
                outcome["error"] = error

        sender = threading.Thread(target=send)
        sender.start()
        assert half_sent.wait(10)
        time.sleep(0.2)  # the server has the first part
        server.process.send_signal(signal.SIGTERM)
        sender.join(timeout=30)

        assert "error" not in outcome, outcome.get("error")
        response = outcome["response"]
        assert response.status_code == 200, response.text
        # uvicorn finishes its graceful shutdown, then re-raises the signal it caught.
        assert server.process.wait(timeout=20) in (0, -signal.SIGTERM)
        with pytest.raises(httpx.ConnectError):
            httpx.get(server.base_url + "/healthz", timeout=2)

        server.start()
        request_id = response.json()["request_id"]
        stored = httpx.get(f"{server.base_url}/gate/{request_id}", timeout=10)
        assert stored.status_code == 200
        assert stored.json()["decision"] == response.json()["decision"]
