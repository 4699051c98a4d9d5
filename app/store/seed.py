"""Load the Hazard Template Library from `templates_db/*.yaml` and seed it into the database.

In: a directory of YAML files, each a mapping with a `templates:` list (schema in
`templates_db/README.md`). Out: `HazardTemplate` values (`load_library`), and a `SeedReport` of
what a load changed (`seed_templates`, idempotent: see `Repository.upsert_seed_templates`).
Fails: `TemplateInvalid` naming the file, the entry and the field for anything malformed (YAML
syntax, a missing `templates:` list, a field that fails validation, an id used twice), so a bad
library stops start-up instead of silently leaving a hazard unguarded; `Unavailable` from the
database while seeding.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from app.domain.errors import TemplateInvalid
from app.domain.models import HazardTemplate, TemplateSource
from app.store.records import SeedReport
from app.store.repository.templates import TemplateQueries


def _field_path(location: tuple[int | str, ...]) -> str:
    parts: list[str] = []
    for part in location:
        if isinstance(part, int):
            parts.append(f"[{part}]")
        else:
            parts.append(f".{part}" if parts else part)
    return "".join(parts)


def _read_entries(path: Path) -> list[Any]:
    try:
        document = yaml.safe_load(path.read_text(encoding="utf-8"))
    except yaml.YAMLError as error:
        raise TemplateInvalid(f"{path.name}: not valid YAML: {error}", file=path.name) from error
    except OSError as error:
        raise TemplateInvalid(f"{path.name}: cannot be read: {error}", file=path.name) from error
    if not isinstance(document, dict) or not isinstance(document.get("templates"), list):
        raise TemplateInvalid(
            f"{path.name}: expected a mapping with a 'templates:' list",
            field="templates",
            file=path.name,
        )
    entries: list[Any] = document["templates"]
    return entries


def _parse_entry(path: Path, index: int, entry: Any) -> HazardTemplate:
    label = entry.get("id") if isinstance(entry, dict) else None
    where = f"{path.name}: templates[{index}]" + (f" ({label})" if label else "")
    if not isinstance(entry, dict):
        raise TemplateInvalid(f"{where}: expected a mapping", field=f"templates[{index}]")
    try:
        template = HazardTemplate.model_validate(entry)
    except ValidationError as error:
        first = error.errors()[0]
        field = _field_path(tuple(first["loc"]))
        raise TemplateInvalid(
            f"{where}: field {field!r}: {first['msg']}",
            field=f"templates[{index}].{field}" if field else f"templates[{index}]",
            file=path.name,
            template_id=label,
            errors=len(error.errors()),
        ) from error
    return template.model_copy(update={"source": TemplateSource.SEED})


def load_library(directory: Path) -> list[HazardTemplate]:
    """Read every `*.yaml` file of a template library directory, in file-name order.

    Args:
        directory: the library, e.g. `Path("templates_db")`.

    Returns:
        The templates, as seed templates, in file then entry order.

    Raises:
        TemplateInvalid: the directory is missing, or an entry is malformed or duplicated; the
            detail names the file, the entry and the field.
    """
    if not directory.is_dir():
        raise TemplateInvalid(f"no template library directory at {directory}")
    templates: list[HazardTemplate] = []
    first_seen: dict[str, str] = {}
    for path in sorted(directory.glob("*.yaml")):
        for index, entry in enumerate(_read_entries(path)):
            template = _parse_entry(path, index, entry)
            if template.id in first_seen:
                raise TemplateInvalid(
                    f"{path.name}: templates[{index}]: id {template.id!r} already defined in "
                    f"{first_seen[template.id]}",
                    field=f"templates[{index}].id",
                    file=path.name,
                )
            first_seen[template.id] = path.name
            templates.append(template)
    return templates


def seed_templates(repository: TemplateQueries, directory: Path) -> SeedReport:
    """Load the library from `directory` and upsert it into the database.

    Args:
        repository: where to store the templates.
        directory: the YAML library.

    Returns:
        What the load added, revised, left unchanged and skipped (user templates).

    Raises:
        TemplateInvalid: the library is malformed (nothing is written then).
        Unavailable: database error.
    """
    return repository.upsert_seed_templates(load_library(directory))
