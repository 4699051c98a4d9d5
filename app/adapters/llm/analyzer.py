"""Stage 1 by an LLM: the Hazard Analysis Matrix filled level by level through litellm.

In: a `GateRequest`. The LLM is asked three times, once per information level (task: the
command; deployment: + the scene; user: + the user and the robot), each time across the four
categories, with what the earlier levels found, and told to report unknown properties of the
user as unknowns instead of assuming them safe. Every answer is parsed into `LevelAnswer`,
its entity ids checked against the scene, with one repair round (`structured.py`).
Out: a `HazardReport` (analyzer "llm", proposals with source "llm:<model>").
Fails closed: any `LlmError` (timeout, connection, 5xx, 429, invalid or truncated output)
yields a report with the critical unknown "hazard analysis unavailable" and no proposals, so
the gate defers. Successful analyses are cached by a hash of (request, model, prompt version)
in an optional `AnalysisCache` (the store's `Repository` is one); a cache that fails is skipped.
"""

from __future__ import annotations

import hashlib
import json
import logging
from collections.abc import Callable, Iterable
from typing import Any, Protocol

from pydantic import ValidationError

from app.adapters.llm.client import ChatClient
from app.adapters.llm.errors import LlmError
from app.adapters.llm.matrix import MatrixBuilder
from app.adapters.llm.prompting import PromptSet
from app.adapters.llm.rendering import SceneIds, information
from app.adapters.llm.schemas import LevelAnswer, json_schema
from app.adapters.llm.structured import ask_structured
from app.domain.ensemble import failed_report
from app.domain.errors import SafeGateError
from app.domain.models import GateRequest, HazardReport, HazardTemplate, Level

LEVELS = (Level.TASK, Level.DEPLOYMENT, Level.USER)
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


def request_hash(request: GateRequest) -> str:
    """A stable digest of everything the analysis sees of a request.

    Args:
        request: the gate request.

    Returns:
        The hex SHA-256 of the request's canonical JSON.
    """
    canonical = json.dumps(
        request.model_dump(mode="json", by_alias=True, exclude_none=True),
        sort_keys=True,
        ensure_ascii=False,
        separators=(",", ":"),
    )
    return hashlib.sha256(canonical.encode()).hexdigest()


class LlmAnalyzer:
    """An `Analyzer` that asks an LLM to fill the Hazard Analysis Matrix."""

    name = "llm"

    def __init__(
        self,
        client: ChatClient,
        *,
        prompts: PromptSet | None = None,
        cache: AnalysisCache | None = None,
    ) -> None:
        """Set the analyzer up.

        Args:
            client: the chat client (litellm, or a fake in tests).
            prompts: the prompt version to use (default v1).
            cache: where to keep successful analyses; None disables caching.
        """
        self._client = client
        self._prompts = prompts or PromptSet()
        self._cache = cache
        self._system = self._prompts.render(
            "analysis_system",
            hazard_classes=self._prompts.text("hazard_classes"),
            schema=json.dumps(json_schema(LevelAnswer)),
        )

    @property
    def prompt_version(self) -> str:
        """The prompt set's identity, part of the cache key."""
        return self._prompts.identity

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport:
        """Fill the matrix for one request, or fail closed.

        Args:
            request: the gate request.
            templates: the active library (not yet shown to the model: its class list comes
                from the prompt files).

        Returns:
            The LLM's report, from the cache when the same request, model and prompts were
            analysed before; on any LLM failure, the fail-closed report.
        """
        key = request_hash(request)
        cached = self._cached(key)
        if cached is not None:
            return cached
        try:
            report = self._analyze_levels(request)
        except LlmError as error:
            _log.warning("LLM analysis failed, deferring: %s", error.detail)
            return failed_report(self.name, f"{type(error).__name__}: {error.detail[:200]}")
        self._store(key, report)
        return report

    def _analyze_levels(self, request: GateRequest) -> HazardReport:
        ids = SceneIds.of(request)
        matrix = MatrixBuilder(source=f"llm:{self._client.model}")
        for rank, level in enumerate(LEVELS):
            if rank == 0:
                earlier = ""
            else:
                hazards, unknowns = matrix.earlier_summary()
                earlier = self._prompts.render(
                    "analysis_earlier", hazards=hazards, unknowns=unknowns
                ) + "\n"
            user = self._prompts.render(
                "analysis_level",
                level=level.value,
                focus=self._prompts.text(f"level_{level.value}"),
                information=information(request, level),
                earlier=earlier,
            )
            answer = ask_structured(
                self._client,
                system=self._system,
                user=user,
                answer_model=LevelAnswer,
                prompts=self._prompts,
                check=_entity_check(level, ids),
            )
            matrix.add(level, answer)
        return HazardReport(
            proposals=matrix.proposals(), unknowns=matrix.unknowns(), analyzer=self.name
        )

    def _cached(self, key: str) -> HazardReport | None:
        if self._cache is None:
            return None
        try:
            stored = self._cache.get_cached_analysis(key, self._client.model, self.prompt_version)
        except SafeGateError as error:
            _log.warning("analysis cache unreadable, analysing afresh: %s", error.detail)
            return None
        if stored is None:
            return None
        try:
            return HazardReport.model_validate(stored)
        except ValidationError:
            return None

    def _store(self, key: str, report: HazardReport) -> None:
        if self._cache is None:
            return
        try:
            self._cache.put_cached_analysis(
                key, self._client.model, self.prompt_version, report.model_dump(mode="json")
            )
        except SafeGateError as error:
            _log.warning("analysis cache not written: %s", error.detail)


def _entity_check(level: Level, ids: SceneIds) -> Callable[[LevelAnswer], list[str]]:
    def check(answer: LevelAnswer) -> list[str]:
        if level is Level.TASK:
            return []
        problems: list[str] = []
        for number, hazard in enumerate(answer.hazards):
            for variable, value in hazard.entities.as_bindings().items():
                problems.extend(
                    f"hazards[{number}].{p}" for p in ids.problems(variable, value)
                )
        return problems

    return check
