"""The committed benchmark: size, label mix, grid coverage and structural honesty of labels."""

from __future__ import annotations

import json
import re
from collections import Counter
from pathlib import Path
from typing import Any

import pytest

from bench.case import COMPLEXITIES, DOMAINS, BenchmarkCase
from bench.cases.build_benchmark import DATA, build, render
from bench.score import load_cases

BENCHMARK = Path(__file__).resolve().parents[2] / "bench" / "cases" / "benchmark.jsonl"
STEP_BANDS = {"simple": (1, 4), "medium": (5, 10), "complex": (11, 10_000)}


@pytest.fixture(scope="module")
def cases() -> list[BenchmarkCase]:
    return load_cases(BENCHMARK)


@pytest.fixture(scope="module")
def raw() -> list[dict[str, Any]]:
    return [json.loads(x) for x in BENCHMARK.read_text(encoding="utf-8").splitlines() if x]


def _props(entity: dict[str, Any]) -> dict[str, Any]:
    value: dict[str, Any] = entity.get("properties", {})
    return value


class TestBenchmarkFile:
    def test_has_at_least_230_parsing_cases(self, cases: list[BenchmarkCase]) -> None:
        assert len(cases) >= 230
        assert len({c.id for c in cases}) == len(cases)

    def test_label_mix_is_near_the_papers(self, cases: list[BenchmarkCase]) -> None:
        labels = Counter(c.label for c in cases)
        assert abs(labels["safe"] - 83) <= 5
        assert abs(labels["unsafe"] - 100) <= 5
        assert abs(labels["ambiguous"] - 47) <= 5

    def test_every_grid_cell_holds_every_label(self, cases: list[BenchmarkCase]) -> None:
        cells = Counter((c.domain, c.complexity, c.label) for c in cases)
        for domain in DOMAINS:
            for complexity in COMPLEXITIES:
                for label in ("safe", "unsafe", "ambiguous"):
                    assert cells[(domain, complexity, label)] >= 4, (domain, complexity, label)

    def test_blocked_labels_name_a_category_and_reasoning(
        self, cases: list[BenchmarkCase]
    ) -> None:
        for case in cases:
            if case.label != "safe":
                assert case.category is not None and case.reasoning is not None, case.id
        kinds = Counter(c.reasoning for c in cases if c.label == "unsafe")
        assert {"compositional", "consequential_state", "direct"} <= set(kinds)
        categories = {c.category for c in cases if c.label == "unsafe"}
        assert categories == {"physical", "psychological", "operational", "consequential"}

    def test_commands_are_all_different(self, cases: list[BenchmarkCase]) -> None:
        normalized = [re.sub(r"[^a-z0-9]+", " ", c.request.command.lower()) for c in cases]
        assert len(set(normalized)) == len(normalized)

    def test_step_counts_match_complexity(self, raw: list[dict[str, Any]]) -> None:
        for record in raw:
            low, high = STEP_BANDS[record["complexity"]]
            assert low <= record["steps"] <= high, record["id"]

    def test_every_case_has_a_scene_user_and_robot(self, cases: list[BenchmarkCase]) -> None:
        for case in cases:
            request = case.request
            assert request.scene is not None and request.scene.layout is not None, case.id
            assert request.scene.objects or request.scene.people, case.id
            assert request.user is not None and request.robot is not None, case.id
            assert request.robot.skills, case.id

    def test_robots_vary(self, cases: list[BenchmarkCase]) -> None:
        names = {c.request.robot.name for c in cases if c.request.robot is not None}
        payloads = {c.request.robot.payload_kg for c in cases if c.request.robot is not None}
        assert len(names) >= 5 and len(payloads) >= 5

    def test_file_is_byte_for_byte_what_the_builder_writes(self) -> None:
        assert BENCHMARK.read_text(encoding="utf-8") == render(build())

    def test_the_nine_case_files_are_the_grid(self) -> None:
        names = sorted(path.name for path in DATA.glob("*.yaml"))
        assert names == sorted(f"{d}_{c}.yaml" for d in DOMAINS for c in COMPLEXITIES)


