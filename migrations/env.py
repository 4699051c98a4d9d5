"""Alembic environment for SafeGate.

Where the database comes from, first match wins: a connection handed in through
`config.attributes["connection"]` (what `app.store.db.migrate` and the tests do),
`alembic -x url=...`, the `sqlalchemy.url` main option, the `SAFEGATE_DATABASE_URL` environment
variable, and finally `sqlite:///./safegate.db`. SQLite is migrated in batch mode (it cannot ALTER
most things in place); on PostgreSQL a transaction-scoped advisory lock keeps two starting
replicas from migrating at once.
"""

from __future__ import annotations

import os
from logging.config import fileConfig

from alembic import context
from sqlalchemy import Connection, text

from app.store.db import DEFAULT_DATABASE_URL, create_engine_for
from app.store.tables import Base

MIGRATION_LOCK_KEY = 0x5AFE6A7E

config = context.config
if config.config_file_name is not None and not config.attributes.get("connection"):
    fileConfig(config.config_file_name, disable_existing_loggers=False)

target_metadata = Base.metadata


def _database_url() -> str:
    from_cli = context.get_x_argument(as_dictionary=True).get("url")
    if from_cli:
        return from_cli
    from_config = config.get_main_option("sqlalchemy.url")
    if from_config:
        return from_config
    return os.environ.get("SAFEGATE_DATABASE_URL", DEFAULT_DATABASE_URL)


def _configure(connection: Connection) -> None:
    context.configure(
        connection=connection,
        target_metadata=target_metadata,
        render_as_batch=connection.dialect.name == "sqlite",
        compare_type=True,
    )


def _upgrade_on(connection: Connection) -> None:
    _configure(connection)
    with context.begin_transaction():
        if connection.dialect.name == "postgresql":
            connection.execute(
                text("SELECT pg_advisory_xact_lock(:key)"), {"key": MIGRATION_LOCK_KEY}
            )
        context.run_migrations()


def run_migrations_offline() -> None:
    url = _database_url()
    context.configure(
        url=url,
        target_metadata=target_metadata,
        literal_binds=True,
        render_as_batch=url.startswith("sqlite"),
        dialect_opts={"paramstyle": "named"},
    )
    with context.begin_transaction():
        context.run_migrations()


def run_migrations_online() -> None:
    connection = config.attributes.get("connection")
    if connection is not None:
        _upgrade_on(connection)
        return
    engine = create_engine_for(_database_url())
    try:
        with engine.connect() as connection:
            _upgrade_on(connection)
            connection.commit()
    finally:
        engine.dispose()


if context.is_offline_mode():
    run_migrations_offline()
else:
    run_migrations_online()
