"""The angle rule in every message: a dimensionless pint Quantity is a number, radians, and an
echo of it says radians, never degrees; ``simulate_batch`` refuses an angle for a sphere with
``simulate``'s message (docs/glossary.md, "The angle rule")."""

from __future__ import annotations

import math

import numpy as np
import pint
import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD, Sphere
from impactlab.dynamics.input_checks import check_angle, velocity_from
from impactlab.units import has_unit, registry

Q_ = registry().Quantity
OTHER = pint.UnitRegistry()  # a user's registry


@pytest.mark.parametrize(
    "value", [Q_(95.0, ""), Q_(2.0, "dimensionless"), OTHER.Quantity(95.0, "")], ids=str
)
def test_a_dimensionless_angle_is_echoed_in_radians(value) -> None:
    with pytest.raises(ValueError, match="angle must be in radians") as err:
        check_angle(value, PAPER_ROD)
    text = str(err.value)
    assert "deg, got" not in text  # it was: "angle must be in (0, 90] deg, got 95 "
    assert f"got {float(value.magnitude)!r} rad" in text and "radians" in text


def test_a_dimensionless_angle_in_range_is_radians() -> None:
    assert check_angle(Q_(0.35, ""), PAPER_ROD) == 0.35
    assert check_angle(OTHER.Quantity(0.35, "dimensionless"), PAPER_ROD) == 0.35


def test_an_angle_with_a_unit_is_echoed_as_given() -> None:
    with pytest.raises(ValueError, match=r"\(0, 90\] deg, got 95 deg: the rod leans past"):
        check_angle(Q_(95, "deg"), PAPER_ROD)
    with pytest.raises(ValueError, match=r"got 2 rad: the rod leans past .* 65.4084 deg with"):
        check_angle(Q_(2.0, "rad"), PAPER_ROD)
    with pytest.raises(ValueError, match=r"got 100 deg: .* at angle = 80 deg with"):
        check_angle("100 deg", PAPER_ROD)
    with pytest.raises(ValueError, match=r"got 190 deg$"):
        check_angle("190 deg", PAPER_ROD)


def test_a_dimensionless_incidence_gets_the_radians_hint() -> None:
    with pytest.raises(ValueError, match="a bare incidence is radians") as err:
        velocity_from(None, 1.0, Q_(2.0, ""))
    assert f"{math.degrees(2.0):.6g} deg" in str(err.value)
    with pytest.raises(ValueError, match="incidence must lie in") as err:
        velocity_from(None, 1.0, Q_(100.0, "deg"))
    assert "bare incidence" not in str(err.value)


def test_has_unit() -> None:
    assert has_unit("20 deg") and has_unit(Q_(1.0, "rad")) and has_unit(OTHER.Quantity(1, "deg"))
    assert not has_unit(0.35) and not has_unit(Q_(0.35, "")) and not has_unit(None)


@pytest.mark.parametrize("angle", [0.3, [0.3, 0.4], "20 deg", np.array([0.2])], ids=str)
def test_batch_refuses_an_angle_for_a_sphere_as_simulate_does(angle) -> None:
    ball = Sphere(0.005)
    with pytest.raises(ValueError, match="a Sphere has no angle") as one:
        il.simulate(ball, angle=angle, velocity=(0.0, -1.0))
    with pytest.raises(ValueError, match="a Sphere has no angle") as many:
        il.simulate_batch(ball, angle=angle, vy=-1.0)
    assert str(many.value) == str(one.value)


def test_batch_of_spheres_without_an_angle_runs() -> None:
    b = il.simulate_batch(Sphere(0.005), law="hertz", vy=[-1.0, -2.0])
    assert b.ok.all()


def test_the_closed_forms_echo_an_angle_in_radians() -> None:
    from impactlab.analytic import critical_friction

    with pytest.raises(ValueError, match=r"angle must be <= 1.5708 rad, got 95.0 rad$"):
        critical_friction(Q_(95.0, ""))
    with pytest.raises(ValueError, match=r"got 1.658\d* rad$"):
        critical_friction(Q_(95.0, "deg"))
