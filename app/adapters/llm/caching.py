"""Where LLM analyses are kept between calls, under a key that changes whenever the answer could.

In: an `AnalysisCache` (the store's `Repository` has its methods), and per lookup the request,
the library view's digest, the answer schema and the client's identity (model and the settings
that change its answers: temperature, max tokens, structured-output dialect). Out: the cached
`HazardReport`, or None. Entries carry their expiry; an expired or unreadable entry is a miss.
Fails: never; a cache that raises `SafeGateError` is skipped (logged), so the analysis runs afresh.
"""

from __future__ import annotations

import hashlib
import json
import logging
import time
from collections.abc import Callable
from typing import Any, Protocol

from pydantic import ValidationError

from app.adapters.llm.rendering import visible
from app.domain.errors import SafeGateError
from app.domain.models import GateRequest, HazardReport

DEFAULT_TTL_SECONDS = 7 * 24 * 3600.0
_log = logging.getLogger(__name__)


class AnalysisCache(Protocol):
    """Where analyses are kept between calls (`app.store.Repository` has these methods)."""

    def get_cached_analysis(
        self, cache_key: str, model: str, prompt_version: str
    ) -> dict[str, Any] | None:
        """The stored result, or None."""
        ...

    def put_cached_analysis(
        self, cache_key: str, model: str, prompt_version: str, result: dict[str, Any]
    ) -> None:
        """Store a result."""
        ...


def _digest(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()


def request_hash(request: GateRequest) -> str:
    """A stable digest of everything the analysis sees of a request.

    Args:
        request: the gate request.

    Returns:
        The hex SHA-256 of the canonical JSON of the request's visible part (extra keys the
        schema does not declare never reach the model, so they do not split the cache).
    """
    return _digest(json.dumps(visible(request), sort_keys=True, ensure_ascii=False,
                              separators=(",", ":")))


class CachedAnalyses:
    """An `AnalysisCache` used with keys that cover everything an answer depends on."""

    def __init__(self, cache: AnalysisCache | None, *, model: str, prompt_version: str,
                 ttl_seconds: float = DEFAULT_TTL_SECONDS,
                 clock: Callable[[], float] = time.time) -> None:
        self._cache = cache
        self._model = model
        self._prompt_version = prompt_version
        self._ttl = ttl_seconds
        self._clock = clock

    @staticmethod
    def key(request: GateRequest, *, library: str, schema: str, client: str) -> str:
        """The cache key of one analysis.

        Args:
            request: the gate request.
            library: the digest of the class list shown to the model.
            schema: the answer's JSON schema, serialized.
            client: the client's identity (model and answer-changing settings).

        Returns:
            A hex digest.
        """
        return _digest("|".join((request_hash(request), library, _digest(schema), client)))

    def get(self, key: str) -> HazardReport | None:
        """The unexpired report stored under `key`, or None."""
        if self._cache is None:
            return None
        try:
            stored = self._cache.get_cached_analysis(key, self._model, self._prompt_version)
        except SafeGateError as error:
            _log.warning("analysis cache unreadable, analysing afresh: %s", error.detail)
            return None
        if stored is None or not isinstance(stored.get("expires_at"), int | float):
            return None
        if stored["expires_at"] <= self._clock():
            return None
        try:
            return HazardReport.model_validate(stored.get("report"))
        except ValidationError:
            return None

    def put(self, key: str, report: HazardReport) -> None:
        """Store a report under `key` until the expiry."""
        if self._cache is None:
            return
        entry = {"report": report.model_dump(mode="json"),
                 "expires_at": self._clock() + self._ttl}
        try:
            self._cache.put_cached_analysis(key, self._model, self._prompt_version, entry)
        except SafeGateError as error:
            _log.warning("analysis cache not written: %s", error.detail)
