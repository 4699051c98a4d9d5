"""Template queries on SQLite and PostgreSQL: seeding, curation, versions, listing."""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC

import pytest

from app.domain.errors import Conflict, NotFound, TemplateInvalid
from app.domain.models import Category, HazardTemplate, TemplateSource, TemplateStatus
from app.store.repository import Repository, template_content_hash

TemplateFactory = Callable[..., HazardTemplate]


class TestUpsertSeedTemplates:
    def test_new_templates_are_added_at_version_one(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        report = repository.upsert_seed_templates(
            [make_template(id="a.one"), make_template(id="a.two")]
        )
        assert report.added == ("a.one", "a.two")
        stored = repository.get_template("a.one")
        assert (stored.version, stored.source, stored.status) == (
            1,
            TemplateSource.SEED,
            TemplateStatus.ACTIVE,
        )

    def test_reloading_the_same_library_changes_nothing(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        library = [make_template(id="a.one")]
        repository.upsert_seed_templates(library)
        report = repository.upsert_seed_templates(library)
        assert (report.added, report.new_versions, report.unchanged) == ((), (), ("a.one",))
        assert len(repository.get_template_history("a.one").versions) == 1

    def test_changed_seed_content_becomes_a_new_version(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.upsert_seed_templates([make_template(id="a.one")])
        report = repository.upsert_seed_templates(
            [make_template(id="a.one", description="Now with more detail.")]
        )
        assert report.new_versions == ("a.one",)
        current = repository.get_template("a.one")
        assert (current.version, current.description) == (2, "Now with more detail.")
        assert repository.get_template("a.one", version=1).description != current.description

    def test_a_curator_status_survives_a_reload_with_new_content(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.upsert_seed_templates([make_template(id="a.one")])
        repository.set_template_status("a.one", TemplateStatus.DEPRECATED)
        repository.upsert_seed_templates([make_template(id="a.one", severity="critical")])
        assert repository.get_template("a.one").status is TemplateStatus.DEPRECATED

    def test_user_templates_are_never_overwritten(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(id="a.one", name="Mine"), author="ann")
        report = repository.upsert_seed_templates([make_template(id="a.one", name="Seed's")])
        assert report.skipped_user == ("a.one",)
        stored = repository.get_template("a.one")
        assert (stored.name, stored.version, stored.source) == ("Mine", 1, TemplateSource.USER)

    def test_duplicate_ids_in_one_load_are_refused(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        with pytest.raises(TemplateInvalid):
            repository.upsert_seed_templates([make_template(id="a.one"), make_template(id="a.one")])
        assert repository.list_templates() == []


class TestCreateUserTemplate:
    def test_a_new_template_is_a_user_draft(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        created = repository.create_user_template(
            make_template(status="active", source="seed"), author="ann"
        )
        assert (created.status, created.source, created.author, created.version) == (
            TemplateStatus.DRAFT,
            TemplateSource.USER,
            "ann",
            1,
        )
        assert created.created_at is not None and created.created_at.tzinfo is not None

    def test_an_existing_id_is_a_conflict(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(), author="ann")
        with pytest.raises(Conflict):
            repository.create_user_template(make_template(), author="bob")


class TestAddTemplateVersion:
    def test_a_revision_increments_the_version_and_keeps_history(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(), author="ann")
        revised = repository.add_template_version(
            "test.hot_mug", make_template(severity="critical"), author="bob"
        )
        history = repository.get_template_history("test.hot_mug")
        assert revised.version == 2
        assert [(v.version, v.author) for v in history.versions] == [(1, "ann"), (2, "bob")]
        assert history.versions[0].template.severity.value == "high"
        assert history.current.severity.value == "critical"

    def test_revising_a_seed_template_makes_it_a_user_template(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.upsert_seed_templates([make_template()])
        repository.add_template_version("test.hot_mug", make_template(name="Edited"), author="c")
        repository.upsert_seed_templates([make_template(name="Seed again")])
        stored = repository.get_template("test.hot_mug")
        assert (stored.name, stored.source) == ("Edited", TemplateSource.USER)

    def test_a_document_for_another_id_is_refused(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(), author="ann")
        with pytest.raises(TemplateInvalid):
            repository.add_template_version("test.hot_mug", make_template(id="x.y"), author="a")

    def test_an_unknown_template_is_not_found(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        with pytest.raises(NotFound):
            repository.add_template_version("test.hot_mug", make_template(), author="ann")


class TestSetTemplateStatus:
    def test_activating_a_draft_makes_it_active(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(), author="ann")
        activated = repository.set_template_status("test.hot_mug", TemplateStatus.ACTIVE)
        assert activated.status is TemplateStatus.ACTIVE
        history = repository.get_template_history("test.hot_mug")
        assert history.versions[-1].status is TemplateStatus.ACTIVE

    def test_an_active_template_cannot_go_back_to_draft(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.upsert_seed_templates([make_template()])
        with pytest.raises(Conflict):
            repository.set_template_status("test.hot_mug", TemplateStatus.DRAFT)

    def test_an_unknown_template_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.set_template_status("nope", TemplateStatus.ACTIVE)


class TestGetTemplate:
    def test_the_stored_template_round_trips(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        original = make_template()
        repository.upsert_seed_templates([original])
        stored = repository.get_template(original.id)
        assert template_content_hash(stored) == template_content_hash(original)
        assert stored.created_at is not None and stored.created_at.tzinfo == UTC

    def test_an_unknown_version_is_not_found(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.upsert_seed_templates([make_template()])
        with pytest.raises(NotFound):
            repository.get_template("test.hot_mug", version=2)

    def test_an_unknown_template_is_not_found(self, repository: Repository) -> None:
        with pytest.raises(NotFound):
            repository.get_template_history("nope")


class TestListTemplates:
    @pytest.fixture
    def stocked(self, repository: Repository, make_template: TemplateFactory) -> Repository:
        repository.upsert_seed_templates(
            [
                make_template(id="b.scald", hazard_class="scald_hot_liquid"),
                make_template(id="a.burn", hazard_class="thermal_burn"),
                make_template(id="c.scare", hazard_class="startling", category="psychological"),
                make_template(id="d.draft", hazard_class="thermal_burn", status="draft"),
            ]
        )
        return repository

    def test_everything_is_listed_in_id_order(self, stocked: Repository) -> None:
        ids = [t.id for t in stocked.list_templates()]
        assert ids == ["a.burn", "b.scald", "c.scare", "d.draft"]

    def test_filters_combine(self, stocked: Repository) -> None:
        found = stocked.list_templates(
            category=Category.PHYSICAL, hazard_class="thermal_burn", status=TemplateStatus.ACTIVE
        )
        assert [t.id for t in found] == ["a.burn"]

    def test_active_templates_leave_out_drafts_and_deprecated_ones(
        self, stocked: Repository
    ) -> None:
        stocked.set_template_status("b.scald", TemplateStatus.DEPRECATED)
        assert [t.id for t in stocked.list_active_templates()] == ["a.burn", "c.scare"]

    def test_listing_shows_the_current_version(
        self, stocked: Repository, make_template: TemplateFactory
    ) -> None:
        stocked.add_template_version(
            "a.burn", make_template(id="a.burn", name="v2", hazard_class="thermal_burn"), author="x"
        )
        (burn,) = stocked.list_templates(hazard_class="thermal_burn", status=TemplateStatus.ACTIVE)
        assert (burn.name, burn.version) == ("v2", 2)
