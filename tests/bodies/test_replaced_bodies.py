"""``dataclasses.replace`` of a body computes again what the body computed (a rod's m L^2/12, a
mass from the diameter, a sphere's mass or density, a flexible rod's mode counts), saying so
where the value changes, and keeps what was given: the body equals the one built fresh with the
same inputs."""

from __future__ import annotations

import dataclasses
import math
import pickle

import pytest

import impactlab as il
from impactlab import FlexibleRod, Rod, Sphere


def test_a_longer_rod_takes_its_own_inertia() -> None:
    """The paper's rod made twice as long kept the short rod's inertia: delta_max 40 % low."""
    with pytest.warns(UserWarning, match=r"inertia: 0\.0035667 was computed by another body"):
        long = dataclasses.replace(Rod.paper(), length=0.6096)
    fresh = Rod(length=0.6096, tip_radius=0.0088, mass=0.4607)
    assert long == fresh and long.inertia == pytest.approx(0.4607 * 0.6096**2 / 12, rel=1e-15)
    kw = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}
    assert il.simulate(long, **kw).delta_max == il.simulate(fresh, **kw).delta_max
    with pytest.warns(UserWarning, match="so this body computes its own"):
        heavier = dataclasses.replace(Rod.paper(), mass=4.607)
    assert heavier.inertia == pytest.approx(4.607 * 0.3048**2 / 12, rel=1e-15)


def test_a_given_inertia_and_mass_are_kept() -> None:
    rod = dataclasses.replace(Rod.paper(inertia=0.005), length=0.4)
    assert rod.inertia == 0.005 and rod.mass == 0.4607


def test_a_sphere_is_replaced_in_any_field() -> None:
    """Every replace raised "give either mass or density for a Sphere, not both"."""
    s = Sphere(radius="5 mm")
    with pytest.warns(UserWarning, match="mass: 0.00408407 was computed by another body"):
        assert dataclasses.replace(s, radius="3 mm") == Sphere(radius="3 mm")
    al = il.get_material("al-6061-t6")
    assert dataclasses.replace(s, material=al).density == al.density
    with pytest.warns(UserWarning, match="density: "):
        assert dataclasses.replace(Sphere(radius=0.005, mass=0.01), radius=0.006).mass == 0.01
    with pytest.warns(UserWarning, match="mass: "):
        dense = dataclasses.replace(Sphere(radius=0.005, density=2000.0), radius=0.006)
    assert dense.density == 2000.0 and dense == Sphere(radius=0.006, density=2000.0)


def test_a_flexible_rod_from_its_diameter_is_replaced() -> None:
    """The mass from the old length was checked as a given one, and refused."""
    rod = FlexibleRod(length=0.3048, tip_radius=0.0088, diameter=0.0157)
    with pytest.warns(UserWarning, match="mass: 0.460255 was computed by another body"):
        longer = dataclasses.replace(rod, length=0.6)
    assert longer == FlexibleRod(length=0.6, tip_radius=0.0088, diameter=0.0157)


def test_computed_fields_are_plain_numbers_to_the_user() -> None:
    rod = Rod.paper()
    assert rod.inertia == rod.mass * rod.length * rod.length / 12 and isinstance(rod.inertia, float)
    assert pickle.loads(pickle.dumps(rod)) == rod and f"{rod.inertia:.4g}" == "0.003567"
    assert il.rerun(il.simulate(rod, angle=0.3, velocity=(0.0, -1.0)).to_dict()).ok


def test_a_computed_value_copied_into_another_body_is_said_to_be_recomputed() -> None:
    """A value read off one body and passed to another is one that body computed: the new body
    computes its own, and says so (give a plain number to keep it)."""
    with pytest.warns(UserWarning, match=r"inertia: .* give inertia as a plain number"):
        rod = Rod(length=0.5, tip_radius=0.0088, mass=0.4607, inertia=Rod.paper().inertia)
    assert rod.inertia == pytest.approx(0.4607 * 0.25 / 12, rel=1e-15)
    kept = Rod(length=0.5, tip_radius=0.0088, mass=0.4607, inertia=float(Rod.paper().inertia))
    assert kept.inertia == Rod.paper().inertia
