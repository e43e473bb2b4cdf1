"""The mass convention of a rod of uniform section: a weighed mass is the cylinder between the
end-sphere centres plus up to two hemispherical ends of radius R, so a rod with hemispherical
ends of its own radius is accepted from its true mass, alone or with its diameter, while a rod
really wider than its tip is still refused; the paper's rod keeps its diameter."""

from __future__ import annotations

import math
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.bodies import FlexibleRod, Rod
from impactlab.bodies._checks import DENSITY_TOLERANCE, MASS_CONVENTION
from impactlab.cli import main
from impactlab.materials import AISI_201, BRASS_C360

RHO = BRASS_C360.density
L, R = 0.2, 0.005  # 200 mm between the end-sphere centres (210 mm tip to tip), 5 mm ends
#: A 10 mm brass rod with 5 mm hemispherical ends: cylinder plus a sphere of its diameter.
CAPSULE = RHO * (math.pi * R * R * L + 4.0 / 3.0 * math.pi * R**3)


def test_a_rod_with_hemispherical_ends_is_read_from_its_true_mass() -> None:
    assert CAPSULE == pytest.approx(0.1379, abs=5e-5)
    rod = FlexibleRod(length=L, tip_radius=R, mass=CAPSULE, material=BRASS_C360)
    assert rod.mass == CAPSULE and rod.diameter is None
    sec = rod.section
    assert sec.d == 2 * R  # not sqrt(4 m / (pi rho L)) = 10.16 mm
    # the beam carries the whole mass along L: the ends' mass raises its density by 2d / 3L
    assert sec.rho_eff == pytest.approx(RHO * (1 + 2 * 2 * R / (3 * L)), rel=1e-12)
    both = FlexibleRod(length=L, tip_radius=R, mass=CAPSULE, diameter=2 * R, material=BRASS_C360)
    assert both.section == sec
    rigid = Rod(length=L, tip_radius=R, mass=CAPSULE, diameter=2 * R, material=BRASS_C360)
    assert rigid.mass == CAPSULE


def test_the_diameter_from_the_mass_is_continuous_up_to_twice_the_tip_radius() -> None:
    cylinder = RHO * math.pi * R * R * L  # the mass that fills 2R over L, ends weightless
    below = FlexibleRod(length=L, tip_radius=R, mass=cylinder * (1 - 1e-6), material=BRASS_C360)
    assert below.section.d == pytest.approx(2 * R, rel=1e-6) and below.section.d < 2 * R
    above = FlexibleRod(length=L, tip_radius=R, mass=cylinder * (1 + 1e-6), material=BRASS_C360)
    assert above.section.d == 2 * R


def test_a_rod_really_wider_than_its_tip_is_still_refused() -> None:
    most = (1 + DENSITY_TOLERANCE) * CAPSULE
    FlexibleRod(length=L, tip_radius=R, mass=most * (1 - 1e-9), material=BRASS_C360)
    with pytest.raises(ValueError, match="exceeds twice the tip radius") as refused:
        FlexibleRod(length=L, tip_radius=R, mass=most * 1.001, material=BRASS_C360)
    text = str(refused.value)
    assert "with both hemispherical ends counted" in text and MASS_CONVENTION in text
    assert "weighs 0.1379 kg, and the mass (" in text and "by 2% at most" in text
    for body in (Rod, FlexibleRod):  # a given diameter is checked as it is
        with pytest.raises(ValueError, match=r"exceeds twice the tip radius .* below 11.4 deg"):
            body(length=L, tip_radius=R, diameter=0.0102, material=BRASS_C360)


def test_mass_and_diameter_are_checked_against_the_range_of_end_masses() -> None:
    for body in (Rod, FlexibleRod):
        with pytest.raises(ValueError, match=r"imply a density of 9549 kg/m\^3 .* to 9241") as e:
            body(length=L, tip_radius=R, mass=0.15, diameter=2 * R, material=BRASS_C360)
        assert MASS_CONVENTION in str(e.value) and "within 2% of that range" in str(e.value)
        light = 0.97 * RHO * math.pi * R * R * L  # 3 % below even weightless ends
        with pytest.raises(ValueError, match="imply a density"):
            body(length=L, tip_radius=R, mass=light, diameter=2 * R, material=BRASS_C360)


@settings(deadline=None, max_examples=40)
@given(
    length=st.floats(0.05, 1.0),
    ratio=st.floats(0.2, 1.0),  # d / 2R
    tip=st.floats(0.002, 0.012),
    scale=st.floats(0.9, 1.2),
)
def test_rigid_and_flexible_rods_accept_the_same_masses(length, ratio, tip, scale) -> None:
    d = 2 * tip * ratio
    if length / d < 2 or tip > length / 2:
        return
    rho = AISI_201.density
    cylinder = rho * math.pi * d * d / 4 * length
    m = cylinder * scale
    ok = m >= (1 - DENSITY_TOLERANCE) * cylinder and m <= (1 + DENSITY_TOLERANCE) * (
        cylinder + rho * 4 / 3 * math.pi * tip**3
    )
    verdicts = []
    for make in (Rod, lambda **kw: FlexibleRod(**kw, n_axial=0, n_bending=0)):
        try:
            make(length=length, tip_radius=tip, mass=m, diameter=d)
            verdicts.append(True)
        except ValueError:
            verdicts.append(False)
    assert verdicts == [ok, ok]


def test_the_papers_rod_keeps_its_diameter() -> None:
    rod = FlexibleRod.paper()
    assert rod.diameter is None
    assert rod.section.d == math.sqrt(4.0 * 0.4607 / (7800.0 * 0.3048) / math.pi)
    assert rod.section.rho_eff == pytest.approx(7800.0, rel=1e-14)


def test_drop_takes_the_weighed_mass_of_a_rod_with_hemispherical_ends(monkeypatch, capsys):
    args = ["impactlab", "drop", "--angle", "30 deg", "--vy", "-2 m/s", "--mu", "0.15"]
    args += ["--length", "200 mm", "--radius", "5 mm", "--mass", "0.1379 kg"]
    for extra in ([], ["--diameter", "10 mm"]):
        monkeypatch.setattr(sys, "argv", [*args, *extra, "--material", "brass-c360"])
        try:
            main()
            code = 0
        except SystemExit as exc:
            code = int(exc.code or 0)
        out = capsys.readouterr()
        assert code == 0 and "max_force" in out.out, out.err
