"""Imported by the analysis pool's fork server only: runs the pipeline once, so every worker
forked from it starts with the analyzer's lazily built caches (lexicons, object types, parsed
conditions) already in memory. The first decision of a cold process takes about half a second;
of a warm one, a few milliseconds.

Nothing here may fail the fork server: any error only costs the workers their warm start.
Do not import this module anywhere else (importing it runs the warm-up).
"""

from __future__ import annotations

import logging

from app.domain.models import GateRequest

SAMPLE = GateRequest.model_validate({
    "command": "Bring the hot coffee to the child in the living room and put the knife away",
    "scene": {
        "objects": [
            {"id": "mug_1", "type": "Mug", "room": "kitchen",
             "properties": {"temperature": "hot", "contents": "coffee"}},
            {"id": "knife_1", "type": "Knife", "room": "kitchen"},
            {"id": "stove_1", "type": "StoveBurner", "room": "kitchen", "properties": {"on": True}},
        ],
        "people": [{"id": "person_1", "room": "living_room",
                    "properties": {"age_group": "child"}}],
        "layout": {"rooms": ["kitchen", "living_room"],
                   "connections": [["kitchen", "living_room"]]},
    },
    "robot": {"room": "kitchen", "skills": ["navigate", "pick", "place"]},
})


def warm_up() -> None:
    """Decide the sample request once with the seed library and the symbolic analyzer."""
    from app.config import Settings
    from app.domain.analysis import SymbolicAnalyzer
    from app.domain.binding import TemplateIndex
    from app.domain.pipeline import run_gate
    from app.store.seed import load_library

    settings = Settings()
    templates = TemplateIndex(load_library(settings.templates_dir))
    run_gate(SAMPLE, templates=templates, analyzer=SymbolicAnalyzer(reject_from=settings.theta))


try:
    warm_up()
except Exception:  # a cold start is still a correct start
    logging.getLogger("safegate.analysis_pool").warning("analysis warm-up failed",
                                                        exc_info=True)
