"""AI2-THOR object-type reference data (a package so that installs ship the JSON)."""
