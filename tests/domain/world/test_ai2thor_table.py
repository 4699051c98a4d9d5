"""The one AI2-THOR object-type table: its shape, its reading by the world, and its build.

In: `app/domain/world/data/ai2thor_types.json` through `ai2thor_table.ai2thor_types()`, and the
build script run on the AI2-THOR reference data when this machine has it. Out: pytest verdicts.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest

from app.domain.world import type_info
from app.domain.world.ai2thor_table import AI2THOR_TYPES_FILE, ai2thor_types

FIELDS = {"flags", "mass_kg", "materials_all", "materials_some", "size_m", "receptacles",
          "receptacles_start", "receptacles_restored"}
REFERENCE_DATA = Path("/work/shared/data/ai2thor")


def _build_script() -> ModuleType:
    path = AI2THOR_TYPES_FILE.with_name("build_ai2thor_types.py")
    spec = importlib.util.spec_from_file_location("build_ai2thor_types", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class TestAi2thorTable:
    def test_every_type_has_every_field(self) -> None:
        types = ai2thor_types()
        assert len(types) == 125
        assert all(set(row) == FIELDS for row in types.values())

    def test_the_world_reads_its_flags_materials_and_documented_receptacles(self) -> None:
        mug = ai2thor_types()["Mug"]
        info = type_info("Mug")
        assert info.known and info.flag("pickupable") is True
        assert info.materials_all == frozenset(mug["materials_all"])
        assert info.receptacles == frozenset(mug["receptacles"])
        assert info.fits_in("CounterTop") is True

    def test_is_read_only(self) -> None:
        with pytest.raises(TypeError):
            ai2thor_types()["Mug"]["flags"] = {}  # type: ignore[index]

    @pytest.mark.skipif(not REFERENCE_DATA.is_dir(),
                        reason=f"the AI2-THOR reference data is not at {REFERENCE_DATA}")
    def test_is_what_the_build_script_derives_from_the_reference_data(self) -> None:
        built = _build_script().build(REFERENCE_DATA)["types"]
        assert built == {name: dict(row) for name, row in ai2thor_types().items()}
