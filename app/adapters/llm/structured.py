"""Ask for a structured answer: call, parse, validate, one repair round, then give up.

In: a `ChatClient`, the system and user prompts, the pydantic model the answer must fit and an
optional semantic check (e.g. "every entity id is in the scene"). Out: the validated model.
Prose or a Markdown fence around the one JSON object is tolerated (models add them even when
told not to); the object itself must still fit the model exactly.
Fails: `LlmOutputInvalid` when the answer is not JSON, is cut short, does not fit the model or
fails the check, twice in a row (the second time after being told what was wrong), carrying
the last answer's problems (`LlmOutputInvalid.problems`); any
transport `LlmError` (timeout, 429, 5xx) at once, with no repair round. Never returns text.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from typing import TypeVar

from pydantic import BaseModel, ValidationError

from app.adapters.llm.client import ChatAnswer, ChatClient, Message
from app.adapters.llm.errors import LlmOutputInvalid
from app.adapters.llm.prompting import PromptSet
from app.adapters.llm.schemas import json_schema

AnswerT = TypeVar("AnswerT", bound=BaseModel)
Check = Callable[[AnswerT], Sequence[str]]
REPAIR_ROUNDS = 1
_ECHO_LIMIT = 6000
# Enough for the twelve matrix cells of a batched answer, each named in the repair prompt.
_PROBLEMS_SHOWN = 16


class _Unusable(Exception):
    """Why one answer cannot be used, phrased for the repair prompt."""

    def __init__(self, message: str, problems: Sequence[str] = ()) -> None:
        super().__init__(message)
        self.problems = tuple(problems) or (message,)


def ask_structured(
    client: ChatClient,
    *,
    system: str,
    user: str,
    answer_model: type[AnswerT],
    prompts: PromptSet,
    check: Check[AnswerT] | None = None,
) -> AnswerT:
    """Get an answer that parses into `answer_model` and passes `check`.

    Args:
        client: the chat client.
        system: the system prompt.
        user: the user prompt.
        answer_model: the pydantic model the JSON answer must fit.
        prompts: the prompt set holding the `repair` prompt.
        check: extra validation returning problems (empty when the answer is usable).

    Returns:
        The validated answer.

    Raises:
        LlmOutputInvalid: the answer stayed unusable after the repair round.
        LlmError: the call itself failed.
    """
    schema = json_schema(answer_model)
    messages: list[Message] = [
        {"role": "system", "content": system},
        {"role": "user", "content": user},
    ]
    problem = ""
    problems: tuple[str, ...] = ()
    for round_number in range(REPAIR_ROUNDS + 1):
        answer = client.complete(messages, schema_name=answer_model.__name__, schema=schema)
        try:
            return _parse(answer, answer_model, check)
        except _Unusable as unusable:
            problem, problems = str(unusable), unusable.problems
        if round_number < REPAIR_ROUNDS:
            messages = [
                *messages,
                {"role": "assistant", "content": answer.text[:_ECHO_LIMIT]},
                {"role": "user", "content": prompts.render("repair", error=problem)},
            ]
    raise LlmOutputInvalid(
        f"{client.model} gave no usable {answer_model.__name__} after "
        f"{REPAIR_ROUNDS} repair round(s): {problem}",
        problems=problems,
    )


def _parse(answer: ChatAnswer, model: type[AnswerT], check: Check[AnswerT] | None) -> AnswerT:
    if answer.finish_reason == "length":
        raise _Unusable("the answer was cut off at the length limit; answer more briefly")
    text = _without_code_fence(answer.text.strip())
    if not text:
        raise _Unusable("the answer was empty")
    try:
        data = _json_in(text)
    except json.JSONDecodeError as error:
        where = f"{error.msg} at char {error.pos}"
        raise _Unusable(f"the answer is not valid JSON ({where})") from error
    if not isinstance(data, dict):
        raise _Unusable("the answer must be a JSON object")
    try:
        parsed = model.model_validate(data)
    except ValidationError as error:
        raise _Unusable(f"the answer does not fit the schema: {_summary(error)}") from error
    problems = list(check(parsed)) if check is not None else []
    if problems:
        raise _Unusable("; ".join(problems[:_PROBLEMS_SHOWN]), problems)
    return parsed


def _json_in(text: str) -> object:
    """The JSON answer, also when a model wrapped it in prose ("Here is the matrix: {...}")."""
    try:
        return json.loads(text)
    except json.JSONDecodeError:
        start = text.find("{")
        if start < 0:
            raise
        # Only one complete object is taken; prose after it is ignored, a second object is not
        # merged in, and a truncated object still fails to decode.
        data, _ = json.JSONDecoder().raw_decode(text, start)
        return data


def _without_code_fence(text: str) -> str:
    # Some models wrap JSON in a Markdown fence even when asked not to; the fence is not content.
    if text.startswith("```") and text.endswith("```") and len(text) >= 6:
        body = text[3:-3]
        first_newline = body.find("\n")
        return body[first_newline + 1 :].strip() if first_newline >= 0 else body.strip()
    return text


def _summary(error: ValidationError) -> str:
    parts = []
    for item in error.errors()[:8]:
        where = ".".join(str(p) for p in item["loc"]) or "(root)"
        parts.append(f"{where}: {item['msg']}")
    return "; ".join(parts)
