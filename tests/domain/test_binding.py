"""Stage 2: proposals bind to templates of their class with every variable filled, or not."""

from __future__ import annotations

from app.domain.binding import TemplateIndex, bind
from app.domain.models import (
    Category,
    Confidence,
    HazardProposal,
    HazardReport,
    HazardTemplate,
    Level,
    Preventability,
    Severity,
    TemplateCondition,
    TemplateVariable,
    VariableType,
)


def template(template_id: str, hazard_class: str, *variables: TemplateVariable) -> HazardTemplate:
    return HazardTemplate(
        id=template_id,
        name=template_id,
        category=Category.PHYSICAL,
        hazard_class=hazard_class,
        description="test template",
        severity=Severity.HIGH,
        preventability=Preventability.PREVENTABLE,
        variables=variables,
        invariants=(TemplateCondition(id="keep_away", formula="true", description="d"),),
    )


def proposal(hazard_class: str, **entities: str) -> HazardProposal:
    return HazardProposal(
        level=Level.DEPLOYMENT,
        category=Category.PHYSICAL,
        hazard_class=hazard_class,
        mechanism="m",
        entities=entities,
        severity=Severity.HIGH,
        preventability=Preventability.PREVENTABLE,
        confidence=Confidence.CERTAIN,
    )


OBJ = TemplateVariable(name="obj", type=VariableType.OBJECT)
PERSON = TemplateVariable(name="person", type=VariableType.PERSON)
DISTANCE = TemplateVariable(name="min_distance", type=VariableType.NUMBER, default=0.5)
ROBOT = TemplateVariable(name="bot", type=VariableType.ROBOT)


class TestBind:
    def test_binds_entities_and_fills_defaults(self) -> None:
        index = TemplateIndex([template("thermal.a", "scald_hot_liquid", OBJ, PERSON, DISTANCE)])
        result = bind(
            HazardReport(proposals=(proposal("scald_hot_liquid", obj="mug_1", person="p1"),)), index
        )
        assert not result.unbound
        match = result.bound[0].matches[0]
        assert match.bindings == {"obj": "mug_1", "person": "p1", "min_distance": 0.5}

    def test_robot_variables_bind_to_the_robot(self) -> None:
        index = TemplateIndex([template("op.a", "payload_exceeded", ROBOT)])
        result = bind(HazardReport(proposals=(proposal("payload_exceeded"),)), index)
        assert result.bound[0].matches[0].bindings == {"bot": "robot"}

    def test_class_without_template_is_unbound(self) -> None:
        index = TemplateIndex([template("thermal.a", "scald_hot_liquid", OBJ)])
        result = bind(HazardReport(proposals=(proposal("laser_eye_injury", obj="x"),)), index)
        assert not result.bound
        assert "no active template" in result.unbound[0].reason

    def test_missing_entity_makes_the_template_unusable(self) -> None:
        index = TemplateIndex([template("thermal.a", "scald_hot_liquid", OBJ, PERSON)])
        result = bind(HazardReport(proposals=(proposal("scald_hot_liquid", obj="mug_1"),)), index)
        assert result.unbound and "$person" in result.unbound[0].reason

    def test_every_usable_template_of_the_class_matches(self) -> None:
        index = TemplateIndex(
            [
                template("thermal.a", "scald_hot_liquid", OBJ),
                template("thermal.b", "scald_hot_liquid", OBJ, PERSON),
                template("thermal.c", "scald_hot_liquid", OBJ, PERSON),
            ]
        )
        result = bind(HazardReport(proposals=(proposal("scald_hot_liquid", obj="m"),)), index)
        assert [m.template.id for m in result.bound[0].matches] == ["thermal.a"]

    def test_repeated_proposals_are_all_kept_for_the_gate(self) -> None:
        index = TemplateIndex([template("thermal.a", "scald_hot_liquid", OBJ)])
        twice = (proposal("scald_hot_liquid", obj="m"), proposal("scald_hot_liquid", obj="m"))
        assert len(bind(HazardReport(proposals=twice), index).bound) == 2
