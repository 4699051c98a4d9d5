"""GET /vocabulary: the condition language's symbols and the action model."""

from __future__ import annotations

from fastapi import APIRouter

from app.api.openapi import problem_responses
from app.api.read_schemas import VocabularyResponse
from app.domain.formula.vocabulary import VOCABULARY
from app.domain.world import describe_actions

router = APIRouter(tags=["vocabulary"])


@router.get("/vocabulary", response_model=VocabularyResponse,
            response_model_exclude_unset=True,
            summary="List the condition language and the action model",
            responses=problem_responses(
                (500, "Failed unexpectedly (never expected: the vocabulary is built in).")))
def get_vocabulary() -> VocabularyResponse:
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
    return VocabularyResponse.model_validate({"symbols": symbols, "actions": describe_actions()})
