"""Stage 1 by an LLM: the Hazard Analysis Matrix filled level by level through litellm.

In: a `GateRequest` and the active library. The system prompt lists the library's hazard classes
as they are now (`library.py`), so a curator's new class is offered on the next request. The
matrix is filled per information level (task: the command; deployment: + the scene; user: + the
user and the robot), each level across the four categories and from what the earlier levels
found: either one call per level (`batch_levels=False`), each seeing only its partition, or the
three levels in one call whose prompt shows the partition level by level (the service's
default: one system prompt per request and a third of the characters); the request goes in as
delimited, JSON-encoded data (`rendering.py`). Every answer is parsed into
`LevelAnswer` and checked (each of the level's four cells answered, by a hazard or by "none,
because ...", `cells.py`; entity ids in the scene; classes in the library or marked new), with
one repair round (`structured.py`). Hazards still without the scene ids their templates need go
back once more for their ids (the entity round). Levels merge by identity (`matrix.py`).
Out: a `HazardReport` (analyzer "llm", proposals with source "llm:<model>").
Fails closed: any `LlmError` (timeout, connection, 5xx, 429, invalid or truncated output)
yields a report with the critical unknown "hazard analysis unavailable" and no proposals; an
answer usable but for matrix cells still open after the repair round is "not understood" (the
critical `comprehension` unknown). An
analysis with no hazard and no unknown is not evidence of safety (a model that did not follow,
or that obeyed text injected in the request, answers just that): with `require_findings` it
becomes a critical `comprehension` unknown. Successful analyses are cached (`caching.py`).
"""

from __future__ import annotations

import json
import logging
from collections.abc import Callable, Iterable

from app.adapters.llm.caching import AnalysisCache, CachedAnalyses, request_hash
from app.adapters.llm.cells import cell_problems, only_cells_missing
from app.adapters.llm.client import ChatClient
from app.adapters.llm.errors import LlmError, LlmOutputInvalid
from app.adapters.llm.library import LibraryView, attribute_problems, attributes_text
from app.adapters.llm.matrix import MatrixBuilder
from app.adapters.llm.prompting import PromptSet
from app.adapters.llm.rendering import SceneIds, information
from app.adapters.llm.schemas import BatchedAnswer, LevelAnswer, json_schema
from app.adapters.llm.structured import ask_structured
from app.domain.ensemble import failed_report
from app.domain.models import (
    GateRequest,
    HazardReport,
    HazardTemplate,
    Level,
    Severity,
    UnknownFact,
)

LEVELS = (Level.TASK, Level.DEPLOYMENT, Level.USER)
COMPREHENSION = "comprehension"
_log = logging.getLogger(__name__)

__all__ = ["COMPREHENSION", "LEVELS", "AnalysisCache", "LlmAnalyzer", "request_hash"]


