"""Bodies from what a researcher knows: a Rod from its diameter and the material's density (mass
checked against it), the length convention said everywhere, ``impactlab drop`` with any rod,
material and flat; and the study rules: no library material partly changed, the angle rule."""

from __future__ import annotations

import math
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod
from impactlab.cli import main
from impactlab.materials import AL_6061_T6, BRASS_C360
from impactlab.sweep import Study


@settings(deadline=None, max_examples=30)
@given(L=st.floats(0.05, 1.0), d=st.floats(0.002, 0.03))
def test_rigid_and_flexible_rods_agree_on_the_mass_from_the_diameter(L, d) -> None:
    rod = Rod(length=L, tip_radius=0.5 * d, diameter=d, material=BRASS_C360)
    assert rod.mass == pytest.approx(BRASS_C360.density * math.pi * d * d / 4 * L, rel=1e-14)
    if L / d >= 2:
        # the mode counts given: the mass does not depend on them, and choosing them by
        # frequency (default_mode_count) takes up to 2 s for a slender rod
        flex = FlexibleRod(
            length=L, tip_radius=0.5 * d, diameter=d, material=BRASS_C360, n_axial=8, n_bending=12
        )
        assert flex.mass == pytest.approx(rod.mass, rel=1e-14)
    again = Rod(length=L, tip_radius=0.5 * d, mass=rod.mass * 1.01, diameter=d, material=BRASS_C360)
    assert again.mass == rod.mass * 1.01  # within 2 %: the given mass is kept


def test_a_rod_wider_than_its_tip_is_refused() -> None:
    # d > 2R: the end face's rim stands out beside the tip and strikes first at shallow angles
    for body in (Rod, FlexibleRod):
        with pytest.raises(ValueError, match=r"exceeds twice the tip radius .* below 84.3 deg"):
            body(length=0.2, tip_radius=0.001, diameter=0.02)
    assert Rod(length=0.2, tip_radius=0.01, diameter=0.02).diameter == 0.02  # d = 2R: accepted


def test_a_flexible_rod_whose_mass_makes_it_wider_than_its_tip_is_refused() -> None:
    """The beam is a uniform rod of its material: without a diameter, the mass implies one
    (27.4 mm here, for a 4 mm tip), which is checked as a given one is."""
    with pytest.raises(ValueError, match=r"the diameter that the mass, length and density imply"):
        FlexibleRod(length=0.1, tip_radius=0.002, mass=0.46)
    assert FlexibleRod.paper().diameter is None  # 15.7 mm implied, under 2R = 17.6 mm


def test_mass_and_diameter_checked_against_the_density() -> None:
    with pytest.raises(ValueError, match=r"imply a density of .* within 2%"):
        Rod(length=0.3, tip_radius=0.005, mass=1.0, diameter=0.01)
    with pytest.raises(ValueError, match=r"give the mass .* or the diameter"):
        Rod(length=0.3, tip_radius=0.005)
    with pytest.raises(ValueError, match="diameter"):
        Rod(length=0.3, tip_radius=0.005, diameter="-1 mm")


def test_the_length_convention_is_said() -> None:
    assert PAPER_ROD.overall_length == pytest.approx(0.3048 + 2 * 0.0088)
    assert "overall_length = 322.4 mm" in str(PAPER_ROD)
    assert "overall_length = 322.4 mm" in str(FlexibleRod.paper())
    assert "L + 2R" in (Rod.__doc__ or "") and "L + 2R" in (FlexibleRod.__doc__ or "")


def _cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out = capsys.readouterr()
    return code, out.out, out.err


def test_length_convention_in_the_help(monkeypatch, capsys) -> None:
    for cmd in ("simulate", "drop"):
        code, out, _ = _cli(monkeypatch, capsys, cmd, "--help")
        assert code == 0 and "L + 2R" in " ".join(out.split()), cmd


def test_drop_needs_a_mass_or_diameter_for_another_rod(monkeypatch, capsys) -> None:
    args = ("drop", "--angle", "30 deg", "--vy", "-1 m/s", "--rigid", "--length", "200 mm")
    code, _, err = _cli(monkeypatch, capsys, *args)
    assert code == 2 and "--mass or --diameter" in err
    code, _, err = _cli(monkeypatch, capsys, *args, "--mass", "1 kg", "--diameter", "10 mm")
    assert code == 2 and "imply a density" in err
    code, _, err = _cli(monkeypatch, capsys, *args, "--mass", "1 kg", "--modes-axial", "2")
    assert code == 2 and "--modes-axial: a rigid rod has no modes" in err


def test_study_material_rules() -> None:
    base = {"fixed": {"vy": -1.0, "mu": 0.1}, "grid": {"angle": ["20 deg", "40 deg"]}}
    with pytest.raises(ValueError, match="flat_E without flat_nu, flat_yield_strength"):
        Study.from_dict({**base, "fixed": {**base["fixed"], "flat_E": "69 GPa"}})
    named = {"flat_material": "aisi-1010", "flat_E": 69e9, "flat_nu": 0.33}
    with pytest.raises(ValueError, match="flat_material = 'aisi-1010' together with flat_E"):
        Study.from_dict({**base, "fixed": {**base["fixed"], **named, "flat_yield_strength": 276e6}})
    al = {"flat_E": "68.9 GPa", "flat_nu": 0.33, "flat_yield_strength": "276 MPa"}
    s = Study.from_dict({**base, "fixed": {**base["fixed"], **al}})
    assert s.fixed["flat_material"] == "custom"
    num, cat, _ = s.chunk_cases(0)
    assert cat["flat_material"] == "custom" and math.isnan(num["flat_brinell_hardness"][0])
    from impactlab.sweep.models import material_for

    flat = material_for("flat", "custom", {k: v[0] for k, v in num.items()})
    assert (flat.E, flat.nu, flat.yield_strength) == (
        AL_6061_T6.E,
        AL_6061_T6.nu,
        AL_6061_T6.yield_strength,
    )
    assert not flat.has_hardness  # never the 1010's 105
    lib = Study.from_dict({**base, "fixed": {**base["fixed"], "flat_material": "6061-T6"}})
    assert lib.value_of("flat_material") == "6061-T6"


