"""Persistence: SQLAlchemy tables, the repository, migrations and the seed library loader.

Start-up wiring: `engine = create_engine_for(url)`, `migrate(engine)`,
`repository = Repository(engine)`, `seed_templates(repository, Path("templates_db"))`.
"""

from app.store.db import DEFAULT_DATABASE_URL, create_engine_for, migrate
from app.store.repository import Repositories, Repository, hash_api_key
from app.store.seed import load_library, seed_templates

__all__ = [
    "DEFAULT_DATABASE_URL",
    "Repositories",
    "Repository",
    "create_engine_for",
    "hash_api_key",
    "load_library",
    "migrate",
    "seed_templates",
]
