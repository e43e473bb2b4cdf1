"""Inputs through the Python API: a sphere's implausible mass, an impact that comes to rest,
Brake's Meyer index from a material, and a drop's body checked first."""

from __future__ import annotations

import dataclasses
import re
import warnings
from pathlib import Path

import pytest

import impactlab as il
from impactlab.bodies._checks import DENSE_SPHERE_FACTOR
from impactlab.flags import ResultFlag

DOCS = Path(__file__).resolve().parents[2] / "docs" / "api" / "dynamics.md"
BALL = il.Sphere(radius="5 mm", material="aisi-52100")


def test_sphere_far_heavier_than_its_material_warns() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match=r"the mass is 245 times that of a solid"):
        s = il.Sphere(radius="5 mm", mass=1.0)
    assert s.mass == 1.0  # taken as given
    with pytest.warns(il.ImplausibleInputWarning) as rod:
        il.Rod(length=0.3, tip_radius=0.005, mass=5.0)
    # the Rod's words: "(warned above 10: a unit mistake?)"
    assert "(warned above 10: a unit mistake?)" in str(rod[0].message)
    with pytest.warns(il.ImplausibleInputWarning, match=r"\(warned above 100: a unit mistake\?\)"):
        il.Sphere(radius="5 mm", mass=1.0)


def test_a_sphere_standing_in_for_a_rod_along_its_axis_is_quiet() -> None:
    # the paper's rod (0.4607 kg) on its 8.8 mm tip: 21 times a solid steel sphere
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        il.Sphere(radius="8.8 mm", mass=0.4607, material=il.AISI_201)


def test_sphere_mass_up_to_the_factor_is_quiet() -> None:
    steel = il.AISI_201.density * 4.0 / 3.0 * 3.141592653589793 * 0.005**3
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        il.Sphere(radius="5 mm", mass=steel)  # a solid ball
        il.Sphere(radius="5 mm", mass=0.999 * DENSE_SPHERE_FACTOR * steel)
        il.Sphere(radius="5 mm", density=7800.0)
    with pytest.warns(il.ImplausibleInputWarning):
        il.Sphere(radius="5 mm", mass=1.001 * DENSE_SPHERE_FACTOR * steel)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        il.Sphere(radius="5 mm", mass=1.001 * steel / DENSE_SPHERE_FACTOR)  # a thin shell


@pytest.mark.parametrize("kw", [{"density": 7.8}, {"density": 7.8e6}, {"mass": 4e-6}])
def test_a_sphere_density_or_mass_a_thousand_times_off_warns(kw) -> None:
    """density=7.8 (g/cm^3 read as kg/m^3) gave e 0.794 for 0.436, plain success, silently."""
    with pytest.warns(il.ImplausibleInputWarning, match="solid sphere of the material"):
        il.Sphere(radius="5 mm", **kw)


def test_docs_say_a_slow_impact_that_comes_to_rest_is_refused() -> None:
    text = " ".join(DOCS.read_text(encoding="utf-8").split())
    assert "not refused" not in text
    assert "comes to rest on the flat" in text and "is refused" in text
    doc = " ".join((il.simulate.__doc__ or "").split())
    assert "never refused" not in doc and "is refused" in doc
    with pytest.raises(ValueError, match=r"ends at rest on the flat"):
        il.simulate(BALL, il.AISI_1010, velocity=(0.0, -1e-9))
    with pytest.raises(ValueError, match=r"ends at rest on the flat"):
        il.simulate(il.Rod.paper(), il.AISI_1010, angle="90 deg", velocity=(0.0, -1e-9))
    r = il.simulate(il.Rod.paper(), il.AISI_1010, angle="20 deg", velocity=(0.0, -1e-9))
    assert r.flags == ResultFlag.GRAVITY_DOMINATED


def _material(n: float) -> il.Material:
    base = il.get_material("E=200GPa, nu=0.3, Sy=300MPa, rho=7800kg/m^3, HB=120")
    return dataclasses.replace(base, name="soft steel", meyer_index=n)


def test_brake_refuses_a_material_meyer_index_of_3_naming_it() -> None:
    m3 = _material(3.0)
    ball = il.Sphere(radius="5 mm", material=il.AISI_201)
    message = (
        r"^meyer_index = 3\.0 of the flat 'soft steel' \(the material that yields first, "
        r"whose index Brake's law takes\) must lie in \(2, 3\) for Brake's Eq\. 24"
    )
    runs = [
        lambda: il.simulate(ball, m3, law="brake", velocity=(0.0, -1.0)),
        lambda: il.simulate(ball, m3, law="brake", velocity=(0.0, "-1 m/s")),  # the full path
        lambda: il.simulate_batch(ball, m3, law="brake", vy=[-1.0, -2.0]),
        lambda: il.simulate_drop(il.Rod.paper(), m3, law="brake", angle=0.3, velocity=(0, -1)),
        lambda: il.simulate_drops(il.Rod.paper(), m3, law="brake", angle=0.3, vy=-1.0),
    ]
    for run in runs:
        with pytest.raises(ValueError, match=message) as err:
            run()
        assert "\n" not in str(err.value)
        # the advice fits a material by values (the command line's n=) and Python alike
        assert str(err.value).endswith(
            "give the material an index below 3 (its n= key, e.g. 'n=2.2', or meyer_index), or "
            "another law (in Python also law_params={'meyer_index': ...})"
        )


def test_brake_names_the_body_material_when_it_yields_first() -> None:
    ball = il.Sphere(radius="5 mm", material=_material(3.0))
    with pytest.raises(ValueError, match=r"of the body's material 'soft steel'"):
        il.simulate(ball, il.AISI_1010, law="brake", velocity=(0.0, -1.0))


def test_brake_with_its_own_meyer_index_or_another_law_runs() -> None:
    m3 = _material(3.0)
    ball = il.Sphere(radius="5 mm", material=il.AISI_201)
    own = il.simulate(ball, m3, law="brake", law_params={"meyer_index": 2.2}, velocity=(0, -1))
    same = il.simulate(ball, _material(2.2), law="brake", velocity=(0.0, -1.0))
    assert own.e == same.e
    assert 0.0 < il.simulate(ball, m3, law="ghaednia", velocity=(0.0, -1.0)).e < 1.0
    with pytest.raises(ValueError, match=r"^meyer_index must lie in \(2, 3\)"):  # the law's
        il.simulate(ball, m3, law="brake", law_params={"meyer_index": 3.0}, velocity=(0, -1))


def test_drop_of_a_sphere_is_refused_for_its_body_first() -> None:
    message = re.escape("body must be an impactlab FlexibleRod or Rod, got Sphere")
    for run in (
        lambda: il.simulate_drop(BALL, il.AISI_1010, velocity=(0.0, -1.0)),
        lambda: il.simulate_drop(BALL),
        lambda: il.simulate_drops(BALL, vy=-1.0),
    ):
        with pytest.raises(ValueError, match=message):
            run()
    with pytest.raises(ValueError, match=r"^angle is required for the drop of a Rod"):
        il.simulate_drop(il.Rod.paper(), velocity=(0.0, -1.0))
