"""The checks every benchmark case passes before it is written.

In: a `Case` read from a case file and the id it will get. Out: nothing when it is consistent.
Fails: `CaseError` naming the case: a step count outside its complexity band, a dangling object,
person or room id, an unsafe or ambiguous case without category and reasoning kind, a safe case
with a person of unknown age or whereabouts, or an ambiguous case whose declared missing fact
is in fact present.
"""

from __future__ import annotations

import re

from bench.cases.kit import Case, CaseError, Json

BANDS = {"simple": range(1, 5), "medium": range(5, 11), "complex": range(11, 200)}


def normalized_command(command: str) -> str:
    """The command as the repeat check compares it: lower case, words only."""
    return re.sub(r"[^a-z0-9]+", " ", command.lower()).strip()


def _check_references(case: Case, where: str) -> None:
    scene = case.scene
    rooms = set(scene["layout"]["rooms"])
    ids = {x["id"] for x in scene["objects"]} | {x["id"] for x in scene["people"]}
    for entity in scene["objects"] + scene["people"] + [case.robot]:
        if entity.get("room") is not None and entity["room"] not in rooms:
            raise CaseError(f"{where}: unknown room {entity['room']!r}")
    for x in scene["objects"]:
        for key in ("on", "in"):
            if key in x and x[key] not in ids:
                raise CaseError(f"{where}: {x['id']} {key} unknown {x[key]!r}")
    for r in scene["relations"]:
        if r["subject"] not in ids or r["object"] not in ids:
            raise CaseError(f"{where}: relation on unknown id {r}")
    person_id = case.user.get("person_id")
    if person_id is not None and person_id not in {x["id"] for x in scene["people"]}:
        raise CaseError(f"{where}: user {person_id!r} is not in the scene")
    if len(ids) != len(scene["objects"]) + len(scene["people"]):
        raise CaseError(f"{where}: repeated scene id")


def _missing_holds(case: Case, fact: Json) -> bool:
    objects = {x["id"]: x for x in case.scene["objects"]}
    people = {x["id"]: x for x in case.scene["people"]}
    kind = fact["kind"]
    if kind == "object_prop":
        return fact["attr"] not in objects[fact["id"]].get("properties", {})
    if kind == "person_attr":
        absent = fact["attr"] not in people[fact["id"]].get("properties", {})
        is_user = case.user.get("person_id") == fact["id"]
        return absent and not (is_user and case.user.get(fact["attr"]) is not None)
    if kind == "person_room":
        return people[fact["id"]].get("room") is None
    if kind == "user_attr":
        return case.user.get(fact["attr"]) is None
    if kind == "referent":
        kinds = {objects[i]["type"] for i in fact["ids"]}
        return len(fact["ids"]) >= 2 and len(kinds) == 1
    raise CaseError(f"unknown missing-fact kind {kind!r}")


def check_case(case: Case, where: str) -> None:
    """Raise `CaseError` when `case` (to be written as `where`) is inconsistent."""
    if case.steps not in BANDS[case.complexity]:
        raise CaseError(f"{where}: {case.steps} steps is not {case.complexity}")
    _check_references(case, where)
    if case.label != "safe" and (case.category is None or case.reasoning is None):
        raise CaseError(f"{where}: a {case.label} case needs a category and a reasoning kind")
    if case.label == "safe":
        for person in case.scene["people"]:
            if "age_group" not in person.get("properties", {}) or "room" not in person:
                raise CaseError(f"{where}: safe case with unknown age or room of {person['id']}")
    if case.label == "ambiguous" and not case.missing:
        raise CaseError(f"{where}: an ambiguous case must declare its missing fact")
    for fact in case.missing:
        if not _missing_holds(case, fact):
            raise CaseError(f"{where}: declared missing fact {fact} is present")
