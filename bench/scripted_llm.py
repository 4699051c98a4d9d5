"""An OpenAI-compatible chat server on loopback that answers from a script, for litellm.

Used by the LLM adapter's tests and by `make bench`'s scripted LLM methods (`bench/methods.py`
with `bench/scripted_analyst.py` as the responder); it never reaches a model or the network.

In: a queue of `Scripted` replies (a JSON answer, raw text, an HTTP status, a delay). Each POST
to /v1/chat/completions takes the next reply; the request bodies are recorded. Out: real HTTP on
127.0.0.1 at a free port. With the script empty the server asks `responder` (a function of the
request body) if one is set, else answers 500, so an unexpected extra call (a retry nobody
asked for) shows up as a failure and in `requests`.
"""

from __future__ import annotations

import json
import threading
import time
from collections import deque
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any


@dataclass(frozen=True)
class Scripted:
    """One scripted reply: `content` as the assistant's message, or an error status."""

    content: str = ""
    status: int = 200
    delay: float = 0.0
    finish_reason: str = "stop"
    reject_json_schema: bool = False
    rejection_status: int = 400


@dataclass
class ScriptedServer:
    """The running server: its base URL, the remaining script and what it received."""

    base_url: str
    script: deque[Scripted] = field(default_factory=deque)
    requests: list[dict[str, Any]] = field(default_factory=list)
    responder: Callable[[dict[str, Any]], Scripted] | None = None
    prepare: Callable[[object], object] | None = None
    """Applied to each payload `answer_json` serializes (the LLM tests complete open cells)."""

    def queue(self, *replies: Scripted) -> None:
        """Append replies to the script."""
        self.script.extend(replies)

    def answer_json(self, *payloads: object) -> None:
        """Append replies whose content is each payload serialized as JSON."""
        prepare = self.prepare or (lambda payload: payload)
        self.queue(*(Scripted(content=json.dumps(prepare(p))) for p in payloads))


def _completion(content: str, finish_reason: str) -> dict[str, Any]:
    return {
        "id": "chatcmpl-scripted",
        "object": "chat.completion",
        "created": int(time.time()),
        "model": "scripted-model",
        "choices": [
            {
                "index": 0,
                "message": {"role": "assistant", "content": content},
                "finish_reason": finish_reason,
            }
        ],
        "usage": {"prompt_tokens": 10, "completion_tokens": 10, "total_tokens": 20},
    }


def _handler(server_state: ScriptedServer) -> type[BaseHTTPRequestHandler]:
    class Handler(BaseHTTPRequestHandler):
        def log_message(self, format: str, *args: Any) -> None:
            return

        def _send(self, status: int, body: dict[str, Any]) -> None:
            data = json.dumps(body).encode()
            try:
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)
            except (BrokenPipeError, ConnectionResetError):
                return

        def do_POST(self) -> None:
            length = int(self.headers.get("Content-Length") or 0)
            body = json.loads(self.rfile.read(length) or b"{}")
            server_state.requests.append(body)
            if not self.path.endswith("/chat/completions"):
                self._send(404, {"error": {"message": "not found"}})
                return
            if server_state.script:
                reply: Scripted | None = server_state.script.popleft()
            elif server_state.responder is not None:
                reply = server_state.responder(body)
            else:
                reply = None
            if reply is None:
                self._send(500, {"error": {"message": "script exhausted", "type": "server"}})
                return
            if reply.delay:
                time.sleep(reply.delay)
            response_format = body.get("response_format") or {}
            if reply.reject_json_schema and response_format.get("type") == "json_schema":
                # The reply stays queued for the retry in the other dialect.
                server_state.script.appendleft(reply)
                self._send(reply.rejection_status, {"error": {
                    "message": "response_format.type: Input should be 'text' or 'json_object'",
                    "type": "invalid_request_error"}})
                return
            if reply.status != 200:
                self._send(reply.status, {"error": {"message": f"scripted {reply.status}",
                                                    "type": "scripted"}})
                return
            self._send(200, _completion(reply.content, reply.finish_reason))

    return Handler


@contextmanager
def scripted_server() -> Iterator[ScriptedServer]:
    """Serve scripted chat completions on 127.0.0.1 for the duration of the block."""
    state = ScriptedServer(base_url="")
    httpd = ThreadingHTTPServer(("127.0.0.1", 0), _handler(state))
    httpd.daemon_threads = True
    host, port = httpd.server_address[:2]
    state.base_url = f"http://{host!s}:{port}/v1"
    thread = threading.Thread(target=httpd.serve_forever, name="scripted-llm", daemon=True)
    thread.start()
    try:
        yield state
    finally:
        httpd.shutdown()
        httpd.server_close()
        thread.join(timeout=5)