class TestLabelsAreStructurallyHonest:
    def test_safe_cases_know_everyones_age_and_room(self, raw: list[dict[str, Any]]) -> None:
        for record in raw:
            if record["label"] != "safe":
                continue
            for person in record["request"]["scene"]["people"]:
                assert "age_group" in _props(person), (record["id"], person["id"])
                assert person.get("room"), (record["id"], person["id"])

    def test_safe_cases_give_no_infant_a_hazard(self, raw: list[dict[str, Any]]) -> None:
        # A safe case may have an infant at home, but never in the room of a sharp,
        # toxic or hot object (a crude spot check of "no child near the knife").
        for record in raw:
            if record["label"] != "safe":
                continue
            scene = record["request"]["scene"]
            infant_rooms = {p["room"] for p in scene["people"]
                            if _props(p).get("age_group") == "infant"}
            for obj in scene["objects"]:
                props = _props(obj)
                dangerous = props.get("sharp") or props.get("toxic")
                assert not (dangerous and obj.get("room") in infant_rooms), record["id"]

    def test_gaps_mark_ambiguous_cases_not_safe_ones(self, raw: list[dict[str, Any]]) -> None:
        # The independent spot check sees a typical gap (unknown age, whereabouts, allergies,
        # contents, or an ambiguous referent) in most ambiguous cases and in few safe ones;
        # the rarer gaps (weight, material, last dose...) are covered by the declared check.
        def share(label: str) -> float:
            group = [r for r in raw if r["label"] == label]
            return sum(_has_a_gap(r["request"]) for r in group) / len(group)

        assert share("ambiguous") >= 0.6
        assert share("safe") <= 0.1

    def test_gap_check_passes_a_fully_specified_request(self) -> None:
        complete = {"scene": {
            "objects": [{"id": "cup_1", "type": "Cup", "properties": {"contents": "tea"}}],
            "people": [{"id": "p1", "room": "kitchen",
                        "properties": {"age_group": "adult", "allergies": []}}]}}
        assert not _has_a_gap(complete)
        unknown_age = json.loads(json.dumps(complete))
        del unknown_age["scene"]["people"][0]["properties"]["age_group"]
        assert _has_a_gap(unknown_age)

    def test_missing_facts_are_of_varied_kinds(self, raw: list[dict[str, Any]]) -> None:
        kinds = Counter(f["kind"] for r in raw if r["label"] == "ambiguous" for f in r["missing"])
        assert {"object_prop", "person_attr", "person_room", "referent"} <= set(kinds)

    def test_declared_missing_facts_are_absent(self, raw: list[dict[str, Any]]) -> None:
        for record in raw:
            if record["label"] == "ambiguous":
                assert record["missing"], record["id"]
            for fact in record["missing"]:
                assert _absent(record["request"], fact), (record["id"], fact)


FIXTURES = {"CounterTop", "StoveBurner", "StoveKnob", "Fridge", "SinkBasin", "Faucet",
            "Microwave", "Cabinet", "Drawer", "GarbageCan", "Sofa", "CoffeeTable", "Television",
            "FloorLamp", "Bed", "SideTable", "Dresser", "DeskLamp", "Toilet", "Bathtub",
            "Window", "Door", "LightSwitch", "Shelf", "Crib"}
CONTAINERS = {"Cup", "Mug", "Bottle", "SprayBottle", "Pitcher", "Jar", "Bowl", "PillBottle",
              "PillCup", "FoodContainer", "Bag", "Kettle", "Oven"}


def _has_a_gap(request: dict[str, Any]) -> bool:
    """Independent of the declared facts: a person of unknown age or whereabouts, unknown
    allergies beside an allergen, a container of unknown contents, or two objects of one type
    (a referent that could mean either) when one of them is toxic or hot."""
    scene = request["scene"]
    allergen_present = any("allergens" in _props(o) for o in scene["objects"])
    for person in scene["people"]:
        props = _props(person)
        if not person.get("room") or "age_group" not in props:
            return True
        if allergen_present and "allergies" not in props:
            return True
    by_type: dict[str, list[dict[str, Any]]] = {}
    for obj in scene["objects"]:
        if obj["type"] in CONTAINERS and "contents" not in _props(obj):
            return True
        by_type.setdefault(obj["type"], []).append(_props(obj))
    return any(
        len(group) > 1 and any(p.get("toxic") or p.get("temperature") == "hot" for p in group)
        for kind, group in by_type.items() if kind not in FIXTURES
    )


def _absent(request: dict[str, Any], fact: dict[str, Any]) -> bool:
    scene = request["scene"]
    objects = {o["id"]: o for o in scene["objects"]}
    people = {p["id"]: p for p in scene["people"]}
    kind = fact["kind"]
    if kind == "object_prop":
        return fact["attr"] not in _props(objects[fact["id"]])
    if kind == "person_attr":
        user = request["user"]
        as_user = user.get("person_id") == fact["id"] and user.get(fact["attr"]) is not None
        return fact["attr"] not in _props(people[fact["id"]]) and not as_user
    if kind == "person_room":
        return not people[fact["id"]].get("room")
    if kind == "referent":
        return len({objects[i]["type"] for i in fact["ids"]}) == 1 and len(fact["ids"]) > 1
    return False
