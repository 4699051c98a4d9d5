"""A lean HTTP/1.1 keep-alive client over asyncio streams, for load that measures the server.

A general client (httpx) spends about as much CPU per request as a fast endpoint does, and on a
two-core machine the client shares the cores with the server under test; this one sends
pre-encoded requests and reads only the status line, the Content-Length and the body.
"""

from __future__ import annotations

import asyncio
import json
from urllib.parse import urlsplit


def encode_post(base: str, path: str, body: object) -> bytes:
    """The bytes of one `POST path` with a JSON body, ready to write on a keep-alive connection."""
    payload = json.dumps(body, separators=(",", ":")).encode()
    host = urlsplit(base).netloc
    head = (
        f"POST {path} HTTP/1.1\r\nhost: {host}\r\ncontent-type: application/json\r\n"
        f"content-length: {len(payload)}\r\n\r\n"
    )
    return head.encode() + payload


class Connection:
    """One keep-alive connection; `exchange` writes a request and returns (status, body)."""

    def __init__(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        self._reader = reader
        self._writer = writer

    @classmethod
    async def open(cls, base: str) -> Connection:
        parts = urlsplit(base)
        reader, writer = await asyncio.open_connection(parts.hostname, parts.port)
        return cls(reader, writer)

    async def exchange(self, raw_request: bytes) -> tuple[int, bytes]:
        self._writer.write(raw_request)
        head = await self._reader.readuntil(b"\r\n\r\n")
        status = int(head[9:12])
        length = 0
        for line in head.split(b"\r\n")[1:]:
            name, _, value = line.partition(b":")
            if name.strip().lower() == b"content-length":
                length = int(value)
        body = await self._reader.readexactly(length) if length else b""
        return status, body

    async def close(self) -> None:
        self._writer.close()
        await self._writer.wait_closed()
