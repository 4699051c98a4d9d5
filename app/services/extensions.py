"""The library-extension loop: requests waiting for a template, and deciding them again.

In: the audit trail. A request is waiting when the latest decision of its chain (the request,
then its answers and re-evaluations) is a deferral with `extend_library`; what it waits for are
that decision's unbound hazards. Out: waiting requests grouped by hazard class (with the active
templates now covering the class and a template skeleton), and new decisions from re-evaluation,
which runs the normal pipeline against the current library and links the new record to the one
it re-decides. Fails: `NotFound` (404), `Conflict` (409: the request is not waiting, or no
active template covers the class), `Unavailable` (503).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from pydantic import ValidationError

from app.domain.errors import Conflict
from app.domain.gate import Decision, DeferKind
from app.domain.models import HazardProposal
from app.domain.template_validation import suggest_template
from app.services.gate import Decided, GateService
from app.services.template_cache import TemplateCache
from app.store.records import GateRecord
from app.store.repository import AuditRepository, TemplateRepository

PENDING_LIMIT = 1000


@dataclass(frozen=True)
class WaitingRequest:
    """A request whose latest decision defers for a library extension."""

    record: GateRecord
    unbound: tuple[HazardProposal, ...]

    @property
    def hazard_classes(self) -> frozenset[str]:
        return frozenset(h.hazard_class for h in self.unbound)


@dataclass
class PendingClass:
    """The requests waiting on one hazard class."""

    hazard_class: str
    requests: list[WaitingRequest] = field(default_factory=list)
    covered_by: tuple[str, ...] = ()
    suggested_template: dict[str, Any] = field(default_factory=dict)


def _unbound_hazards(record: GateRecord) -> tuple[HazardProposal, ...]:
    hazards: list[HazardProposal] = []
    for trigger in record.triggers:
        if isinstance(trigger, dict) and "hazard_class" in trigger:
            try:
                hazards.append(HazardProposal.model_validate(trigger))
            except ValidationError:
                continue
    return tuple(hazards)


def is_waiting(record: GateRecord) -> bool:
    """Whether a decision defers for a library extension."""
    return record.decision is Decision.DEFER and record.defer_kind is DeferKind.EXTEND_LIBRARY


class ExtensionService:
    """The library-extension loop over the audit trail and the current library."""

    def __init__(self, *, audit: AuditRepository, templates: TemplateRepository,
                 cache: TemplateCache, gate: GateService) -> None:
        """Args:
            audit: the decisions and their chains.
            templates: the whole library (for the skeletons of suggested templates).
            cache: the active templates (what covers a class now).
            gate: decides a waiting request again.
        """
        self._audit = audit
        self._templates = templates
        self._cache = cache
        self._gate = gate

    def waiting_requests(self) -> list[WaitingRequest]:
        """Every request waiting for a library extension, oldest first."""
        records = self._audit.list_pending_library_extensions(limit=PENDING_LIMIT)
        return [WaitingRequest(record, _unbound_hazards(record)) for record in records]


    def pending_by_class(self) -> list[PendingClass]:
        """Waiting requests grouped by the hazard classes they wait for, largest group first."""
        groups: dict[str, PendingClass] = {}
        for waiting in self.waiting_requests():
            for hazard_class in sorted(waiting.hazard_classes):
                groups.setdefault(hazard_class, PendingClass(hazard_class)).requests.append(waiting)
        library = self._templates.list_templates()
        index = self._cache.index()
        for group in groups.values():
            group.covered_by = tuple(t.id for t in index.for_class(group.hazard_class))
            proposal = next(
                h for h in group.requests[0].unbound if h.hazard_class == group.hazard_class
            )
            group.suggested_template = suggest_template(proposal, library)
        return sorted(groups.values(), key=lambda g: (-len(g.requests), g.hazard_class))


    def latest_in_chain(self, request_id: str) -> GateRecord:
        """The most recent decision that follows `request_id` (itself when none does)."""
        record = self._audit.get_gate_record(request_id)
        while True:
            children = self._audit.list_child_records(str(record.id))
            if not children:
                return record
            record = children[-1]


    def reevaluate_request(self, request_id: str) -> Decided:
        """Decide a waiting request again (the latest decision of its chain) with today's library.

        Raises:
            NotFound: no such request.
            Conflict: the request's latest decision is not an `extend_library` deferral.
        """
        latest = self.latest_in_chain(request_id)
        if not is_waiting(latest):
            kind = f" ({latest.defer_kind})" if latest.defer_kind else ""
            raise Conflict(
                f"request {request_id!r} is not waiting for a library extension: its latest "
                f"decision {latest.id!r} is {latest.decision}{kind}",
                latest_request_id=latest.id,
            )
        return self._gate.reevaluate(str(latest.id))


    def reevaluate_class(self, hazard_class: str) -> list[tuple[str, Decided]]:
        """Decide again every request waiting on a hazard class an active template now covers.

        Returns:
            (id of the re-decided record, the new decision) per waiting request, oldest first.

        Raises:
            Conflict: no active template covers the class (nothing would change).
        """
        if not self._cache.index().covers(hazard_class):
            raise Conflict(
                f"no active template covers hazard class {hazard_class!r}; add and activate one "
                "first", field="body.hazard_class")
        waiting = [w for w in self.waiting_requests() if hazard_class in w.hazard_classes]
        return [(str(w.record.id), self._gate.reevaluate(str(w.record.id))) for w in waiting]
