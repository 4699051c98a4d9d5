"""A word's own typical mass beats its concept's and the concept's AI2-THOR type's: a radio is
no television, a milk carton or a cat-food pouch no 3 kg box, a hair dryer no fan heater; a
word without its own mass keeps the type's measured one."""

from __future__ import annotations

import pytest

from app.domain.world.object_types import type_info


@pytest.mark.parametrize(("name", "at_most"), [
    ("Radio", 2.0), ("MilkCarton", 1.5), ("cat food pouch", 0.2), ("strawberries punnet", 0.5),
    ("HairDryer", 1.0), ("Drill", 2.0), ("BathMat", 1.0), ("ToyBricks", 1.5)])
def test_small_things_weigh_what_such_things_weigh(name: str, at_most: float) -> None:
    mass = type_info(name).mass_kg
    assert mass is not None and mass[1] <= at_most, (name, mass)


@pytest.mark.parametrize(("name", "at_least"), [
    ("Television", 5.0), ("Dumbbell", 4.0), ("Sofa", 20.0), ("Wheelchair", 10.0)])
def test_heavy_things_stay_heavy(name: str, at_least: float) -> None:
    mass = type_info(name).mass_kg
    assert mass is not None and mass[0] >= at_least, (name, mass)
