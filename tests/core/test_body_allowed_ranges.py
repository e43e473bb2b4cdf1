"""Bodies of absurd but finite sizes and masses are refused with the parameter, its value and
the allowed range (``bodies._checks``: SIZE_RANGE, MASS_RANGE, INERTIA_RANGE), given or derived,
never a ZeroDivisionError or OverflowError deep inside; the bodies at the ends of the ranges
build, and so does a law for their radius (``contact._common.RADIUS_RANGE``)."""

from __future__ import annotations

import re
import sys
import warnings

import pytest

from impactlab.bodies import FlexibleRod, Rod, Sphere
from impactlab.bodies._checks import (
    INERTIA_RANGE,
    MASS_RANGE,
    PLAUSIBLE_LENGTH,
    PLAUSIBLE_MASS,
    PLAUSIBLE_RADIUS,
    SIZE_RANGE,
)
from impactlab.cli import main
from impactlab.contact import get_law
from impactlab.contact._common import RADIUS_RANGE
from impactlab.materials import AISI_201, AISI_1010, ContactPair


@pytest.fixture(autouse=True)
def _quiet() -> None:
    warnings.simplefilter("ignore")  # the plausibility warnings of the extreme bodies


REFUSED = [
    (lambda: Rod(0.3048, 1e-200, 0.46), r"^tip_radius = 1e-200 m lies outside the allowed range"),
    (lambda: Rod(0.3, 0.009, 0.46, diameter=1e-310), r"^diameter = 1e-310 m lies outside"),
    (lambda: Rod(0.3048, 0.0088, diameter=1e-200), r"^diameter = 1e-200 m lies outside"),
    (lambda: Rod(1e300, 0.0088, 0.46), r"^length = 1e\+300 m lies outside .*far above"),
    (lambda: Rod(0.3, 0.0088, 1e300), r"^mass = 1e\+300 kg lies outside the allowed range"),
    (lambda: Rod(0.3, 0.0088, 0.46, inertia=1e-300), r"^inertia = 1e-300 kg m\^2 lies outside"),
    (lambda: FlexibleRod(0.3048, 0.0088, mass=1e-200), r"^mass = 1e-200 kg lies outside"),
    (lambda: FlexibleRod(0.3048, 0.0088, diameter=1e-310), r"^diameter = 1e-310 m lies"),
    (lambda: FlexibleRod(0.3048, 0.0088, mass=1e-23), r"^diameter = .* m \(sqrt\(4 m / \(pi"),
    (lambda: Sphere(1e-200), r"^radius = 1e-200 m lies outside the allowed range \[1e-09, 10000\]"),
    (lambda: Sphere(1e-310), r"^radius = 1e-310 m lies outside .*far below"),
    (lambda: Sphere(1e200), r"^radius = 1e\+200 m lies outside"),
    (lambda: Sphere(0.01, mass=1e-300), r"^mass = 1e-300 kg lies outside"),
    (lambda: Sphere(5e-9, density=1e-3), r"^mass = .* kg \(4/3 pi R\^3 rho, from the radius\)"),
]


@pytest.mark.parametrize(("build", "message"), REFUSED)
def test_an_absurd_size_or_mass_is_refused_by_name(build, message) -> None:
    with pytest.raises(ValueError, match=message):
        build()


def test_the_bodies_at_the_ends_of_the_ranges_build() -> None:
    lo, hi = SIZE_RANGE
    assert Sphere(lo).mass > MASS_RANGE[0]  # a 1 nm steel sphere: 3e-23 kg
    assert Sphere(lo, mass=MASS_RANGE[0]).radius == lo
    assert Rod(2 * lo, lo, MASS_RANGE[0]).inertia >= INERTIA_RANGE[0]
    assert Rod(hi, hi / 2, MASS_RANGE[1]).length == hi
    assert FlexibleRod(0.3048, 0.0088, diameter=lo).diameter == lo


def test_the_warned_ranges_lie_well_inside_the_refused_ones() -> None:
    """A plausible value, and one a thousand times off (a unit mistake), warns: never refused."""
    for (lo, hi), (a, b) in (
        (SIZE_RANGE, PLAUSIBLE_LENGTH),
        (SIZE_RANGE, PLAUSIBLE_RADIUS),
        (MASS_RANGE, PLAUSIBLE_MASS),
    ):
        assert lo <= a / 1e3 * (1 + 1e-12) and b * 1e3 <= hi
    tiny = Sphere(PLAUSIBLE_RADIUS[0] / 1e3)  # 1 um / 1000: round-off below 1 nm, accepted
    assert tiny.radius < SIZE_RANGE[0]
    get_law("ghaednia").build(ContactPair(AISI_201, AISI_1010), tiny.radius)
    assert RADIUS_RANGE == SIZE_RANGE  # a law's radius: the sizes of the bodies


@pytest.mark.parametrize("law", ["ghaednia", "hertz", "jackson-green", "kogut-komvopoulos",
                                 "brake", "thornton"])  # fmt: skip
@pytest.mark.parametrize("radius", [1e-200, 1e200])
def test_a_law_refuses_a_radius_outside_the_range(law, radius) -> None:
    with pytest.raises(ValueError, match="^" + re.escape(f"radius = {radius!r} m lies outside")):
        get_law(law).build(ContactPair(AISI_201, AISI_1010), radius)


def test_a_mode_count_given_as_a_float_says_so() -> None:
    with pytest.raises(ValueError, match=r"n_axial must be an integer \(a mode count\), not a "
                                         r"float: got 0\.0; write 0"):  # fmt: skip
        FlexibleRod.paper(n_axial=0.0)


def test_the_command_line_refuses_a_tiny_sphere_without_a_traceback(monkeypatch, capsys) -> None:
    monkeypatch.setattr(sys, "argv", ["impactlab", "simulate", "sphere", "--vy", "-2 m/s",
                                      "--radius", "1e-310"])  # fmt: skip
    with pytest.raises(SystemExit) as stop:
        main()
    err = capsys.readouterr().err
    assert stop.value.code == 2 and "Traceback" not in err
    assert "radius = 1e-310 m lies outside the allowed range [1e-09, 10000] m" in err
