"""Input limits at the edge: the shape of every JSON body.

In: the JSON body of any POST/PUT/PATCH request (`json_body_within_limits`, installed app-wide
by `create_app`, runs after the body parsed and before the route's own validation).
Out: nothing when the input is within limits.
Limits: JSON nesting at most `max_json_depth` deep; every number finite and within
`MAX_JSON_NUMBER` of zero (NaN, Infinity and 400-digit integers would otherwise reach float
arithmetic, the solver or a JSONB column); no string (value or key) holding a NUL character or
a lone UTF-16 surrogate (PostgreSQL cannot store either). The sizes of what the models hold (a
command's length, scene lists, plan steps) are the services' check, one rule for every route
and the CLI (`app/services/input_limits.py`); the body's size is the middleware's business
(413, `app/api/observability.py`).
Fails: `InvalidInput` naming the offending field (e.g. `body.scene.objects.3.properties.mass_kg`),
which `app/api/problems.py` answers as a 422 problem+json.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence

from starlette.requests import HTTPConnection, Request

from app.config import Settings
from app.domain.errors import InvalidInput

MAX_JSON_NUMBER = 1e15
_WRITE_METHODS = frozenset({"POST", "PUT", "PATCH"})
_UNSTORABLE_CHARACTERS = re.compile("[\x00\ud800-\udfff]")
# For `_plainly_within_limits`, which reads the raw bytes of a body that is valid JSON.
_KEPT = b'[]{}",.0123456789eEIN'
_DROPPED = bytes(b for b in range(256) if b not in _KEPT)
_BRACKETS_ONLY = (bytes.maketrans(b"{}", b"[]"), bytes(b for b in range(256) if b not in b"[]{}"))
# Outside strings: an exponent, a 16-digit run (>= 1e15) or NaN/Infinity (the only capitals).
_RISKY_NUMBER = re.compile(rb"\d[eE]|\d{16}|[NI]")

PathPart = str | int


def _field(path: Sequence[PathPart]) -> str:
    return ".".join(str(part) for part in path)


def _check_text(text: str, path: Sequence[PathPart], what: str) -> None:
    if _UNSTORABLE_CHARACTERS.search(text):
        raise InvalidInput(
            f"{what} holds a NUL character or a lone UTF-16 surrogate", field=_field(path))


def _check_number(number: float, path: Sequence[PathPart]) -> None:
    if isinstance(number, float) and not math.isfinite(number):
        raise InvalidInput("numbers must be finite (no NaN or Infinity)", field=_field(path))
    if abs(number) > MAX_JSON_NUMBER:
        raise InvalidInput(f"numbers must lie within ±{MAX_JSON_NUMBER:.0e}",
                           field=_field(path), limit=MAX_JSON_NUMBER)


def check_json_value(value: object, *, max_depth: int, root: str = "body") -> None:
    """Check a decoded JSON value against the shape limits (iteratively: no recursion limit).

    Args:
        value: what `json.loads` returned.
        max_depth: the deepest nesting of arrays and objects allowed (the root counts as 1).
        root: the name of the value's place, first in every reported field path.

    Raises:
        InvalidInput: nesting too deep, a non-finite or huge number, or an unstorable string.
    """
    pending: list[tuple[object, tuple[PathPart, ...], int]] = [(value, (root,), 1)]
    while pending:
        item, path, depth = pending.pop()
        if isinstance(item, dict | list) and depth > max_depth:
            raise InvalidInput(f"JSON nested deeper than {max_depth} levels",
                               field=_field(path), limit=max_depth)
        if isinstance(item, dict):
            for key, child in item.items():
                _check_text(key, (*path, key), "a key")
                pending.append((child, (*path, key), depth + 1))
        elif isinstance(item, list):
            pending.extend((child, (*path, index), depth + 1) for index, child in enumerate(item))
        elif isinstance(item, str):
            _check_text(item, path, "a string")
        elif isinstance(item, int | float) and not isinstance(item, bool):
            _check_number(item, path)


def _plainly_within_limits(body: bytes, max_depth: int) -> bool:
    """Whether the raw bytes alone show the body within the shape limits, if it is valid JSON.

    True only for a body (UTF-8: no NUL byte) with no `\\u` escape and no 0xED byte (so no
    string can hold a NUL or a lone surrogate) whose text outside strings has no exponent, no
    run of 16 digits, no NaN/Infinity and nesting within `max_depth`. Anything else returns
    False and takes the full walk, which names the offending field. Most requests are plain,
    and C-level byte operations read them several times faster than decoding and walking.
    """
    if b"\x00" in body or b"\\u" in body or b"\xed" in body:
        return False
    # Escapes pair up from the left as the decoder reads them; after these two replacements
    # every remaining quote opens or closes a string.
    unescaped = body.replace(b"\\\\", b"").replace(b'\\"', b"")
    outside_strings = b"".join(unescaped.translate(None, _DROPPED).split(b'"')[::2])
    if _RISKY_NUMBER.search(outside_strings):
        return False
    brackets = outside_strings.translate(*_BRACKETS_ONLY)
    # Each pass removes the innermost containers (one left-to-right scan, no rescan): the
    # passes needed are the nesting depth.
    for _ in range(max_depth):
        if not brackets:
            return True
        brackets = brackets.replace(b"[]", b"")
    return not brackets


async def json_body_within_limits(connection: HTTPConnection) -> None:
    """App-wide dependency: refuse a JSON body whose shape is out of limits (422).

    Bodies that are not JSON are left to the route (which answers 422 for them too).
    """
    if not isinstance(connection, Request) or connection.method not in _WRITE_METHODS:
        return
    content_type = connection.headers.get("content-type", "application/json")
    if "json" not in content_type:
        return
    body = await connection.body()
    if not body:
        return
    settings: Settings = connection.app.state.settings
    # A body that is not JSON is refused by the route whatever the bytes suggest.
    if _plainly_within_limits(body, settings.max_json_depth):
        return
    try:
        value = json.loads(body)
    except (ValueError, RecursionError):
        return  # FastAPI has already refused what it could not parse; nothing to add
    check_json_value(value, max_depth=settings.max_json_depth)
