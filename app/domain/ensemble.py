"""Defense in depth for Stage 1: run several analyzers and bind the union of what they found.

In: two or more `Analyzer`s (typically the symbolic one and the LLM one) and a gate request.
Out: one `HazardReport` holding every proposal and every unknown any member reported
(duplicates dropped, order kept: first member first). The deterministic gate then decides on
the union, so a member can only add hazards and unknowns, never remove the other's.
Fails closed: a member that raises contributes the critical unknown "hazard analysis
unavailable" (see `analysis_unavailable`), so the gate defers even when the other member found
nothing. `analyze` itself never raises.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import TypeVar

from app.domain.models import GateRequest, HazardReport, HazardTemplate, UnknownFact
from app.domain.pipeline import Analyzer

ANALYSIS_UNAVAILABLE = "hazard analysis unavailable"
_ItemT = TypeVar("_ItemT")


def analysis_unavailable(analyzer_name: str, reason: str) -> UnknownFact:
    """The critical unknown that stands for an analysis that could not be done.

    Args:
        analyzer_name: which analyzer failed.
        reason: a short cause (exception type, "timeout", "invalid output"...).

    Returns:
        A critical `UnknownFact`, so the gate can never authorize on it.
    """
    return UnknownFact(
        attribute="hazard_analysis",
        description=ANALYSIS_UNAVAILABLE,
        critical=True,
        why=f"the {analyzer_name} analyzer failed ({reason}); "
        "without an analysis nothing can be authorized",
        question="The hazard analysis could not be completed. "
        "Please try again or describe the task differently.",
    )


def failed_report(analyzer_name: str, reason: str) -> HazardReport:
    """A report with no proposals and the critical "hazard analysis unavailable" unknown.

    Args:
        analyzer_name: which analyzer failed.
        reason: a short cause.

    Returns:
        The fail-closed report.
    """
    return HazardReport(
        unknowns=(analysis_unavailable(analyzer_name, reason),), analyzer=analyzer_name
    )


def union_reports(reports: Iterable[HazardReport], analyzer_name: str) -> HazardReport:
    """Merge reports: every proposal and unknown of every report, each once.

    Args:
        reports: the members' reports.
        analyzer_name: the name the merged report carries.

    Returns:
        The union report.
    """
    materialized = list(reports)
    return HazardReport(
        proposals=_unique(p for r in materialized for p in r.proposals),
        unknowns=_unique(u for r in materialized for u in r.unknowns),
        analyzer=analyzer_name,
    )


def _unique(items: Iterable[_ItemT]) -> tuple[_ItemT, ...]:
    seen: list[_ItemT] = []
    for item in items:
        if item not in seen:
            seen.append(item)
    return tuple(seen)


class EnsembleAnalyzer:
    """An `Analyzer` whose report is the union of its members' reports."""

    def __init__(self, members: Sequence[Analyzer]) -> None:
        """Combine analyzers.

        Args:
            members: at least one analyzer; their order is the order of the merged items.

        Raises:
            ValueError: no member given.
        """
        if not members:
            raise ValueError("an ensemble needs at least one analyzer")
        self._members = tuple(members)
        self.name = "ensemble(" + "+".join(m.name for m in self._members) + ")"

    @property
    def members(self) -> tuple[Analyzer, ...]:
        """The combined analyzers, in order."""
        return self._members

    def analyze(self, request: GateRequest,
                templates: Iterable[HazardTemplate] = ()) -> HazardReport:
        """Run every member and merge their reports.

        Args:
            request: the gate request.
            templates: the active library, passed on to every member.

        Returns:
            The union; a member that raised contributes the critical "analysis unavailable".
        """
        library = tuple(templates)
        return union_reports((_run(m, request, library) for m in self._members), self.name)


def _run(member: Analyzer, request: GateRequest,
         templates: tuple[HazardTemplate, ...]) -> HazardReport:
    try:
        return member.analyze(request, templates)
    except Exception as error:
        # Whatever went wrong, the member's silence must not read as "no hazards".
        return failed_report(member.name, type(error).__name__)