class LlmAnalyzer:
    """An `Analyzer` that asks an LLM to fill the Hazard Analysis Matrix."""

    name = "llm"

    def __init__(
        self,
        client: ChatClient,
        *,
        prompts: PromptSet | None = None,
        cache: AnalysisCache | None = None,
        require_findings: bool = True,
        theta: Severity = Severity.HIGH,
        batch_levels: bool = False,
    ) -> None:
        """Set the analyzer up.

        Args:
            client: the chat client (litellm, or a fake in tests).
            prompts: the prompt version to use (default v1).
            cache: where to keep successful analyses; None disables caching.
            require_findings: read an empty analysis as "not understood" (True when the LLM
                decides alone; an ensemble whose other member reads the command may pass False).
            theta: the gate's severity threshold, which the prompt's severity anchors name.
            batch_levels: ask for the three levels in one call (the service's default,
                `SAFEGATE_LLM_BATCH_LEVELS`: a third of the characters sent,
                bench/perf/llm_prompt_size.py); False asks one call per level, each call seeing
                only its partition and the earlier calls' findings.
        """
        self._client = client
        self._prompts = prompts or PromptSet()
        self._require_findings = require_findings
        self._theta = theta
        self._batch_levels = batch_levels
        self._schema = json.dumps(json_schema(BatchedAnswer if batch_levels else LevelAnswer))
        self._cache = CachedAnalyses(cache, model=client.model,
                                     prompt_version=self._prompts.identity)

    @property
    def prompt_version(self) -> str:
        """The prompt set's identity, part of the cache key."""
        return self._prompts.identity

    def system_prompt(self, library: LibraryView) -> str:
        """The system prompt for a library: the classes as they are now.

        The JSON schema is not repeated here: it travels in the request's `response_format`,
        and the prompt's worked examples show the shape.
        """
        return self._prompts.render(
            "analysis_system", hazard_classes=library.prompt_text(),
            attributes=attributes_text(), theta=self._theta.value,
        )

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport:
        """Fill the matrix for one request, or fail closed.

        Args:
            request: the gate request.
            templates: the active library; its classes are offered to the model and answers
                are checked against them.

        Returns:
            The LLM's report, from the cache when the same request, library, model settings and
            prompts were analysed before; on any LLM failure, the fail-closed report.
        """
        library = LibraryView.of(templates)
        key = CachedAnalyses.key(request, library=library.digest, schema=self._schema,
                                 client=f"{self._client.identity}|theta={self._theta.value}")
        report = self._cache.get(key)
        if report is None:
            try:
                report = self._analyze_levels(request, library)
            except LlmOutputInvalid as error:
                if not only_cells_missing(error.problems):
                    _log.warning("LLM analysis failed, deferring: %s", error.detail)
                    return failed_report(self.name, f"LlmOutputInvalid: {error.detail[:200]}")
                # An answer that still leaves cells open after the repair round did not look at
                # every category at every level: not understood, like an empty matrix.
                _log.warning("LLM left matrix cells open, not understood: %s", error.detail)
                return HazardReport(unknowns=(_not_understood(_CELLS_OPEN),),
                                    analyzer=self.name)
            except LlmError as error:
                _log.warning("LLM analysis failed, deferring: %s", error.detail)
                return failed_report(self.name, f"{type(error).__name__}: {error.detail[:200]}")
            self._cache.put(key, report)
        # Applied to cached reports too: the cache holds what the model found, whichever mode
        # (alone or in an ensemble) stored it.
        if self._require_findings and not report.proposals and not report.unknowns:
            return report.model_copy(update={"unknowns": (_not_understood(_EMPTY),)})
        return report

    def _analyze_levels(self, request: GateRequest, library: LibraryView) -> HazardReport:
        ids = SceneIds.of(request)
        system = self.system_prompt(library)
        matrix = MatrixBuilder(source=f"llm:{self._client.model}")
        if self._batch_levels:
            self._ask_batched(request, matrix, library, system, ids)
        else:
            self._ask_level_by_level(request, matrix, library, system, ids)
        if request.scene is not None:
            self._entity_round(request, matrix, library, system, ids)
        return HazardReport(proposals=matrix.proposals(), unknowns=matrix.unknowns(),
                            analyzer=self.name)

    def _earlier(self, matrix: MatrixBuilder) -> str:
        hazards, unknowns = matrix.earlier_summary()
        return self._prompts.render("analysis_earlier", hazards=hazards, unknowns=unknowns) + "\n"

    def _ask(self, system: str, user: str,
             check: Callable[[LevelAnswer], list[str]]) -> LevelAnswer:
        return ask_structured(self._client, system=system, user=user, answer_model=LevelAnswer,
                              prompts=self._prompts, check=check)

    def _ask_level_by_level(self, request: GateRequest, matrix: MatrixBuilder,
                            library: LibraryView, system: str, ids: SceneIds) -> None:
        """One call per level, each seeing its partition and what the earlier levels found."""
        for level in LEVELS:
            user = self._prompts.render(
                "analysis_level",
                level=level.value,
                focus=self._prompts.text(f"level_{level.value}"),
                information=information(request, level),
                earlier=self._earlier(matrix) if level is not Level.TASK else "",
            )
            matrix.add(level, self._ask(system, user, _answer_check(level, ids, library)))

    def _ask_batched(self, request: GateRequest, matrix: MatrixBuilder, library: LibraryView,
                     system: str, ids: SceneIds) -> None:
        """All three levels in one call, folded in level order as if asked one by one.

        The prompt shows the partition level by level (the command, what the scene adds, what
        the user and robot add) and the answer writes the levels in order, so each is written
        after, and from, the earlier levels' findings; they merge by identity as in the
        level-by-level mode. The task level's entities are dropped whatever it wrote.
        """
        values = {f"{level.value}_focus": self._prompts.text(f"level_{level.value}")
                  for level in LEVELS}
        values |= {f"{level.value}_information": information(request, level, only_new=True)
                   for level in LEVELS}
        user = self._prompts.render("analysis_batched", **values)
        checks = {level: _answer_check(level, ids, library) for level in LEVELS}

        def check(answer: BatchedAnswer) -> list[str]:
            return [f"{level.value}.{problem}" for level in LEVELS
                    for problem in checks[level](getattr(answer, level.value))]

        batched = ask_structured(self._client, system=system, user=user,
                                 answer_model=BatchedAnswer, prompts=self._prompts, check=check)
        for level in LEVELS:
            matrix.add(level, getattr(batched, level.value))

    def _entity_round(self, request: GateRequest, matrix: MatrixBuilder, library: LibraryView,
                      system: str, ids: SceneIds) -> None:
        """Send hazards that still lack the scene ids their templates bind back for them."""
        vague = matrix.without_ids(library.lacks_ids)
        if not vague:
            return
        listed = "\n".join(f"- {p.category.value}/{p.hazard_class} (given: "
                           f"{', '.join(sorted(p.entities)) or 'no ids'}): {p.mechanism}"
                           for p in vague)
        user = self._prompts.render("analysis_entities", information=information(
            request, Level.USER), hazards=listed)
        try:
            answer = self._ask(system, user,
                               _answer_check(Level.USER, ids, library, cells=False))
        except LlmOutputInvalid as error:
            # The hazards stay without ids, so unbound: the gate defers (R2, entities missing).
            _log.warning("LLM gave no usable entities, hazards stay unbound: %s", error.detail)
            return
        # This round was asked about these hazards only: it may dismiss them, nothing else.
        asked = {p.hazard_class for p in vague}
        kept = [d for d in answer.dismissed if d.kind == "hazard" and d.name in asked]
        matrix.add(Level.USER, answer.model_copy(update={"dismissed": kept}))


