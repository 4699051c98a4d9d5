"""The active hazard templates in memory, for Stages 2-4.

In: the template repository. Out: a `TemplateIndex` of the active templates, swapped whole on
`refresh()` (after a curator changes the library), so a reader never sees half a reload.
Fails: `Unavailable` when the database cannot be read (the index in use stays as it was).
"""

from __future__ import annotations

import threading

from app.domain.binding import TemplateIndex
from app.store.repository.templates import TemplateQueries


class TemplateCache:
    """The active templates in memory, reloaded after a curator changes the library.

    `version` counts the reloads; the analysis workers reload theirs when a job carries a
    version they have not seen.
    """

    def __init__(self, repository: TemplateQueries) -> None:
        self._repository = repository
        self._lock = threading.Lock()
        self._index = TemplateIndex(())
        self.version = 0
        self.refresh()

    def refresh(self) -> None:
        index = TemplateIndex(self._repository.list_active_templates())
        with self._lock:
            self._index = index
            self.version += 1

    def index(self) -> TemplateIndex:
        return self._index
