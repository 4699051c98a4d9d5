"""Answers as real models write them: each ends in the right decision or a defer, never a wrong
authorize.

A scripted model answers every prompt of the analysis (the three levels, the entity round and
repairs) honestly, then one distortion is applied: a Markdown fence, prose around the JSON, a
misspelt or invented class, hazards a later level does not restate, a list cut off mid-way, or
the output of a model that followed an injected instruction at one level. Two requests: one the
honest analysis authorizes, one it defers. A distortion the analyzer can see through keeps the
decision; every other one ends in a defer, never an authorize the honest analysis did not give.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import pytest

from app.adapters.llm import LitellmClient, LlmAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.gate import Decision
from app.domain.models import GateRequest
from app.domain.pipeline import GateResult, run_gate
from tests.adapters.llm.answers import (
    SAFE_REQUEST,
    TWO_PEOPLE_REQUEST,
    hazard,
    honest_script,
    with_cells,
)
from tests.adapters.llm.scripted_server import Scripted, ScriptedServer
from tests.conftest import seed_library

ClientFactory = Callable[..., LitellmClient]
Distort = Callable[[dict[str, Any], str, bool], Scripted]
_LEVEL = re.compile(r"^Level: (task|deployment|user)\.", re.M)


def _plain(answer: dict[str, Any]) -> Scripted:
    return Scripted(content=json.dumps(answer))


def _respell(answer: dict[str, Any], spelling: Callable[[str], str]) -> dict[str, Any]:
    return {**answer, "hazards": [{**h, "hazard_class": spelling(h["hazard_class"])}
                                  for h in answer["hazards"]]}


def fenced(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    return Scripted(content=f"```json\n{json.dumps(answer, indent=2)}\n```")


def prose_around(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    return Scripted(content=f"Here is the {level} level of the matrix:\n{json.dumps(answer)}\n"
                            "Let me know if you need anything else.")


def misspelt_once(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    if level == "deployment" and not repair:
        return _plain(_respell(answer, lambda c: c.replace("_", "-", 1).replace("-", "_") + "s"))
    return _plain(answer)


def misspelt_always(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    if level == "deployment":
        return _plain(_respell(answer, lambda c: c + "s"))
    return _plain(answer)


def invented_class(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    if level == "user":
        made_up = hazard("robot_feels_nervous", category="psychological", severity="negligible")
        return _plain({**answer, "hazards": [*answer["hazards"], made_up]})
    return _plain(answer)


def unrestated(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    if level in ("deployment", "user"):
        # The model answers the cells ("none new") but does not repeat the earlier hazards.
        cells_left = {k: v for k, v in answer.items() if k != "none_because"}
        return _plain(with_cells({**cells_left, "hazards": []}))
    return _plain(answer)


def truncated_once(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    if level == "user" and not repair:
        text = json.dumps(answer)
        return Scripted(content=text[: len(text) // 2], finish_reason="length")
    return _plain(answer)


def truncated_always(answer: dict[str, Any], level: str, repair: bool) -> Scripted:
    if level == "user":
        text = json.dumps(answer)
        return Scripted(content=text[: text.index("}") + 1], finish_reason="length")
    return _plain(answer)


def obeys_an_injection_to_report_nothing(answer: dict[str, Any], level: str,
                                         repair: bool) -> Scripted:
    if level == "user":
        return _plain(with_cells({"hazards": [], "unknowns": []}))
    return _plain(answer)


def obeys_an_injection_to_report_nothing_without_cells(answer: dict[str, Any], level: str,
                                                       repair: bool) -> Scripted:
    if level == "user":
        return Scripted(content='{"hazards": [], "unknowns": []}')
    return _plain(answer)


def obeys_an_injection_to_dismiss_everything(answer: dict[str, Any], level: str,
                                             repair: bool) -> Scripted:
    if level == "user":
        everything = [{"kind": "hazard", "name": h["hazard_class"], "why": "as instructed"}
                      for h in answer["hazards"]]
        everything += [{"kind": "unknown", "name": u["attribute"], "why": "as instructed"}
                       for u in answer["unknowns"]]
        return _plain(with_cells({"hazards": [], "unknowns": [], "dismissed": everything}))
    return _plain(answer)


@dataclass(frozen=True)
class Distortion:
    distort: Distort
    keeps_decision: bool


DISTORTIONS = {
    "fenced JSON": Distortion(fenced, True),
    "prose around the JSON": Distortion(prose_around, True),
    "misspelt class, repaired": Distortion(misspelt_once, True),
    "misspelt class, kept": Distortion(misspelt_always, False),
    "invented class": Distortion(invented_class, False),
    "hazards not restated": Distortion(unrestated, True),
    "list cut off, repaired": Distortion(truncated_once, True),
    "list cut off twice": Distortion(truncated_always, False),
    # Silence at one level is not evidence: what the earlier levels found still decides.
    "followed an injection: nothing": Distortion(obeys_an_injection_to_report_nothing, True),
    # ...but a level that leaves its four cells unanswered, repair or not, is not understood.
    "followed an injection: nothing, no cells": Distortion(
        obeys_an_injection_to_report_nothing_without_cells, False),
    "followed an injection: dismiss all": Distortion(obeys_an_injection_to_dismiss_everything,
                                                     False),
}
REQUESTS = {"authorized when honest": SAFE_REQUEST, "deferred when honest": TWO_PEOPLE_REQUEST}


def _responder(request: GateRequest, distort: Distort) -> Callable[[dict[str, Any]], Scripted]:
    honest = honest_script(request)

    def answer(body: dict[str, Any]) -> Scripted:
        messages = body["messages"]
        found = _LEVEL.search(messages[1]["content"])
        level = found.group(1) if found else "entities"
        return distort(honest[level], level, len(messages) > 2)

    return answer


def _gate(request: GateRequest, client: LitellmClient) -> GateResult:
    return run_gate(request, templates=TemplateIndex(seed_library()),
                    analyzer=LlmAnalyzer(client))


@pytest.mark.parametrize("request_name", list(REQUESTS))
@pytest.mark.parametrize("name", list(DISTORTIONS))
def test_a_realistic_answer_never_buys_a_wrong_authorize(
    llm_server: ScriptedServer, make_client: ClientFactory, name: str, request_name: str
) -> None:
    request = REQUESTS[request_name]
    llm_server.responder = _responder(request, lambda answer, level, repair: _plain(answer))
    honest = _gate(request, make_client()).decision.decision
    assert honest is (Decision.AUTHORIZE if request == SAFE_REQUEST else Decision.DEFER)

    distortion = DISTORTIONS[name]
    llm_server.responder = _responder(request, distortion.distort)
    decided = _gate(request, make_client()).decision.decision
    if distortion.keeps_decision:
        assert decided is honest
    else:
        assert decided is Decision.DEFER
