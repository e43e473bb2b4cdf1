"""A Material built without its density has none (None, "not given"), never a steel's 7850
kg/m^3 by default: whatever needs it (a Sphere's or a Rod's mass from it, a FlexibleRod, the FE
impact deck's flat) refuses the material naming it and ``density=``; what does not (a flat in
a rigid-body impact, a rod given its mass) works as before. The library's entries all have
their densities, and the text form still requires rho."""

from __future__ import annotations

import dataclasses
import warnings

import pytest

from impactlab import Material
from impactlab.bodies import FlexibleRod, Rod, Sphere
from impactlab.materials import get_material
from impactlab.materials.library import AISI_1010, PRESETS

AL = dict(name="al", E=69e9, nu=0.33, yield_strength=276e6)
NEEDS = r"material 'al' has no density, which .* needs: give it density= \(kg/m\^3; rho in the"


def test_a_material_without_density_has_none() -> None:
    m = Material(**AL)  # type: ignore[arg-type]
    assert m.density is None
    assert "density=None" in repr(m) and "density" not in str(m)
    with pytest.raises(ValueError, match=NEEDS):
        m.require_density("a test")
    assert Material(**AL, density="2.7 g/cm^3").require_density("a test") == pytest.approx(2700.0)


def test_the_library_entries_all_have_densities() -> None:
    for key, m in PRESETS.items():
        assert m.density is not None and m.density > 0.0, key


def test_the_text_form_still_requires_rho() -> None:
    with pytest.raises(ValueError, match=r"needs E, nu, Sy and rho; missing rho"):
        get_material("E=69GPa, nu=0.33, Sy=276MPa")


def test_a_library_entry_without_its_density_is_relabelled() -> None:
    m = dataclasses.replace(AISI_1010, density=None)
    assert m.density is None and "modified (density)" in m.name and m.source == ""


def test_a_sphere_of_it_needs_a_mass_or_a_density() -> None:
    m = Material(**AL)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=NEEDS.replace(".*", "a Sphere's mass from its radius")):
        Sphere(radius=0.005, material=m)
    with pytest.raises(ValueError, match=r"; or give the Sphere mass= or density=$"):
        Sphere(radius=0.005, material=m)
    assert Sphere(radius=0.005, material=m, mass=1.4e-3).mass == 1.4e-3
    assert Sphere(radius=0.005, material=m, density=2700.0).mass == pytest.approx(1.4137e-3, 1e-4)
    with_rho = Material(**AL, density=2700.0)  # type: ignore[arg-type]
    assert Sphere(radius=0.005, material=with_rho).mass == pytest.approx(1.4137e-3, rel=1e-4)


def test_a_rod_of_it_needs_its_mass_without_density() -> None:
    m = Material(**AL)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=NEEDS.replace(".*", "a rod's mass from its diameter")):
        Rod(length=0.2, tip_radius=0.005, diameter=0.01, material=m)
    with pytest.raises(ValueError, match=r"; or give its mass=$"):
        Rod(length=0.2, tip_radius=0.005, diameter=0.01, material=m)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no plausibility check without a density, no crash
        rod = Rod(length=0.2, tip_radius=0.005, mass=0.04, material=m)
        both = Rod(length=0.2, tip_radius=0.005, mass=0.04, diameter=0.01, material=m)
    assert rod.mass == both.mass == 0.04


def test_a_flexible_rod_of_it_is_refused() -> None:
    m = Material(**AL)  # type: ignore[arg-type]
    flexible = NEEDS.replace(".*", r"a FlexibleRod \(its mass, section and wave speeds\)")
    with pytest.raises(ValueError, match=flexible):
        FlexibleRod(length=0.3, tip_radius=0.005, mass=0.05, material=m)


def test_the_fe_impact_deck_needs_the_flats_density() -> None:
    from types import SimpleNamespace

    from impactlab.fe.impact_problem import make_impact_problem
    from impactlab.fe.impact_run import deck_spec
    from impactlab.materials import AISI_201

    for rho, expected in ((None, None), (2700.0, 2700.0)):
        flat = Material("al", 69e9, 0.33, 276e6, 95.0, density=rho)
        problem = make_impact_problem(flat, AISI_201, radius=8.8e-3, speed=1.0)
        mesh = SimpleNamespace(spec=problem.indentation.mesh_spec())
        if expected is None:
            deck = NEEDS.replace(".*", r"the FE impact deck's flat \(its inertia\)")
            with pytest.raises(ValueError, match=deck):
                deck_spec(problem, mesh)  # type: ignore[arg-type]
        else:
            assert deck_spec(problem, mesh).flat_density == expected  # type: ignore[arg-type]
