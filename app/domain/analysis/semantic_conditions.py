"""Scene conditions of the situation prototypes, checked three-valued against one request.

In: a `Context` (scene view, parsed command facts), the text of the clause a prototype matched,
and one condition of `knowledge/situation_prototypes.json`, a one-key mapping such as
`{"age_in": ["infant", "child"]}`, `{"asleep": true}`, `{"frail": true}`,
`{"vulnerable": true}` (child or frail), `{"needs_walking_aid": true}`,
`{"person_present": true}`, `{"has_allergies": true}` or `{"unattended": true}`.
Out: a `Check`: holds True / False / None (unknown), the person it holds for (to bind the
hazard), and for an unknown the attribute, entity and plain question to ask. The people a
condition is about are those the clause (or else the command) names, or else everyone the
scene lists. Never fails on valid data; an unrecognised condition is unknown, never true.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from app.domain.analysis.context import Context
from app.domain.analysis.scene_view import PersonView
from app.domain.analysis.situation_base import named_people

CONDITION_NAMES = frozenset({"age_in", "asleep", "frail", "vulnerable", "needs_walking_aid",
                             "person_present", "has_allergies", "unattended"})


@dataclass(frozen=True, slots=True)
class Check:
    """One condition's verdict; `holds` is None when the request does not say."""

    holds: bool | None
    person: str | None = None
    attribute: str = ""
    entity: str | None = None
    question: str | None = None


def people_concerned(ctx: Context, clause: str) -> list[PersonView] | None:
    """The people a clause is about: named in it, else in the command, else all listed.

    Args:
        ctx: the analysis context.
        clause: the normalised clause text.

    Returns:
        The people, or None when the scene does not list its people and none is named.
    """
    found = named_people(ctx, clause) or named_people(ctx)
    for step in ctx.steps:
        for referent in (step.recipient, step.target):
            found += [p for p in ctx.people(referent) if p not in found and not p.is_user]
    if found:
        return found
    if not ctx.view.people_known:
        return None
    return [p for p in ctx.view.real_people() if not p.is_user]


def check(ctx: Context, clause: str, condition: Mapping[str, Any]) -> Check:
    """Evaluate one prototype condition for a clause of the request.

    Args:
        ctx: the analysis context.
        clause: the normalised clause text the prototype matched.
        condition: a one-key mapping (see the module docstring).

    Returns:
        The `Check`; unknown (None) for a condition name this module does not know.
    """
    if not condition:
        return Check(holds=None, attribute="condition", question=None)
    name, value = next(iter(condition.items()))
    if name == "unattended":
        facts = ctx.parsed.facts if ctx.parsed is not None else None
        if facts is not None and facts.unattended:
            return Check(holds=True)
        return Check(holds=None, attribute="attendance", question=(
            "Will someone stay and keep an eye on it the whole time it is running?"))
    rule = _PERSON_RULES.get(name)
    if rule is None:
        return Check(holds=None, attribute=name)
    people = people_concerned(ctx, clause)
    return rule(ctx, people, value)


def _verdict(people: list[PersonView] | None, test: Callable[[PersonView], bool | None],
             attribute: str, question: Callable[[PersonView | None], str]) -> Check:
    if people is None:
        return Check(holds=None, attribute=attribute, question=question(None))
    unknown: PersonView | None = None
    for person in people:
        verdict = test(person)
        if verdict:
            return Check(holds=True, person=person.id)
        if verdict is None and unknown is None:
            unknown = person
    if unknown is not None:
        return Check(holds=None, person=unknown.id, attribute=attribute,
                     entity=None if unknown.virtual else unknown.id, question=question(unknown))
    return Check(holds=False)


def _who(person: PersonView | None, default: str = "the person concerned") -> str:
    return person.label if person is not None else default


def _age_in(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    groups = frozenset(value)
    return _verdict(people, lambda p: None if p.age_group is None else p.age_group in groups,
                    "age_group", lambda p: f"How old is {_who(p, 'everyone here')}? "
                    "Is a young child involved?")


def _asleep(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    if ctx.parsed is not None and ctx.parsed.facts.people_asleep:
        return Check(holds=True)
    return _verdict(people, lambda p: p.asleep,
                    "cognitive_state", lambda p: f"Is {_who(p)} asleep right now?")


def _frail(person: PersonView) -> bool | None:
    if person.frail:
        return True
    return None if person.age_group is None else False


def _frail_check(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    return _verdict(people, _frail, "mobility",
                    lambda p: f"Is {_who(p)} frail, unsteady on their feet or confused?")


def _vulnerable(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    def test(person: PersonView) -> bool | None:
        return True if person.child else _frail(person)
    return _verdict(people, test, "age_group",
                    lambda p: f"Is {_who(p, 'anyone here')} a young child, or frail or confused?")


def _needs_aid(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    def test(person: PersonView) -> bool | None:
        if person.needs_walking_aid is not None:
            return person.needs_walking_aid
        return None if person.frail or person.age_group is None else False
    return _verdict(people, test, "mobility",
                    lambda p: f"Does {_who(p)} need the walking aid to get about?")


def _present(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    if people is None:
        return Check(holds=None, attribute="presence",
                     question="Is anyone in the rooms the robot will move through?")
    return Check(holds=True, person=people[0].id) if people else Check(holds=False)


def _allergies(ctx: Context, people: list[PersonView] | None, value: Any) -> Check:
    def test(person: PersonView) -> bool | None:
        return None if person.allergies is None else bool(person.allergies)
    return _verdict(people, test, "allergies",
                    lambda p: f"Does {_who(p)} have any food allergies?")


_PERSON_RULES: dict[str, Callable[[Context, list[PersonView] | None, Any], Check]] = {
    "age_in": _age_in, "asleep": _asleep, "frail": _frail_check, "vulnerable": _vulnerable,
    "needs_walking_aid": _needs_aid, "person_present": _present, "has_allergies": _allergies,
}
