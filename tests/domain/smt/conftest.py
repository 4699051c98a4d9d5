"""Makes the formula tests' Hypothesis strategies (`formula_strategies.py`) importable here."""

from __future__ import annotations

import sys
from pathlib import Path

_STRATEGIES = str(Path(__file__).resolve().parent.parent / "formula")
if _STRATEGIES not in sys.path:
    sys.path.insert(0, _STRATEGIES)
