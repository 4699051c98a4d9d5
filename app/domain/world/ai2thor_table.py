"""The one AI2-THOR object-type table: `data/ai2thor_types.json`, read the same way everywhere.

In: nothing (the table ships with the package; `data/build_ai2thor_types.py` derives it from the
AI2-THOR reference data, `data/README.md` gives its provenance and licence). Out:
`ai2thor_types()`, each AI2-THOR type name mapped to its row: `flags` (capabilities: True, False,
or None where instances disagree), `mass_kg`, `materials_all`, `materials_some`, `size_m`, and
the receptacle facts `receptacles` (the documentation's list), `receptacles_start` (where
instances start in the iTHOR scenes) and `receptacles_restored` (lost by the docs parse). The
world's `object_types` builds its `TypeInfo`s from it, Stage 1 reads objects through those, and
the simulator (`sim/physics.py`) takes the receptacles AI2-THOR accepts from it.
Fails: `OSError` or `ValueError` when the packaged file is missing or is not the table (a broken
install); read once per process.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from functools import cache
from pathlib import Path
from types import MappingProxyType
from typing import Any

AI2THOR_TYPES_FILE = Path(__file__).with_name("data") / "ai2thor_types.json"


@cache
def ai2thor_types() -> Mapping[str, Mapping[str, Any]]:
    """Every AI2-THOR object type's row of the table, by type name (read-only; do not mutate)."""
    rows: dict[str, dict[str, Any]] = json.loads(
        AI2THOR_TYPES_FILE.read_text(encoding="utf-8"))["types"]
    return MappingProxyType({name: MappingProxyType(row) for name, row in rows.items()})
