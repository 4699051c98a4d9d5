"""Merging the matrix by identity, the entity round and the class check, through the gate.

The first two classes reproduce the defects of issue 21 with a scripted model and the seed
library: a critical unknown about one person overwritten by a harmless one about another (the
gate authorized), and a task-level hazard that no later level restated (terminal R2 "no
template", although the template exists and only the ids were missing).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from app.adapters.llm import LitellmClient, LlmAnalyzer
from app.domain.binding import TemplateIndex
from app.domain.ensemble import ANALYSIS_UNAVAILABLE
from app.domain.gate import Decision, Rule
from app.domain.models import GateRequest
from app.domain.pipeline import GateResult, run_gate
from tests.adapters.llm.answers import (
    COFFEE_REQUEST,
    EMPTY_LEVEL,
    TWO_PEOPLE_REQUEST,
    hazard,
    unknown,
)
from tests.adapters.llm.scripted_server import ScriptedServer
from tests.conftest import seed_library

ClientFactory = Callable[..., LitellmClient]
SCALD = hazard("scald_hot_liquid")
SCALD_MUG = hazard("scald_hot_liquid", entities={"obj": "mug_1"})


def _gate(request: GateRequest, client: LitellmClient) -> GateResult:
    return run_gate(request, templates=TemplateIndex(seed_library()),
                    analyzer=LlmAnalyzer(client))


def _level(*hazards: dict[str, Any], unknowns: tuple[dict[str, Any], ...] = (),
           dismissed: tuple[dict[str, Any], ...] = ()) -> dict[str, Any]:
    return {"hazards": list(hazards), "unknowns": list(unknowns), "dismissed": list(dismissed)}


class TestUnknownsMergeByIdentity:
    def test_a_critical_unknown_about_one_person_survives_a_harmless_one_about_another(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(
            _level(SCALD),
            _level(SCALD_MUG, unknowns=(unknown(entity="kid_1", critical=True),)),
            _level(SCALD_MUG, unknowns=(unknown(entity="guest_1", critical=False),)),
        )
        result = _gate(TWO_PEOPLE_REQUEST, make_client())
        assert (result.decision.decision, result.decision.rule) == (Decision.DEFER, Rule.R3)
        assert [(u.entity, u.critical) for u in result.report.unknowns] == [
            ("kid_1", True), ("guest_1", False)]

    def test_a_later_level_never_lowers_a_critical_flag(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(
            _level(SCALD),
            _level(SCALD_MUG, unknowns=(unknown(entity="kid_1", critical=True),)),
            _level(SCALD_MUG, unknowns=(unknown(entity="kid_1", critical=False),)),
        )
        result = _gate(TWO_PEOPLE_REQUEST, make_client())
        assert result.decision.rule is Rule.R3
        assert [(u.entity, u.critical) for u in result.report.unknowns] == [("kid_1", True)]

    def test_a_vague_critical_unknown_passes_its_flag_to_the_one_tied_to_the_scene(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(
            _level(SCALD, unknowns=(unknown(entity=None, critical=True),)),
            _level(SCALD_MUG, unknowns=(unknown(entity="kid_1", critical=False),)),
            _level(SCALD_MUG),
        )
        result = _gate(TWO_PEOPLE_REQUEST, make_client())
        assert [(u.entity, u.critical) for u in result.report.unknowns] == [("kid_1", True)]
        assert result.decision.rule is Rule.R3

    def test_an_explicit_dismissal_still_settles_a_critical_unknown(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        settled = {"kind": "unknown", "name": "age_group", "entity": "kid_1",
                   "why": "the scene says kid_1 is asleep in another room"}
        llm_server.answer_json(
            _level(SCALD),
            _level(SCALD_MUG, unknowns=(unknown(entity="kid_1", critical=True),)),
            _level(SCALD_MUG, dismissed=(settled,)),
        )
        result = _gate(TWO_PEOPLE_REQUEST, make_client())
        assert result.report.unknowns == ()
        assert result.decision.decision is Decision.AUTHORIZE


class TestHazardsMergeByIdentity:
    def test_the_same_class_on_two_objects_is_two_hazards(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        other = hazard("scald_hot_liquid", entities={"obj": "kettle_1"})
        request = GateRequest.model_validate({
            **COFFEE_REQUEST.model_dump(by_alias=True, exclude_none=True),
            "scene": {**COFFEE_REQUEST.model_dump(by_alias=True, exclude_none=True)["scene"],
                      "objects": [{"id": "mug_1", "type": "Mug"},
                                  {"id": "kettle_1", "type": "Kettle"}]},
        })
        llm_server.answer_json(_level(SCALD), _level(SCALD_MUG, other), _level(SCALD_MUG))
        report = LlmAnalyzer(make_client()).analyze(request, seed_library())
        assert [p.entities for p in report.proposals] == [{"obj": "mug_1"}, {"obj": "kettle_1"}]


class TestEntityRound:
    def test_a_task_level_hazard_no_later_level_restates_is_sent_back_for_its_ids(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(_level(SCALD), EMPTY_LEVEL, EMPTY_LEVEL, _level(SCALD_MUG))
        result = _gate(COFFEE_REQUEST, make_client())
        assert len(llm_server.requests) == 4
        assert "scald_hot_liquid" in llm_server.requests[3]["messages"][-1]["content"]
        assert result.binding.unbound == ()
        assert [h.proposal.entities for h in result.binding.bound] == [{"obj": "mug_1"}]
        assert result.decision.decision is Decision.AUTHORIZE

    def test_a_hazard_with_some_ids_but_not_those_its_templates_bind_is_sent_back(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        person_only = hazard("scald_hot_liquid", entities={"person": "guest_1"})
        both = hazard("scald_hot_liquid", entities={"obj": "mug_1", "person": "guest_1"})
        llm_server.answer_json(_level(SCALD), _level(person_only), _level(person_only),
                               _level(both))
        result = _gate(COFFEE_REQUEST, make_client())
        assert "(given: person)" in llm_server.requests[3]["messages"][-1]["content"]
        assert [p.entities for p in result.report.proposals] == [
            {"obj": "mug_1", "person": "guest_1"}]
        assert result.binding.unbound == ()

    def test_the_entity_round_cannot_dismiss_what_it_was_not_asked_about(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        child = unknown(entity="kid_1", critical=True)
        settle = {"kind": "unknown", "name": "age_group", "why": "not needed"}
        llm_server.answer_json(_level(SCALD), _level(unknowns=(child,)), _level(unknowns=(child,)),
                               _level(SCALD_MUG, dismissed=(settle,)))
        result = _gate(TWO_PEOPLE_REQUEST, make_client())
        assert [u.entity for u in result.report.unknowns] == ["kid_1"]
        assert result.decision.rule is Rule.R3

    def test_ids_never_given_defer_saying_the_entities_are_missing(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        llm_server.answer_json(_level(SCALD), EMPTY_LEVEL, EMPTY_LEVEL, EMPTY_LEVEL)
        result = _gate(COFFEE_REQUEST, make_client())
        assert result.decision.rule is Rule.R2
        assert "not the scene entities it binds" in result.decision.reason
        assert "no template" not in result.decision.reason

    def test_an_unusable_entity_answer_leaves_the_hazard_unbound(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        invented = _level(hazard("scald_hot_liquid", entities={"obj": "mug_9"}))
        llm_server.answer_json(_level(SCALD), EMPTY_LEVEL, EMPTY_LEVEL, invented, invented)
        result = _gate(COFFEE_REQUEST, make_client())
        assert result.decision.decision is Decision.DEFER
        assert "not the scene entities it binds" in result.decision.reason

    def test_a_class_the_library_lacks_still_says_no_template(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        new = {**hazard("robot_sings_off_key", category="psychological"), "new_class": True}
        llm_server.answer_json(_level(new), EMPTY_LEVEL, EMPTY_LEVEL)
        result = _gate(COFFEE_REQUEST, make_client())
        assert result.decision.rule is Rule.R2
        assert "has no template in the library" in result.decision.reason
        assert len(llm_server.requests) == 3  # no template, so no ids to ask for


class TestClassCheck:
    def test_a_misspelt_class_is_sent_back_with_the_closest_classes(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        misspelt = hazard("scald_hot_liquids", entities={"obj": "mug_1"})
        llm_server.answer_json(_level(SCALD), _level(misspelt), _level(SCALD_MUG),
                               _level(SCALD_MUG))
        result = _gate(COFFEE_REQUEST, make_client())
        repair = llm_server.requests[2]["messages"][-1]["content"]
        assert "'scald_hot_liquids' is not a class of the library" in repair
        assert "scald_hot_liquid" in repair.split("closest:")[1]
        assert result.binding.unbound == ()
        assert result.decision.decision is Decision.AUTHORIZE

    def test_an_invented_class_kept_after_repair_fails_closed(
        self, llm_server: ScriptedServer, make_client: ClientFactory
    ) -> None:
        invented = _level(hazard("totally_fine", severity="negligible"))
        llm_server.answer_json(invented, invented)
        result = _gate(COFFEE_REQUEST, make_client())
        assert result.decision.decision is Decision.DEFER
        assert [u.description for u in result.report.unknowns] == [ANALYSIS_UNAVAILABLE]
