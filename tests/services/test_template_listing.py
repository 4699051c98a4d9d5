"""Listing templates for the curator's table: whole-word search, stable sorting, paging."""

from __future__ import annotations

from typing import Any

from app.domain.models import HazardTemplate
from app.services.template_listing import SortOrder, TemplateSortKey, page, search


def template(template_id: str, name: str, hazard_class: str, **fields: Any) -> HazardTemplate:
    return HazardTemplate.model_validate({
        "id": template_id, "name": name, "category": "physical", "hazard_class": hazard_class,
        "description": fields.pop("description", "A hazard."), "severity": "high",
        "preventability": "preventable", **fields})


LIBRARY = [
    template("privacy.photographed", "Photographing a guest", "privacy_recording",
             description="Photographing someone who did not agree."),
    template("thermal.hot_liquid_near_person", "Hot liquid carried near people",
             "scald_hot_liquid", severity="critical"),
    template("thermal.iron_left_on", "Iron left on", "thermal_burn", severity="moderate",
             version=3),
    template("fire.shot_glass_flambe", "Shot glass set alight", "fire_ignition", severity="low"),
]


def ids(templates: list[HazardTemplate]) -> list[str]:
    return [t.id for t in templates]


class TestSearch:
    def test_a_word_never_matches_inside_another_word(self) -> None:
        assert ids(search(LIBRARY, "hot")) == ["thermal.hot_liquid_near_person"]

    def test_ids_and_classes_split_into_words(self) -> None:
        assert ids(search(LIBRARY, "scald")) == ["thermal.hot_liquid_near_person"]
        assert ids(search(LIBRARY, "burn")) == ["thermal.iron_left_on"]

    def test_case_and_punctuation_do_not_matter(self) -> None:
        assert ids(search(LIBRARY, "HOT, Liquid!")) == ["thermal.hot_liquid_near_person"]

    def test_every_word_is_needed(self) -> None:
        assert search(LIBRARY, "hot iron") == []

    def test_no_words_keep_everything(self) -> None:
        assert search(LIBRARY, "  ") == LIBRARY and search(LIBRARY, None) == LIBRARY


class TestPage:
    def test_severity_sorts_by_how_bad(self) -> None:
        found = page(LIBRARY, sort=TemplateSortKey.SEVERITY, order=SortOrder.DESC)
        assert [t.severity.value for t in found.templates] == ["critical", "high", "moderate",
                                                              "low"]

    def test_ties_keep_id_order_when_descending(self) -> None:
        found = page(LIBRARY, sort=TemplateSortKey.CATEGORY, order=SortOrder.DESC)
        assert ids(found.templates) == sorted(ids(LIBRARY))

    def test_a_page_is_a_slice_with_the_total(self) -> None:
        found = page(LIBRARY, sort=TemplateSortKey.VERSION, order=SortOrder.DESC, offset=0,
                     limit=1)
        assert ids(found.templates) == ["thermal.iron_left_on"] and found.total == 4
        assert page(LIBRARY, offset=10, limit=5).templates == []
