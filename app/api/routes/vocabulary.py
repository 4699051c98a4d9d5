"""GET /vocabulary: the condition language's symbols and the action model."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter

from app.domain.formula.vocabulary import VOCABULARY
from app.domain.world import describe_actions

router = APIRouter(tags=["vocabulary"])


@router.get("/vocabulary", summary="List the condition language and the action model")
def get_vocabulary() -> dict[str, Any]:
    """Every predicate and function a condition may use, and every action a plan may use."""
    symbols = [
        {
            "name": s.name,
            "args": list(s.args),
            "result": s.result,
            "meaning": s.meaning,
            "can_be_unknown": s.can_be_unknown,
        }
        for s in VOCABULARY.values()
    ]
    return {"symbols": symbols, "actions": describe_actions()}