def _answer_check(level: Level, ids: SceneIds, library: LibraryView, *,
                  cells: bool = True) -> Callable[[LevelAnswer], list[str]]:
    """The semantic check of one level's answer; `cells` holds it to the level's four cells
    (the entity round answers about a few hazards only, not a level)."""

    def check(answer: LevelAnswer) -> list[str]:
        problems = cell_problems(answer, level.value) if cells else []
        problems += library.class_problems(answer.hazards)
        problems += attribute_problems(answer.unknowns, scene=level is not Level.TASK)
        if level is Level.TASK:
            return problems
        for number, hazard in enumerate(answer.hazards):
            for variable, value in hazard.entities.as_bindings().items():
                problems.extend(
                    f"hazards[{number}].{p}" for p in ids.problems(variable, value)
                )
        return problems

    return check


_EMPTY = "the analysis found no hazard and no unknown, so the task was not understood"
_CELLS_OPEN = ("the analysis left cells of the hazard matrix unanswered after a repair round, so "
               "the task was not understood")


def _not_understood(description: str) -> UnknownFact:
    return UnknownFact(
        attribute=COMPREHENSION,
        description=description,
        critical=True,
        why="an analysis that is empty or skips categories cannot be told apart from a command "
        "the model did not follow or from an instruction injected in the request to report "
        "nothing; it is never authorized",
        question="I could not work out what this task involves. Please describe it step by "
        "step, naming the objects and people concerned.",
    )
