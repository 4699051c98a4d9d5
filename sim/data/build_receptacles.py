"""Build `compatible_receptacles.json` from the shared AI2-THOR capability table.

In: `object_type_capabilities.json` (see README.md: derived from the AI2-THOR docs' object-type
table and the 120 iTHOR initial metadata dumps). Out: for each pickupable type, the receptacle
types AI2-THOR accepts it in: the docs' "Default Compatible Receptacles" plus every type an
instance starts in, plus the few corrections listed below. Run by hand:
`python sim/data/build_receptacles.py ../shared/data/ai2thor/object_type_capabilities.json`.
Fails: `KeyError`/`FileNotFoundError` on a missing or differently shaped input.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

# The docs parse lost part of the Mug row; AI2-THOR heats, chills and brews in a mug.
_CORRECTIONS = {"Mug": ["Microwave", "Fridge", "CoffeeMachine", "Sink"]}


def main(source: Path) -> None:
    table = json.loads(source.read_text(encoding="utf-8"))
    types = table.get("types", table)
    out: dict[str, list[str]] = {}
    for name, row in sorted(types.items()):
        if not row.get("metadata_flags", {}).get("pickupable"):
            continue
        allowed = set(row["docs"].get("compatible_receptacles") or ())
        allowed |= set(row.get("initial_parentReceptacle_types") or ())
        allowed |= set(_CORRECTIONS.get(name, ()))
        allowed -= {"Floor", ""}
        out[name] = sorted(allowed)
    target = Path(__file__).with_name("compatible_receptacles.json")
    target.write_text(json.dumps({"source": "derived from shared/data/ai2thor/"
                                  "object_type_capabilities.json by build_receptacles.py",
                                  "types": out}, indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