def test_study_angle_rule() -> None:
    with pytest.raises(ValueError, match=r"angle: the bare number 20 has no unit"):
        Study.from_dict({"fixed": {"vy": -1, "mu": 0.1}, "grid": {"angle": [20, 30]}})
    deg = Study.from_dict(
        {"fixed": {"vy": -1, "mu": 0.1}, "grid": {"angle": {"values": [20, 30], "unit": "deg"}}}
    )
    assert deg.axes[0].values == pytest.approx((math.radians(20), math.radians(30)))
    py = Study(name="p", fixed={"vy": -1.0, "mu": 0.1}, grid={"angle": [0.35]})  # Python: rad
    assert py.axes[0].values == (0.35,)
    sphere = Study.from_dict(
        {"fixed": {"body": "sphere", "radius": "3 mm", "vy": -1}, "grid": {"mu": [0.1, 0.2]}}
    )
    num, _, _ = sphere.chunk_cases(0)  # a sphere-only study needs no angle
    assert (num["angle"] == 0.5 * math.pi).all()
    with pytest.raises(ValueError, match="angle: a sphere has no angle"):  # and takes none
        Study.from_dict(
            {"fixed": {"body": "sphere", "radius": "3 mm", "vy": -1, "angle": "20 deg"},
             "grid": {"mu": [0.1, 0.2]}}
        )  # fmt: skip


def test_python_refuses_an_angle_for_a_sphere() -> None:
    from impactlab import simulate
    from impactlab.bodies import Sphere

    with pytest.raises(ValueError, match=r"angle \(0.3\): a Sphere has no angle to the flat"):
        simulate(Sphere(0.003), angle=0.3, velocity=(0.0, -1.0))


def test_drop_any_rod_material_and_flat(monkeypatch, capsys) -> None:
    """A brass rod on an aluminium flat from the command line equals the library's drop."""
    import json

    from impactlab.dynamics.drop import simulate_drop

    code, out, err = _cli(
        monkeypatch, capsys, "drop", "--rigid", "--angle", "30 deg", "--speed", "2 m/s",
        "--incidence", "10 deg", "--length", "200 mm", "--radius", "5 mm", "--diameter", "10 mm",
        "--material", "brass-c360", "--flat", "al-6061-t6", "--json",
    )  # fmt: skip
    assert code == 0, err
    rod = Rod(length=0.2, tip_radius=0.005, diameter=0.01, material=BRASS_C360)
    th = math.radians(10)
    ref = simulate_drop(
        rod, AL_6061_T6, angle=math.radians(30), velocity=(2 * math.sin(th), -2 * math.cos(th))
    )
    data = json.loads(out)
    assert data["e"]["value"] == pytest.approx(ref.e, rel=1e-12)
    assert data["dent_depth"]["value"] == pytest.approx(ref.dent_depth, rel=1e-12)
    code, out, _ = _cli(
        monkeypatch, capsys, "drop", "--rigid", "--angle", "30 deg", "--vy", "-2 m/s",
        "--length", "200 mm", "--radius", "5 mm", "--diameter", "10 mm",
    )  # fmt: skip
    flowing = " ".join(out.split())  # the legend wraps at the terminal's width
    assert code == 0 and "reload: True if the contact began on an existing dent" in flowing


def test_simulate_rod_from_its_diameter(monkeypatch, capsys) -> None:
    import json

    from impactlab import simulate

    code, out, err = _cli(
        monkeypatch, capsys, "simulate", "rod", "--angle", "30 deg", "--vy", "-2 m/s",
        "--length", "200 mm", "--radius", "5 mm", "--diameter", "10 mm",
        "--material", "brass-c360", "--flat", "al-6061-t6", "--json",
    )  # fmt: skip
    assert code == 0, err
    rod = Rod(length=0.2, tip_radius=0.005, diameter=0.01, material=BRASS_C360)
    ref = simulate(rod, AL_6061_T6, angle=math.radians(30), velocity=(0.0, -2.0))
    assert json.loads(out)["e"]["value"] == ref.e
    code, _, err = _cli(
        monkeypatch, capsys, "simulate", "sphere", "--vy", "-1 m/s", "--diameter", "1 mm"
    )
    assert code == 2 and "--diameter is a rod's; a sphere's size is its radius, --radius" in err


def test_a_rod_whose_inertia_does_not_fit_its_mass_warns() -> None:
    """An inertia 20 times below a uniform rod's m L^2/12 warns as analyze and invert do (1e-30
    kg m^2 gave a plain-success elastic bounce); a plausible one does not."""
    import warnings

    from impactlab import ImplausibleInputWarning

    with pytest.warns(ImplausibleInputWarning, match=r"^rod: the mass and the inertia do not fit"):
        Rod(length=0.3048, tip_radius=0.0088, mass=0.4607, inertia=1e-30)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        Rod(length=0.3048, tip_radius=0.0088, mass=0.4607, inertia=0.4607 * 0.3048**2 / 100)
