"""Hand-written case files: a YAML file of one grid cell read into `Case` records.

In: a case file `data/<domain>_<complexity>.yaml` (its format: `bench/cases/README.md`, "Case
files"): per case a command, a `why` and a scene written with the presets of `kit.py`
(layouts, fixture sets such as `kitchen`, robot presets), under its label. Out: `Case` records
whose scene, user and robot are the gate-request JSON `kit.py` builds.
Fails: `CaseError` naming the file, label and case number on an unknown key, layout, fixture set
or robot preset, or a key YAML read as a boolean (a bare `on:`).
"""

from __future__ import annotations

from pathlib import Path

import yaml

from bench.cases.kit import FIXTURE_SETS, Case, CaseError, Json, o, p, robot, scene, user

LABELS = ("safe", "unsafe", "ambiguous")
CASE_KEYS = {"category", "reasoning", "steps", "command", "why", "scene", "user",
             "robot", "missing"}
USER_KEYS = {"person_id": "person_id", "age_group": "age", "mobility": "mobility",
             "cognitive_state": "cog", "allergies": "allergies", "unknowns": "unknowns"}


def _check_keys(entry: Json) -> None:
    # YAML 1.1 reads an unquoted `on:` or `off:` key as a boolean: the switched-on property
    # must be written `'on': true`.
    if not all(isinstance(key, str) for key in entry):
        raise CaseError(f"a non-text key in {entry} (quote 'on', 'off', 'yes', 'no')")
    for value in entry.values():
        if isinstance(value, dict):
            _check_keys(value)


def _object_entries(entry: str | Json) -> list[Json]:
    """A fixture set (`kitchen`, `{kitchen: kitchenette}`, `{kitchen: {stove_1: {...}}}`) or
    one object (`{id, type, room, at, inside, name, <property>...}`)."""
    if isinstance(entry, str):
        return FIXTURE_SETS[entry]()
    _check_keys(entry)
    if "id" not in entry:
        ((name, spec),) = entry.items()
        return FIXTURE_SETS[name](spec) if isinstance(spec, str) else FIXTURE_SETS[name](**spec)
    fields = dict(entry)
    return [o(fields.pop("id"), fields.pop("type"), fields.pop("room", None),
              at=fields.pop("at", None), inside=fields.pop("inside", None),
              name=fields.pop("name", None), **fields)]


def _person(entry: Json) -> Json:
    """A person `{id, role, room, posture, name, <property>...}`; the rest are properties."""
    _check_keys(entry)
    fields = dict(entry)
    return p(fields.pop("id"), fields.pop("role"), fields.pop("room", None),
             age=fields.pop("age_group", None), mobility=fields.pop("mobility", None),
             cog=fields.pop("cognitive_state", None), posture=fields.pop("posture", None),
             name=fields.pop("name", None), **fields)


def _scene(entry: Json) -> Json:
    objects = [x for item in entry.get("objects", []) for x in _object_entries(item)]
    people = [_person(x) for x in entry.get("people", [])]
    unknown = set(entry) - {"layout", "objects", "people", "relations", "obstacles"}
    if unknown:
        raise CaseError(f"unknown scene keys {sorted(unknown)}")
    return scene(entry["layout"], objects, people, entry.get("relations"),
                 entry.get("obstacles"))


def _user(entry: Json) -> Json:
    unknown = set(entry) - set(USER_KEYS)
    if unknown:
        raise CaseError(f"unknown user keys {sorted(unknown)}")
    return user(**{USER_KEYS[key]: value for key, value in entry.items()})


def _case(entry: Json, label: str, domain: str, complexity: str) -> Case:
    unknown = set(entry) - CASE_KEYS
    if unknown:
        raise CaseError(f"unknown case keys {sorted(unknown)}")
    robot_fields = dict(entry["robot"])
    return Case(domain, complexity, label, entry["category"], entry["reasoning"],
                entry["steps"], entry["command"], entry["why"], _scene(entry["scene"]),
                _user(entry["user"]),
                robot(robot_fields.pop("preset"), robot_fields.pop("room"), **robot_fields),
                list(entry.get("missing", [])))


def read_cases(path: Path) -> list[Case]:
    """The cases of one hand-written case file: its safe, then unsafe, then ambiguous ones.

    Args:
        path: a YAML file with `domain`, `complexity` and a list of cases under each label.

    Returns:
        One `Case` per entry.

    Raises:
        CaseError: on an unknown key, fixture set, layout or robot preset, naming the case.
    """
    document = yaml.safe_load(path.read_text(encoding="utf-8"))
    unknown = set(document) - {"domain", "complexity", *LABELS}
    if unknown:
        raise CaseError(f"{path.name}: unknown keys {sorted(unknown)}")
    cases: list[Case] = []
    for label in LABELS:
        for number, entry in enumerate(document.get(label, []), start=1):
            try:
                cases.append(_case(entry, label, document["domain"], document["complexity"]))
            except (CaseError, KeyError, TypeError, ValueError) as error:
                raise CaseError(f"{path.name}, {label} case {number}: {error!r}") from error
    return cases
