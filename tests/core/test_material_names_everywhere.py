"""Every input that takes a material takes what ``get_material`` takes (docs/glossary.md,
Materials): a Material, a library name, a material by values or a TOML file; anything else is
refused naming the input."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.materials import AISI_201, AISI_1010, AL_6061_T6, ContactPair

VALUES = "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"


def test_simulate_and_batches_take_the_flat_by_name_or_values() -> None:
    kw = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}
    ref = il.simulate(il.Rod.paper(), AL_6061_T6, **kw)
    assert il.simulate(il.Rod.paper(), "al-6061-t6", **kw).e == ref.e
    assert il.simulate(il.Rod.paper(), VALUES, **kw).e == pytest.approx(ref.e, rel=1e-2)
    batch = il.simulate_batch(il.Rod.paper(), "al-6061-t6", angle=[kw["angle"]], vy=-1.41, mu=0.2)
    assert batch.e[0] == ref.e


def test_bodies_and_pairs_take_their_material_by_name(tmp_path) -> None:
    assert il.Rod(length=0.3, tip_radius=0.005, mass=0.4, material="aisi-201").material is AISI_201
    ball = il.Sphere(radius=0.005, material=VALUES)
    assert ball.material.density == 2700.0 and ball.mass == pytest.approx(
        2700 * 4 / 3 * math.pi * 0.005**3
    )
    f = tmp_path / "flat.toml"
    f.write_text('[material]\nE = "200 GPa"\nnu = 0.3\nSy = "305 MPa"\nrho = "7870 kg/m^3"\n')
    assert ContactPair("aisi-201", f).flat.yield_strength == AISI_1010.yield_strength
    flex = il.FlexibleRod.paper(material="aisi-201")
    assert flex.material is AISI_201


@pytest.mark.parametrize("bad", [3, None, ["aisi-1010"]])
def test_anything_else_is_refused_naming_the_input(bad) -> None:
    with pytest.raises(ValueError, match=r"^flat must be an impactlab Material, a library name"):
        il.simulate(il.Rod.paper(), bad, angle=0.35, velocity=(0.0, -1.41))
    with pytest.raises(ValueError, match=r"^material must be an impactlab Material"):
        il.Sphere(radius=0.005, material=bad)


def test_an_unknown_name_lists_the_library() -> None:
    with pytest.raises(
        ValueError,
        match=r"flat: unknown material 'aisi-101' \(did you mean 'aisi-1010'\?\); known: aisi-201",
    ):
        il.simulate(il.Rod.paper(), "aisi-101", angle=0.35, velocity=(0.0, -1.41))


def test_a_property_given_twice_is_refused() -> None:
    with pytest.raises(ValueError, match=r"E is given twice \('69GPa' and '70GPa'\)"):
        il.get_material("E=69GPa, E=70GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3")
