"""`safegate templates export|import` against real SQLite files."""

from __future__ import annotations

from pathlib import Path

import yaml

from app.domain.models import TemplateSource, TemplateStatus
from app.store import create_engine_for, migrate, seed_templates
from app.store.repository import Repository
from tests.commands.conftest import LIBRARY, Invoke

BAD_FORMULA = {
    "id": "thermal.kettle_near_child", "name": "Kettle near a child", "category": "physical",
    "hazard_class": "scald_hot_liquid", "description": "A kettle near a child.",
    "severity": "high", "preventability": "preventable",
    "variables": [{"name": "obj", "type": "object"}],
    "invariants": [{"id": "kettle_cold", "formula": "boiling_hot_thing($obj)",
                    "description": "Never hold a boiling kettle."}],
}


def _seeded(url: str) -> Repository:
    engine = create_engine_for(url)
    migrate(engine)
    repository = Repository(engine)
    seed_templates(repository, LIBRARY)
    return repository


def _fresh(url: str) -> Repository:
    engine = create_engine_for(url)
    migrate(engine)
    return Repository(engine)


def _snapshot(repository: Repository) -> list[tuple[str, int, str, str]]:
    return [(t.id, t.version, t.status.value, t.source.value)
            for t in repository.list_templates()]


class TestTemplatesExportImport:
    def test_round_trip_between_two_databases(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        source = _seeded(sqlite_url)
        exported = tmp_path / "library.yaml"
        result = invoke("templates", "export", "--out", str(exported))
        assert result.exit_code == 0, result.output
        entries = yaml.safe_load(exported.read_text())["templates"]
        assert [e["id"] for e in entries] == [t.id for t in source.list_templates()]
        assert {e["status"] for e in entries} == {"active", "draft"}
        assert not {"version", "source", "author", "created_at"} & entries[0].keys()

        other_url = f"sqlite:///{tmp_path / 'other.db'}"
        imported = invoke("templates", "import", str(exported), url=other_url)
        assert imported.exit_code == 0, imported.output
        assert "created" in imported.stdout
        target = _fresh(other_url)
        assert [(t.id, t.status) for t in target.list_templates()] == [
            (t.id, t.status) for t in source.list_templates()]
        assert {t.source for t in target.list_templates()} == {TemplateSource.USER}
        again = invoke("templates", "export", url=other_url)
        assert again.exit_code == 0
        assert again.stdout == exported.read_text()

    def test_importing_an_unchanged_file_changes_nothing(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        repository = _seeded(sqlite_url)
        before = _snapshot(repository)
        exported = tmp_path / "library.yaml"
        invoke("templates", "export", "-o", str(exported))
        result = invoke("templates", "import", str(exported))
        assert result.exit_code == 0, result.output
        assert _snapshot(repository) == before

    def test_a_changed_entry_becomes_a_new_version_with_its_status(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        repository = _seeded(sqlite_url)
        draft = next(t for t in repository.list_templates() if t.status is TemplateStatus.DRAFT)
        document = yaml.safe_load(invoke("templates", "export").stdout)
        for entry in document["templates"]:
            if entry["id"] == draft.id:
                entry["description"] = "Reworded by a curator."
                entry["status"] = "active"
        changed = tmp_path / "changed.yaml"
        changed.write_text(yaml.safe_dump(document))
        result = invoke("templates", "import", str(changed), "--author", "ann")
        assert result.exit_code == 0, result.output
        history = repository.get_template_history(draft.id)
        assert [v.version for v in history.versions] == [1, 2]
        assert history.current.description == "Reworded by a curator."
        assert history.current.status is TemplateStatus.ACTIVE
        assert history.versions[-1].author == "ann"

    def test_one_bad_entry_refuses_the_whole_file(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        repository = _seeded(sqlite_url)
        before = _snapshot(repository)
        document = yaml.safe_load(invoke("templates", "export").stdout)
        good = dict(BAD_FORMULA, id="thermal.kettle_ok", invariants=[
            {"id": "kettle_cold", "formula": "not (holding(robot, $obj) and hot($obj))",
             "description": "Do not hold the kettle while it is hot."}])
        document["templates"][0]["description"] = "A change that must not be stored."
        document["templates"] += [good, BAD_FORMULA]
        bad = tmp_path / "bad.yaml"
        bad.write_text(yaml.safe_dump(document))
        result = invoke("templates", "import", str(bad))
        assert result.exit_code == 1
        assert "thermal.kettle_near_child" in result.output
        assert "invariants.0.formula" in result.output
        assert "nothing was imported" in result.output
        assert _snapshot(repository) == before

    def test_a_file_that_is_not_a_library_is_refused(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        repository = _seeded(sqlite_url)
        before = _snapshot(repository)
        for name, text in (("broken.yaml", "templates: [unclosed"),
                           ("list.yaml", "- id: thermal.x\n"),
                           ("twice.yaml", yaml.safe_dump({"templates": [BAD_FORMULA] * 2}))):
            path = tmp_path / name
            path.write_text(text)
            result = invoke("templates", "import", str(path))
            assert result.exit_code == 1, (name, result.output)
        assert _snapshot(repository) == before

    def test_an_active_template_cannot_go_back_to_draft(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        repository = _seeded(sqlite_url)
        before = _snapshot(repository)
        document = yaml.safe_load(invoke("templates", "export").stdout)
        active = next(e for e in document["templates"] if e["status"] == "active")
        active["status"] = "draft"
        path = tmp_path / "draft.yaml"
        path.write_text(yaml.safe_dump(document))
        result = invoke("templates", "import", str(path))
        assert result.exit_code == 1
        assert "cannot become draft" in result.output
        assert _snapshot(repository) == before

    def test_dry_run_reports_without_storing(
        self, invoke: Invoke, sqlite_url: str, tmp_path: Path
    ) -> None:
        repository = _seeded(sqlite_url)
        before = _snapshot(repository)
        path = tmp_path / "new.yaml"
        path.write_text(yaml.safe_dump({"templates": [dict(BAD_FORMULA, invariants=[
            {"id": "kettle_cold", "formula": "not (holding(robot, $obj) and hot($obj))",
             "description": "Do not hold the kettle while it is hot."}])]}))
        result = invoke("templates", "import", str(path), "--dry-run")
        assert result.exit_code == 0, result.output
        assert "would import" in result.stdout and "thermal.kettle_near_child" in result.stdout
        assert _snapshot(repository) == before
        stored = invoke("templates", "import", str(path))
        assert stored.exit_code == 0
        assert repository.get_template("thermal.kettle_near_child").status is TemplateStatus.DRAFT

    def test_export_filters_by_status(self, invoke: Invoke, sqlite_url: str) -> None:
        repository = _seeded(sqlite_url)
        drafts = yaml.safe_load(invoke("templates", "export", "--status", "draft").stdout)
        assert [e["id"] for e in drafts["templates"]] == [
            t.id for t in repository.list_templates(status=TemplateStatus.DRAFT)]
