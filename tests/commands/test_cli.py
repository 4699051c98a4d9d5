"""`safegate --version`, `safegate migrate`, the Rich key table (on real SQLite files) and the
note that `safegate bench` moved to `python -m bench`."""

from __future__ import annotations

from importlib.metadata import version

from sqlalchemy import create_engine, inspect, text

from app.store.records import ApiKeyRole
from tests.commands.conftest import Invoke


class TestVersion:
    def test_prints_the_installed_version(self, invoke: Invoke) -> None:
        result = invoke("--version")
        assert result.exit_code == 0
        assert result.stdout.strip() == f"safegate {version('safegate')}"


class TestMigrate:
    def test_upgrades_an_empty_file_to_head(self, invoke: Invoke, sqlite_url: str) -> None:
        result = invoke("migrate")
        assert result.exit_code == 0, result.output
        engine = create_engine(sqlite_url)
        tables = set(inspect(engine).get_table_names())
        assert {"alembic_version", "hazard_templates", "api_keys"} <= tables
        with engine.connect() as connection:
            revision = connection.execute(text("SELECT version_num FROM alembic_version"))
            assert revision.scalar_one()
        assert invoke("migrate").exit_code == 0  # idempotent

    def test_an_unreachable_database_fails_without_showing_the_password(
        self, invoke: Invoke
    ) -> None:
        result = invoke("migrate", url="postgresql+psycopg://ann:hunter2@127.0.0.1:9/nowhere")
        assert result.exit_code == 1
        assert "hunter2" not in result.output
        assert "***" in result.output


class TestKeysList:
    def test_a_table_with_every_key_and_no_secret(self, invoke: Invoke) -> None:
        created = [invoke("keys", "create", "--role", role.value, "--name", f"{role.value} [x]")
                   for role in (ApiKeyRole.ROBOT, ApiKeyRole.CURATOR)]
        secrets = [c.stdout.strip() for c in created]
        listed = invoke("keys", "list")
        assert listed.exit_code == 0
        assert "\t" not in listed.stdout
        header = next(line for line in listed.stdout.splitlines() if "role" in line)
        assert all(word in header for word in ("id", "role", "state", "created", "name"))
        assert "robot [x]" in listed.stdout and "curator [x]" in listed.stdout
        assert not any(secret in listed.stdout for secret in secrets)


class TestBenchMoved:
    def test_points_to_python_m_bench_and_fails(self, invoke: Invoke) -> None:
        result = invoke("bench", "run", "bench/cases/benchmark.jsonl", "--method", "safegate")
        assert result.exit_code == 2
        assert "python -m bench run" in result.stderr

    def test_is_not_listed_in_the_help(self, invoke: Invoke) -> None:
        assert "bench" not in invoke("--help").stdout
