"""`Repository.apply_template_changes`: a batch of template writes, all or nothing."""

from __future__ import annotations

import pytest

from app.domain.errors import Conflict
from app.domain.models import TemplateSource, TemplateStatus
from app.store.records import TemplateChange
from app.store.repository import Repository
from tests.store.conftest import TemplateFactory


class TestApplyTemplateChanges:
    def test_creates_revises_and_restatuses_in_one_go(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(id="test.old"), "ann")
        repository.create_user_template(make_template(id="test.quiet"), "ann")
        repository.apply_template_changes([
            TemplateChange(template=make_template(id="test.new"),
                           status=TemplateStatus.ACTIVE, new_version=True, base_version=None),
            TemplateChange(template=make_template(id="test.old", description="Reworded."),
                           status=TemplateStatus.DRAFT, new_version=True, base_version=1),
            TemplateChange(template=make_template(id="test.quiet"),
                           status=TemplateStatus.DEPRECATED, new_version=False, base_version=1),
        ], "bob")
        new = repository.get_template("test.new")
        assert (new.version, new.status, new.source) == (
            1, TemplateStatus.ACTIVE, TemplateSource.USER)
        old = repository.get_template_history("test.old")
        assert [v.version for v in old.versions] == [1, 2]
        assert old.current.description == "Reworded." and old.versions[-1].author == "bob"
        quiet = repository.get_template_history("test.quiet")
        assert [v.version for v in quiet.versions] == [1]
        assert quiet.current.status is TemplateStatus.DEPRECATED
        assert quiet.versions[0].status is TemplateStatus.DEPRECATED

    def test_a_template_written_since_the_plan_stores_nothing(
        self, repository: Repository, make_template: TemplateFactory
    ) -> None:
        repository.create_user_template(make_template(id="test.old"), "ann")
        repository.create_user_template(make_template(id="test.raced"), "eve")  # after planning
        before = [(t.id, t.version, t.status) for t in repository.list_templates()]
        with pytest.raises(Conflict, match=r"test\.raced"):
            repository.apply_template_changes([
                TemplateChange(template=make_template(id="test.old", description="Changed."),
                               status=TemplateStatus.ACTIVE, new_version=True, base_version=1),
                TemplateChange(template=make_template(id="test.raced"),
                               status=TemplateStatus.DRAFT, new_version=True, base_version=None),
            ], "bob")
        assert [(t.id, t.version, t.status) for t in repository.list_templates()] == before
