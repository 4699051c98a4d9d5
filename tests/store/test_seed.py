"""Loading the YAML template library and seeding it, idempotently, on SQLite and PostgreSQL."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from app.domain.errors import TemplateInvalid
from app.domain.models import TemplateSource, TemplateStatus
from app.store.repository import Repository
from app.store.seed import load_library, seed_templates

REAL_LIBRARY = Path(__file__).resolve().parents[2] / "templates_db"

VALID_ENTRY = """
  - id: extra.one
    name: Extra
    category: physical
    hazard_class: thermal_burn
    description: An extra template.
    severity: low
    preventability: preventable
"""


def _library(tmp_path: Path, **files: str) -> Path:
    for name, text in files.items():
        (tmp_path / f"{name}.yaml").write_text(text, encoding="utf-8")
    return tmp_path


class TestLoadLibrary:
    def test_every_file_is_read_in_name_order(self, library_dir: Path) -> None:
        templates = load_library(library_dir)
        assert [t.id for t in templates] == [
            "sharp.knife_handover_child",
            "thermal.hot_liquid_near_person",
            "thermal.hot_surface_contact",
        ]
        assert all(t.source is TemplateSource.SEED for t in templates)
        assert templates[0].status is TemplateStatus.DRAFT

    def test_a_bad_field_names_the_file_the_entry_and_the_field(self, tmp_path: Path) -> None:
        bad = VALID_ENTRY.replace("severity: low", "severity: dreadful")
        with pytest.raises(TemplateInvalid) as caught:
            load_library(_library(tmp_path, broken=f"templates:{bad}"))
        assert "broken.yaml" in caught.value.detail
        assert "extra.one" in caught.value.detail
        assert caught.value.field == "templates[0].severity"

    def test_a_guard_without_an_action_is_refused(self, tmp_path: Path) -> None:
        entry = VALID_ENTRY + (
            "    guards:\n      - {id: g, formula: 'true', description: no action given}\n"
        )
        with pytest.raises(TemplateInvalid) as caught:
            load_library(_library(tmp_path, guards=f"templates:{entry}"))
        assert caught.value.field == "templates[0].guards"

    def test_invalid_yaml_names_the_file(self, tmp_path: Path) -> None:
        with pytest.raises(TemplateInvalid, match=r"syntax\.yaml"):
            load_library(_library(tmp_path, syntax="templates: [unclosed"))

    def test_a_file_without_a_templates_list_is_refused(self, tmp_path: Path) -> None:
        with pytest.raises(TemplateInvalid, match=r"nolist\.yaml") as caught:
            load_library(_library(tmp_path, nolist="- id: a.b\n"))
        assert caught.value.field == "templates"

    def test_an_id_defined_in_two_files_is_refused(self, tmp_path: Path) -> None:
        library = _library(tmp_path, a=f"templates:{VALID_ENTRY}", b=f"templates:{VALID_ENTRY}")
        with pytest.raises(TemplateInvalid, match=r"already defined in a\.yaml"):
            load_library(library)

    def test_a_missing_directory_is_refused(self, tmp_path: Path) -> None:
        with pytest.raises(TemplateInvalid):
            load_library(tmp_path / "nowhere")


class TestSeedTemplates:
    def test_a_first_load_adds_everything(self, repository: Repository, library_dir: Path) -> None:
        report = seed_templates(repository, library_dir)
        assert len(report.added) == 3
        assert [t.id for t in repository.list_active_templates()] == [
            "thermal.hot_liquid_near_person",
            "thermal.hot_surface_contact",
        ]

    def test_a_second_load_is_a_no_op(self, repository: Repository, library_dir: Path) -> None:
        seed_templates(repository, library_dir)
        report = seed_templates(repository, library_dir)
        assert (report.added, report.new_versions, len(report.unchanged)) == ((), (), 3)

    def test_an_edited_file_adds_a_version_and_a_new_file_adds_templates(
        self, repository: Repository, library_dir: Path, tmp_path: Path
    ) -> None:
        seed_templates(repository, library_dir)
        edited = shutil.copytree(library_dir, tmp_path / "library")
        thermal = edited / "thermal.yaml"
        thermal.write_text(
            thermal.read_text().replace("Touching or placing", "Touching, leaning or placing")
        )
        (edited / "extra.yaml").write_text(f"templates:{VALID_ENTRY}")
        report = seed_templates(repository, edited)
        assert report.added == ("extra.one",)
        assert report.new_versions == ("thermal.hot_surface_contact",)
        assert repository.get_template("thermal.hot_surface_contact").version == 2

    def test_a_curated_template_survives_reseeding(
        self, repository: Repository, library_dir: Path
    ) -> None:
        seed_templates(repository, library_dir)
        seeded = repository.get_template("thermal.hot_surface_contact")
        repository.add_template_version(
            seeded.id, seeded.model_copy(update={"name": "Curated name"}), author="curator"
        )
        report = seed_templates(repository, library_dir)
        assert report.skipped_user == ("thermal.hot_surface_contact",)
        assert repository.get_template(seeded.id).name == "Curated name"

    def test_a_bad_library_writes_nothing(self, repository: Repository, tmp_path: Path) -> None:
        library = _library(
            tmp_path,
            a=f"templates:{VALID_ENTRY}",
            b="templates:\n  - {id: bad}\n",
        )
        with pytest.raises(TemplateInvalid):
            seed_templates(repository, library)
        assert repository.list_templates() == []


class TestRealLibrary:
    def test_the_shipped_library_seeds_twice_without_changes(self, repository: Repository) -> None:
        first = seed_templates(repository, REAL_LIBRARY)
        second = seed_templates(repository, REAL_LIBRARY)
        assert len(first.added) > 0
        assert second.unchanged == first.added
        assert len(repository.list_templates()) == len(first.added)
