"""Build `ai2thor_types.json`, the one AI2-THOR object-type table SafeGate and its simulator read.

In: the AI2-THOR reference data (`object_type_capabilities.json`, `object_types_data.json` and the
per-scene initial metadata in `scenes/`), by default from `/work/shared/data/ai2thor` or the
directory given as the first argument. Out: `ai2thor_types.json` beside this script: for each
object type its capability flags (true, false, or null when instances disagree), its mass range
in kg (null for fixed fixtures whose AI2-THOR mass is 0), the salient materials present in every
instance and in some instances, the median bounding-box dimensions in metres, largest first, and
three receptacle facts: `receptacles`, the receptacle types AI2-THOR's documentation lists as
compatible (where an object of the type may be put; a Microwave's list is what is made to go in
a microwave); `receptacles_start`, the receptacle types instances start in across the 120 iTHOR
scenes; and `receptacles_restored`, types the upstream parse of the documentation lost (a hand
correction, below). The world reads the documented list; the simulator accepts the union.
Fails: FileNotFoundError/KeyError when the reference data is missing or shaped differently.

Run: `python app/domain/world/data/build_ai2thor_types.py [/path/to/ai2thor]`.
"""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path
from typing import Any

FLAG_NAMES = {
    "pickupable": "pickupable",
    "moveable": "moveable",
    "receptacle": "receptacle",
    "openable": "openable",
    "toggleable": "toggleable",
    "breakable": "breakable",
    "canFillWithLiquid": "can_fill",
    "dirtyable": "dirtyable",
    "sliceable": "sliceable",
    "cookable": "cookable",
    "isHeatSource": "heat_source",
    "isColdSource": "cold_source",
}

# The docs parse lost part of the Mug row; AI2-THOR heats, chills and brews in a mug.
RESTORED_RECEPTACLES = {"Mug": ["CoffeeMachine", "Fridge", "Microwave", "Sink"]}


def _flag(value: object) -> bool | None:
    """True/False when every instance agrees; None when the flag varies ("k/n")."""
    return value if isinstance(value, bool) else None


def _median_sizes(scene_dir: Path) -> dict[str, list[float]]:
    sizes: dict[str, list[list[float]]] = {}
    for scene_file in sorted(scene_dir.glob("FloorPlan*.json")):
        for obj in json.loads(scene_file.read_text())["objects"]:
            box = obj.get("aabbSize")
            if box:
                dims = sorted((box["x"], box["y"], box["z"]), reverse=True)
                sizes.setdefault(obj["objectType"], []).append(dims)
    return {
        kind: [round(statistics.median(d[i] for d in dims), 3) for i in range(3)]
        for kind, dims in sizes.items()
    }


def build(source: Path) -> dict[str, Any]:
    """Derive the table from the reference data in `source`."""
    capabilities = json.loads((source / "object_type_capabilities.json").read_text())
    documented = json.loads((source / "object_types_data.json").read_text())
    sizes = _median_sizes(source / "scenes")
    types: dict[str, Any] = {}
    for kind, info in sorted(capabilities.items()):
        flags = info.get("metadata_flags") or {}
        instances = info.get("metadata_instances") or 0
        materials = info.get("salientMaterials") or {}
        mass = info.get("mass_range")
        types[kind] = {
            "flags": {ours: _flag(flags.get(theirs)) for theirs, ours in FLAG_NAMES.items()}
            if flags
            else {},
            "mass_kg": mass if mass and mass[1] > 0 else None,
            "materials_all": sorted(m for m, n in materials.items() if n == instances),
            "materials_some": sorted(m for m, n in materials.items() if 0 < n < instances),
            "size_m": sizes.get(kind),
            "receptacles": sorted({r for r in documented.get(kind, {}).get(
                "compatible_receptacles", []) if r}),
            "receptacles_start": sorted(
                r for r in info.get("initial_parentReceptacle_types") or {} if r),
            "receptacles_restored": RESTORED_RECEPTACLES.get(kind, []),
        }
    return {
        "source": "derived from Kajiih/rl_ai2thor AI2-THOR reference data (MIT); see README.md",
        "types": types,
    }


def main() -> None:
    source = Path(sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data/ai2thor")
    out = Path(__file__).with_name("ai2thor_types.json")
    table = build(source)
    lines = [
        f"  {json.dumps(kind)}: {json.dumps(row, sort_keys=True)}"
        for kind, row in table["types"].items()
    ]
    out.write_text(
        '{"source": ' + json.dumps(table["source"]) + ',\n "types": {\n'
        + ",\n".join(lines) + "\n }\n}\n"
    )
    print(f"wrote {len(table['types'])} types to {out}")


if __name__ == "__main__":
    main()
